// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/registration/global_alignment.h>
#include <morphreg/registration/initial_alignment_strategy.h>

namespace morphreg
{
/** \brief The start "global": alignHeadGlobally, any rotation, for scans with shoulders and clutter or seen from
 *  one view (see global_alignment.h). */
class GlobalStart : public InitialAlignmentStrategy
{
public:
  std::string
  name () const override
  {
    return "global";
  }

  StartEstimate
  estimate (const StartInputs& inputs) const override
  {
    GlobalAlignmentSettings settings;
    settings.viewpoint = inputs.viewpoint;
    const GlobalAlignment aligned =
        alignHeadGlobally (inputs.model_mean, inputs.target, inputs.target_normals, settings);
    StartEstimate found;
    found.similarity = aligned.similarity;
    found.method = name ();
    found.detail = aligned.method;
    found.confidence = aligned.confidence;
    found.head_points = static_cast<int> (aligned.head_indices.size ());
    return found;
  }
};
} // namespace morphreg

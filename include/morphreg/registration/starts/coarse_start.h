// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/registration/initial_alignment_strategy.h>

namespace morphreg
{
/** \brief The start "coarse": robustCoarseSimilarity, 11 pose hypotheses about the principal axes, for heads in a
 *  roughly known pose. */
class CoarseStart : public InitialAlignmentStrategy
{
public:
  std::string
  name () const override
  {
    return "coarse";
  }

  StartEstimate
  estimate (const StartInputs& inputs) const override
  {
    StartEstimate found;
    found.similarity = robustCoarseSimilarity (inputs.model_mean.vertices, inputs.target, inputs.target_neighbours);
    found.method = name ();
    return found;
  }
};
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/common/error.h>
#include <morphreg/registration/initial_alignment_strategy.h>

namespace morphreg
{
/** \brief The start "landmarks": the least-squares similarity (Umeyama) of the mean head's landmarks onto the
 *  target's; needs at least 3. */
class LandmarkStart : public InitialAlignmentStrategy
{
public:
  std::string
  name () const override
  {
    return "landmarks";
  }

  StartEstimate
  estimate (const StartInputs& inputs) const override
  {
    if (inputs.target_landmarks.cols () < 3)
      throw InvalidInputError ("MorphableICP: the landmark initialisation needs >= 3 target landmarks, got " +
                               std::to_string (inputs.target_landmarks.cols ()));
    StartEstimate found;
    found.similarity = similarityFromLandmarks (inputs.model_landmarks, inputs.target_landmarks);
    found.method = name ();
    return found;
  }
};
} // namespace morphreg

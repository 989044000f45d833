// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/registration/starts/global_start.h>
#include <morphreg/registration/starts/guess_start.h>
#include <morphreg/registration/starts/landmark_start.h>

namespace morphreg
{
/** \brief The start "auto", MorphableICP's default: the guess passed to align() unless it is the identity; else the
 *  landmarks if the target has at least 3; else the global start. The estimate names the start it chose. */
class AutomaticStart : public InitialAlignmentStrategy
{
public:
  std::string
  name () const override
  {
    return "auto";
  }

  StartEstimate
  estimate (const StartInputs& inputs) const override
  {
    if (!inputs.guess.isIdentity ())
      return GuessStart ().estimate (inputs);
    if (inputs.target_landmarks.cols () >= 3)
      return LandmarkStart ().estimate (inputs);
    return GlobalStart ().estimate (inputs);
  }
};
} // namespace morphreg

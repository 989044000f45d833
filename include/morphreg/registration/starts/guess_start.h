// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/registration/initial_alignment_strategy.h>

namespace morphreg
{
/** \brief The start "guess": the similarity passed to align(), even the identity (the caller has placed the model). */
class GuessStart : public InitialAlignmentStrategy
{
public:
  std::string
  name () const override
  {
    return "guess";
  }

  StartEstimate
  estimate (const StartInputs& inputs) const override
  {
    StartEstimate found;
    found.similarity = inputs.guess;
    found.method = name ();
    return found;
  }
};
} // namespace morphreg

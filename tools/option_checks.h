// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Validators of numeric options whose messages state the rule, not a limit: CLI11's NonNegativeNumber and
// PositiveNumber print the largest double, a 309-digit number.
#include <CLI/CLI.hpp>

#include <cmath>
#include <string>

namespace morphreg
{
namespace tools
{
/** A validator accepting the numbers for which \a accept holds; others get "Value X is not <rule>". */
template <typename Accept>
CLI::Validator
numberCheck (Accept accept, const std::string& rule, const std::string& name)
{
  return CLI::Validator (
      [accept, rule] (std::string& text) {
        double value = 0.0;
        if (!CLI::detail::lexical_cast (text, value) || !accept (value))
          return "Value " + text + " is not " + rule;
        return std::string ();
      },
      name);
}

/** A finite number >= 0. */
inline CLI::Validator
nonNegative ()
{
  return numberCheck ([] (double v) { return std::isfinite (v) && v >= 0.0; }, "a number >= 0", "NONNEGATIVE");
}

/** A finite number > 0. */
inline CLI::Validator
positive ()
{
  return numberCheck ([] (double v) { return std::isfinite (v) && v > 0.0; }, "a number > 0", "POSITIVE");
}

/** A number >= 0, infinity included. */
inline CLI::Validator
nonNegativeOrInfinite ()
{
  return numberCheck ([] (double v) { return v >= 0.0; }, "a number >= 0 (or inf)", "NONNEGATIVE or inf");
}
} // namespace tools
} // namespace morphreg

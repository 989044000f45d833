// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Validators of numeric options whose messages state the rule, not a limit: CLI11's NonNegativeNumber and
// PositiveNumber print the largest double, a 309-digit number.
#include <CLI/CLI.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <type_traits>

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

/** A number > 0, infinity included. */
inline CLI::Validator
positiveOrInfinite ()
{
  return numberCheck ([] (double v) { return v > 0.0; }, "a number > 0 (or inf)", "POSITIVE or inf");
}

/** \a value as the shortest text that reads back as it (1e-06, 0.5, 10000). */
inline std::string
boundText (double value)
{
  std::ostringstream text;
  text << value;
  return text.str ();
}

/** A finite number from \a low to \a high; others get "Value X is not a number from LOW to HIGH", X as written. */
inline CLI::Validator
numberIn (double low, double high)
{
  const std::string range = boundText (low) + " to " + boundText (high);
  return numberCheck ([low, high] (double v) { return std::isfinite (v) && v >= low && v <= high; },
                      "a number from " + range, "NUMBER in " + range);
}

/** A whole number from \a low to \a high. A whole number written as a decimal or with an exponent (1e3) is accepted
 *  as that number; others are refused saying why ("12.9 is not a whole number", "20000 is not from 1 to 10000"). */
inline CLI::Validator
wholeNumberIn (long long low, long long high)
{
  const std::string range = std::to_string (low) + " to " + std::to_string (high);
  return CLI::Validator (
      [low, high, range] (std::string& text) {
        double value = 0.0;
        if (!CLI::detail::lexical_cast (text, value) || !std::isfinite (value))
          return "Value " + text + " is not a number (a whole number from " + range + ")";
        if (value != std::floor (value))
          return "Value " + text + " is not a whole number (a whole number from " + range + ")";
        if (value < static_cast<double> (low) || value > static_cast<double> (high))
          return "Value " + text + " is not from " + range;
        text = std::to_string (static_cast<long long> (value));
        return std::string ();
      },
      "INTEGER in " + range);
}

/** numberIn() or, for whole-number bounds, wholeNumberIn(): the range of an option by the type of its bounds. */
template <typename Low, typename High>
CLI::Validator
inRange (Low low, High high)
{
  if constexpr (std::is_integral_v<Low> && std::is_integral_v<High>)
    return wholeNumberIn (low, high);
  else
    return numberIn (static_cast<double> (low), static_cast<double> (high));
}

/** A number >= 0, infinity included. */
inline CLI::Validator
nonNegativeOrInfinite ()
{
  return numberCheck ([] (double v) { return v >= 0.0; }, "a number >= 0 (or inf)", "NONNEGATIVE or inf");
}
} // namespace tools
} // namespace morphreg

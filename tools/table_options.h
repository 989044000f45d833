// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The options of a settings table (morphreg/common/setting_options.h) on the command line: each entry an option
// named after its field (--max-distance), with the table's help text and its range or choices as the check.
#include "option_checks.h"

#include <morphreg/common/setting_options.h>

#include <CLI/CLI.hpp>

#include <cmath>
#include <variant>

namespace morphreg
{
namespace tools
{
/** The check of a numeric table entry: whole numbers for counts, a range "from L to H", or a rule ("a number >= L",
 *  "a number > 0 (or inf)") for the entries without an upper bound or above zero (setting_options.h). */
template <typename Settings>
CLI::Validator
rangeCheck (const SettingOption<Settings>& option, bool whole)
{
  const double low = option.lowest, high = option.highest;
  if (whole)
    return inRange (static_cast<long long> (low), static_cast<long long> (high));
  if (high < kUnboundedSetting && low != kAboveZeroSetting)
    return inRange (low, high);
  const std::string range = (low == kAboveZeroSetting ? "> 0" : ">= " + boundText (low)) +
                            (high == kInfiniteSetting   ? " (or inf)"
                             : high < kUnboundedSetting ? " and <= " + boundText (high)
                                                        : std::string ());
  return numberCheck ([low, high] (double v) { return isSettingInRange (v, low, high); }, "a number " + range,
                      "NUMBER " + range);
}

/** Adds the option of one table entry to a command, bound to its field of the settings. */
template <typename Settings>
struct TableOption
{
  CLI::App* command;
  Settings& settings;
  const SettingOption<Settings>& option;

  void
  operator() (int Settings::*field) const
  {
    add (settings.*field)->check (rangeCheck (option, true))->capture_default_str ();
  }
  void
  operator() (double Settings::*field) const
  {
    add (settings.*field)->check (rangeCheck (option, false))->capture_default_str ();
  }
  void
  operator() (std::optional<double> Settings::*field) const
  {
    add (settings.*field)->check (rangeCheck (option, false));
  }
  void
  operator() (std::vector<int> Settings::*field) const
  {
    add (settings.*field)->check (rangeCheck (option, true));
  }
  void
  operator() (std::string Settings::*field) const
  {
    add (settings.*field)->check (CLI::IsMember (option.choices))->capture_default_str ();
  }
  /** A switch: --name turns it on, and the table's off name, when it has one, turns it off (--point-to-point). */
  void
  operator() (bool Settings::*field) const
  {
    std::string names = commandLineName (option.name);
    if (!option.choices.empty ())
      names += ",!" + commandLineName (option.choices.front ());
    command->add_flag (names, settings.*field, option.help);
  }

  template <typename T>
  CLI::Option*
  add (T& value) const
  {
    return command->add_option (commandLineName (option.name), value, option.help);
  }
};

/** Adds \a option of a settings table to \a command, bound to its field of \a settings. */
template <typename Settings>
void
addTableOption (CLI::App* command, Settings& settings, const SettingOption<Settings>& option)
{
  std::visit (TableOption<Settings>{command, settings, option}, option.field);
}
} // namespace tools
} // namespace morphreg

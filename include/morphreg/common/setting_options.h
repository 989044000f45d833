// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file setting_options.h
 *  \brief Tables of the settings a user can set, for any settings struct: each entry names a field, explains it and
 *  bounds it once, and the command line (`--max-distance`), the Python keywords (`max_distance=`) and the library's
 *  checks all read the same table (registration_options.h, resampling_options.h).
 */
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace morphreg
{
/** \brief SettingOption::highest of a setting without an upper bound: any finite number at least the lowest. */
constexpr double kUnboundedSetting = std::numeric_limits<double>::max ();

/** \brief SettingOption::highest of a setting without an upper bound that also takes infinity (no limit at all). */
constexpr double kInfiniteSetting = std::numeric_limits<double>::infinity ();

/** \brief SettingOption::lowest of a setting that must be above 0 (a weight, a noise level), 0 itself refused. */
constexpr double kAboveZeroSetting = std::numeric_limits<double>::denorm_min ();

/** \brief One field of \a Settings as users set it. */
template <typename Settings>
struct SettingOption
{
  /** The field it sets, by its type: whole numbers, numbers, switches, names, an optional number (unset: off) and
   *  a list of counts. */
  using Field = std::variant<int Settings::*, double Settings::*, bool Settings::*, std::string Settings::*,
                             std::optional<double> Settings::*, std::vector<int> Settings::*>;

  std::string name;     ///< the field's name, the Python keyword; the option is "--" + name with '-' for '_'
  std::string help;     ///< one sentence for --help and the Python docstring
  Field field;          ///< the field of the settings struct it sets
  double lowest = 0.0;  ///< numbers: the smallest value allowed (each count of a list; kAboveZeroSetting: > 0)
  double highest = 0.0; ///< numbers: the largest value allowed (kUnboundedSetting: no bound; kInfiniteSetting: inf too)
  std::vector<std::string> choices; ///< names: the values allowed; switches: the name that turns it off, if any
};

/** \brief A setting's command-line option.
 *  \param[in] name the setting's name (max_distance)
 *  \return "--" + \a name with '-' for '_' (--max-distance) */
std::string
commandLineName (const std::string& name);

/** \brief Throws InvalidInputError "<kind> <name> = <value> is out of range (<range>)" unless \a value is within
 *  [\a lowest, \a highest] and finite (or infinite with \a highest kInfiniteSetting).
 *  \param[in] kind what the message calls a setting ("registration setting")
 *  \param[in] name the setting's name
 *  \param[in] value its value
 *  \param[in] lowest the smallest value allowed (kAboveZeroSetting: any above 0)
 *  \param[in] highest the largest value allowed (kUnboundedSetting: no bound; kInfiniteSetting: inf too) */
void
requireSettingInRange (const std::string& kind, const std::string& name, double value, double lowest, double highest);

/** \brief The range of a numeric setting in words.
 *  \param[in] lowest the smallest value allowed (kAboveZeroSetting: any above 0)
 *  \param[in] highest the largest value allowed (kUnboundedSetting: no bound; kInfiniteSetting: inf too)
 *  \return "0 to 1", "at least 0", "above 0", "above 0, or inf" */
std::string
settingRangeText (double lowest, double highest);

/** \brief Whether \a value is within a numeric setting's range (see requireSettingInRange).
 *  \param[in] value the value
 *  \param[in] lowest the smallest value allowed (kAboveZeroSetting: any above 0)
 *  \param[in] highest the largest value allowed (kUnboundedSetting: no bound; kInfiniteSetting: inf too)
 *  \return true when it is allowed */
bool
isSettingInRange (double value, double lowest, double highest);

/** \brief Throws InvalidInputError "<kind> <name> = "<value>" is none of <choices>" unless \a value is one of them.
 *  \param[in] kind what the message calls a setting ("registration setting")
 *  \param[in] name the setting's name
 *  \param[in] value its value
 *  \param[in] choices the values allowed */
void
requireSettingChoice (const std::string& kind, const std::string& name, const std::string& value,
                      const std::vector<std::string>& choices);

/** \brief Throws InvalidInputError naming \a option (as a \a kind, e.g. "registration setting"), its value in
 *  \a settings and the range or the choices, when the value is outside them (a NaN is outside every range).
 *  \param[in] option the option to check
 *  \param[in] settings the settings holding its value
 *  \param[in] kind what the messages call a setting of this table
 */
template <typename Settings>
void
requireValidOption (const SettingOption<Settings>& option, const Settings& settings, const std::string& kind)
{
  std::visit (
      [&] (auto field) {
        const auto& value = settings.*field;
        using T = std::decay_t<decltype (value)>;
        if constexpr (std::is_same_v<T, int> || std::is_same_v<T, double>)
          requireSettingInRange (kind, option.name, value, option.lowest, option.highest);
        else if constexpr (std::is_same_v<T, std::optional<double>>) {
          if (value)
            requireSettingInRange (kind, option.name, *value, option.lowest, option.highest);
        }
        else if constexpr (std::is_same_v<T, std::vector<int>>) {
          for (int count : value)
            requireSettingInRange (kind, option.name, count, option.lowest, option.highest);
        }
        else if constexpr (std::is_same_v<T, std::string>)
          requireSettingChoice (kind, option.name, value, option.choices);
      },
      option.field);
}

/** \brief Throws InvalidInputError for the first entry of \a options whose value in \a settings is outside its range
 *  or choices (requireValidOption).
 *  \param[in] options the table
 *  \param[in] settings the settings
 *  \param[in] kind what the messages call a setting of this table */
template <typename Settings>
void
requireValidOptions (const std::vector<SettingOption<Settings>>& options, const Settings& settings,
                     const std::string& kind)
{
  for (const SettingOption<Settings>& option : options)
    requireValidOption (option, settings, kind);
}

/** \brief One table from its parts, in order (a long table is written as a few functions of related settings).
 *  \param[in] parts the parts
 *  \return the table */
template <typename Settings>
std::vector<SettingOption<Settings>>
joinedOptions (std::initializer_list<std::vector<SettingOption<Settings>>> parts)
{
  std::vector<SettingOption<Settings>> options;
  for (const std::vector<SettingOption<Settings>>& part : parts)
    options.insert (options.end (), part.begin (), part.end ());
  return options;
}

/** \brief The entry of a table by name.
 *  \param[in] options the table
 *  \param[in] name the setting's name
 *  \return the entry, or nullptr if there is none */
template <typename Settings>
const SettingOption<Settings>*
findSettingOption (const std::vector<SettingOption<Settings>>& options, const std::string& name)
{
  for (const SettingOption<Settings>& option : options)
    if (option.name == name)
      return &option;
  return nullptr;
}

} // namespace morphreg

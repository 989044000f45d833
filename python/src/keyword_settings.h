// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Keyword arguments read through a settings table (morphreg/common/setting_options.h): each keyword is a table
// entry's name, converted to its field's type (a TypeError naming it otherwise), unknown keywords are TypeErrors,
// and the docstring lists every entry with its default and help, so the command line and Python name, explain and
// bound a setting from the same table.
#include "python_model.h"

#include <morphreg/common/setting_options.h>

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace morphreg
{
namespace python
{
namespace py = pybind11;

/** A TypeError "FUNCTION(): NAME must be EXPECTED, got REPR". */
inline py::type_error
keywordTypeError (const std::string& function, const std::string& name, const char* expected, const py::handle& value)
{
  return py::type_error (function + "(): " + name + " must be " + expected + ", got " + std::string (py::repr (value)));
}

/** Sets the field of one keyword argument in the settings. */
template <typename Settings>
struct KeywordSetter
{
  Settings& settings;
  const SettingOption<Settings>& option;
  const py::handle& value;
  const std::string& function;

  template <typename T>
  T
  cast (const char* expected) const
  {
    try {
      return value.cast<T> ();
    }
    catch (const py::cast_error&) {
      throw keywordTypeError (function, option.name, expected, value);
    }
  }

  void
  operator() (int Settings::*field) const
  {
    if (py::isinstance<py::bool_> (value) || !py::isinstance<py::int_> (value))
      throw keywordTypeError (function, option.name, "an int", value);
    settings.*field = cast<int> ("an int");
  }
  void
  operator() (double Settings::*field) const
  {
    settings.*field = cast<double> ("a number");
  }
  void
  operator() (bool Settings::*field) const
  {
    settings.*field = cast<bool> ("a bool");
  }
  /** A name; a choice of "on" and "off" also takes a bool. */
  void
  operator() (std::string Settings::*field) const
  {
    if (py::isinstance<py::bool_> (value) && isOnOff ())
      settings.*field = value.cast<bool> () ? "on" : "off";
    else
      settings.*field = cast<std::string> (isOnOff () ? "a str or a bool" : "a str");
  }
  void
  operator() (std::optional<double> Settings::*field) const
  {
    settings.*field = value.is_none () ? std::nullopt : std::optional<double> (cast<double> ("a number or None"));
  }
  void
  operator() (std::vector<int> Settings::*field) const
  {
    settings.*field = componentCounts (value);
  }

  bool
  isOnOff () const
  {
    const auto& c = option.choices;
    return std::find (c.begin (), c.end (), "on") != c.end () && std::find (c.begin (), c.end (), "off") != c.end ();
  }
};

/** \a keywords as \a Settings through \a options (defaults for the others); a TypeError naming \a function for a
 *  keyword the table lacks or a value of the wrong type. The values' ranges are the library's to check. */
template <typename Settings>
Settings
settingsFromKeywords (const py::kwargs& keywords, const std::vector<SettingOption<Settings>>& options,
                      const std::string& function)
{
  Settings settings;
  for (const auto& [key, value] : keywords) {
    const std::string name = py::str (key);
    const SettingOption<Settings>* option = findSettingOption (options, name);
    if (!option)
      throw py::type_error (function + "() got an unexpected keyword argument '" + name + "' (see morphreg." +
                            function + ".__doc__ for the settings)");
    std::visit (KeywordSetter<Settings>{settings, *option, value, function}, option->field);
  }
  return settings;
}

/** \a counts as Python writes a list: "[1, 2, 3]". */
inline std::string
listText (const std::vector<int>& counts)
{
  std::string text;
  for (int count : counts)
    text += (text.empty () ? "[" : ", ") + std::to_string (count);
  return text + "]";
}

/** The default of \a option's field as Python writes it. */
template <typename Settings>
std::string
keywordDefault (const SettingOption<Settings>& option)
{
  const Settings defaults;
  return std::visit (
      [&defaults] (auto field) -> std::string {
        const auto& value = defaults.*field;
        using T = std::decay_t<decltype (value)>;
        if constexpr (std::is_same_v<T, bool>)
          return value ? "True" : "False";
        else if constexpr (std::is_same_v<T, std::string>)
          return "\"" + value + "\"";
        else if constexpr (std::is_same_v<T, std::optional<double>>)
          return "None";
        else if constexpr (std::is_same_v<T, std::vector<int>>)
          return value.empty () ? "None" : value.size () == 1 ? std::to_string (value.front ()) : listText (value);
        else {
          std::ostringstream text;
          text << value;
          return text.str ();
        }
      },
      option.field);
}

/** \a summary, then one line per entry of \a options: "name = default: help". */
template <typename Settings>
std::string
keywordDoc (const std::string& summary, const std::vector<SettingOption<Settings>>& options)
{
  std::string doc = summary;
  for (const SettingOption<Settings>& option : options)
    doc += "  " + option.name + " = " + keywordDefault (option) + ": " + option.help + "\n";
  return doc;
}

/** The values of \a settings by the names of \a options: name -> value. */
template <typename Settings>
py::dict
keywordValues (const Settings& settings, const std::vector<SettingOption<Settings>>& options)
{
  py::dict values;
  for (const SettingOption<Settings>& option : options)
    std::visit ([&] (auto field) { values[py::str (option.name)] = py::cast (settings.*field); }, option.field);
  return values;
}

/** The table as Python sees it: name -> (default as Python writes it, help). */
template <typename Settings>
py::dict
keywordTable (const std::vector<SettingOption<Settings>>& options)
{
  py::dict table;
  for (const SettingOption<Settings>& option : options)
    table[py::str (option.name)] = py::make_tuple (keywordDefault (option), option.help);
  return table;
}
} // namespace python
} // namespace morphreg

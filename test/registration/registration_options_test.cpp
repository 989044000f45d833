// SPDX-License-Identifier: BSD-3-Clause
// The one table of registration settings (registration_options.h) that the command line, the Python module and the
// library's checks read.
#include "support/expect_error.h"

#include <morphreg/common/error.h>
#include <morphreg/registration/registration_options.h>
#include <morphreg/registration/registration_settings.h>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <type_traits>

namespace
{
using morphreg::RegistrationOption;
using morphreg::RegistrationSettings;
using morphreg::test::expectErrorContaining;

/** \a settings with \a option's field set to \a value (numbers: every count of a list; names: the text). */
struct SetValue
{
  RegistrationSettings& settings;
  double value;

  template <typename Field>
  void
  operator() (Field field) const
  {
    using T = std::decay_t<decltype (settings.*field)>;
    if constexpr (std::is_same_v<T, int>)
      settings.*field = static_cast<int> (value);
    else if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::optional<double>>)
      settings.*field = value;
    else if constexpr (std::is_same_v<T, std::vector<int>>)
      settings.*field = {static_cast<int> (value)};
  }
};

TEST (RegistrationOptionsTest, EverySettingHasOneEntryWithHelp)
{
  std::set<std::string> names;
  for (const RegistrationOption& option : morphreg::registrationOptions ()) {
    EXPECT_TRUE (names.insert (option.name).second) << option.name << " twice";
    EXPECT_GT (option.help.size (), 20u) << option.name;
    EXPECT_EQ (morphreg::findRegistrationOption (option.name), &option);
  }
  // every field of the report's settings comes from one entry (the report renames some: max_distance ->
  // max_correspondence_distance_mm), so the table holds as many settings as the report
  EXPECT_EQ (names.size (), morphreg::toJson (RegistrationSettings ()).size ());
  EXPECT_EQ (morphreg::findRegistrationOption ("max_distanse"), nullptr);
  EXPECT_EQ (morphreg::commandLineName (morphreg::findRegistrationOption ("max_distance")->name), "--max-distance");
}

TEST (RegistrationOptionsTest, TheDefaultsAreInRangeAndEveryBoundIsChecked)
{
  EXPECT_NO_THROW (morphreg::requireValidSettings (RegistrationSettings ()));
  for (const RegistrationOption& option : morphreg::registrationOptions ()) {
    if (std::holds_alternative<std::string RegistrationSettings::*> (option.field)) {
      RegistrationSettings settings;
      settings.*std::get<std::string RegistrationSettings::*> (option.field) = "furlong";
      expectErrorContaining<morphreg::InvalidInputError> ([&] { morphreg::requireValidSettings (settings); },
                                                          option.name + " = \"furlong\" is none of");
      continue;
    }
    if (std::holds_alternative<bool RegistrationSettings::*> (option.field))
      continue; // a switch (its choices, if any, name the switch that turns it off)
    const bool counts = std::holds_alternative<int RegistrationSettings::*> (option.field) ||
                        std::holds_alternative<std::vector<int> RegistrationSettings::*> (option.field);
    for (const double outside : {option.lowest - 1.0, option.highest * 2.0, std::nan ("")}) {
      if (std::isinf (outside) || (std::isnan (outside) && counts))
        continue; // no upper bound; a count cannot hold a NaN
      RegistrationSettings settings;
      std::visit (SetValue{settings, outside}, option.field);
      expectErrorContaining<morphreg::InvalidInputError> ([&] { morphreg::requireValidSettings (settings); },
                                                          "registration setting " + option.name + " = ");
    }
  }
}

} // namespace

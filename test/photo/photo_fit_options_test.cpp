// SPDX-License-Identifier: BSD-3-Clause
// The one table of photo fit settings (photo_fit_options.h) that fit-photos, Python's fit_photos and the library's
// checks read, and the bounds a table can state (setting_options.h): above zero, and infinity allowed.
#include "support/expect_error.h"

#include <morphreg/common/error.h>
#include <morphreg/common/setting_options.h>
#include <morphreg/photo/photo_fit_options.h>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>
#include <type_traits>

namespace
{
using morphreg::PhotoFitOption;
using morphreg::PhotoFitOptions;
using morphreg::test::expectErrorContaining;

/** \a options with \a field set to \a value (a list: its one count). */
struct SetValue
{
  PhotoFitOptions& options;
  double value;

  template <typename Field>
  void
  operator() (Field field) const
  {
    using T = std::decay_t<decltype (options.*field)>;
    if constexpr (std::is_same_v<T, double> || std::is_same_v<T, std::optional<double>>)
      options.*field = value;
    else if constexpr (std::is_same_v<T, std::vector<int>>)
      options.*field = {static_cast<int> (value)};
  }
};

void
expectRefused (const PhotoFitOption& option, double value, const std::string& fragment)
{
  PhotoFitOptions options;
  std::visit (SetValue{options, value}, option.field);
  expectErrorContaining<morphreg::InvalidInputError> ([&] { morphreg::requireValidPhotoFitOptions (options); },
                                                      "photo fit setting " + option.name + " = " + fragment);
}

TEST (PhotoFitOptionsTest, EverySettingHasOneEntryWithHelpAndTheReportHasThemAll)
{
  std::set<std::string> names;
  for (const PhotoFitOption& option : morphreg::photoFitOptionTable ()) {
    EXPECT_TRUE (names.insert (option.name).second) << option.name << " twice";
    EXPECT_GT (option.help.size (), 20u) << option.name;
  }
  EXPECT_EQ (names.size (), morphreg::toJson (PhotoFitOptions ()).size ());
}

TEST (PhotoFitOptionsTest, TheDefaultsAreInRangeAndEveryBoundIsChecked)
{
  EXPECT_NO_THROW (morphreg::requireValidPhotoFitOptions (PhotoFitOptions ()));
  for (const PhotoFitOption& option : morphreg::photoFitOptionTable ()) {
    if (!option.choices.empty ()) {
      PhotoFitOptions options;
      options.*std::get<std::string PhotoFitOptions::*> (option.field) = "furlong";
      expectErrorContaining<morphreg::InvalidInputError> ([&] { morphreg::requireValidPhotoFitOptions (options); },
                                                          option.name + " = \"furlong\" is none of");
      continue;
    }
    if (option.lowest == morphreg::kAboveZeroSetting)
      expectRefused (option, 0.0, "0 is out of range (above 0");
    else
      expectRefused (option, option.lowest - 1.0, "-1 is out of range");
    if (!std::holds_alternative<std::vector<int> PhotoFitOptions::*> (option.field))
      expectRefused (option, std::nan (""), "nan is out of range");
  }
}

TEST (PhotoFitOptionsTest, NoCoefficientLimitIsInfinityAndOtherSettingsRefuseIt)
{
  PhotoFitOptions options;
  options.coefficient_limit = std::numeric_limits<double>::infinity ();
  EXPECT_NO_THROW (morphreg::requireValidPhotoFitOptions (options));
  options.coefficient_limit = -std::numeric_limits<double>::infinity ();
  EXPECT_THROW (morphreg::requireValidPhotoFitOptions (options), morphreg::InvalidInputError);
  options = PhotoFitOptions ();
  options.landmark_weight = std::numeric_limits<double>::infinity ();
  expectErrorContaining<morphreg::InvalidInputError> ([&] { morphreg::requireValidPhotoFitOptions (options); },
                                                      "landmark_weight = inf is out of range (above 0)");
}

TEST (SettingRangeTest, RangesInWords)
{
  using morphreg::settingRangeText;
  EXPECT_EQ (settingRangeText (0, 1), "0 to 1");
  EXPECT_EQ (settingRangeText (1, morphreg::kUnboundedSetting), "at least 1");
  EXPECT_EQ (settingRangeText (morphreg::kAboveZeroSetting, morphreg::kUnboundedSetting), "above 0");
  EXPECT_EQ (settingRangeText (morphreg::kAboveZeroSetting, morphreg::kInfiniteSetting), "above 0, or inf");
  EXPECT_EQ (settingRangeText (morphreg::kAboveZeroSetting, 2), "above 0 to 2");
  EXPECT_FALSE (morphreg::isSettingInRange (0.0, morphreg::kAboveZeroSetting, 1.0));
  EXPECT_TRUE (morphreg::isSettingInRange (1e-300, morphreg::kAboveZeroSetting, 1.0));
  EXPECT_FALSE (morphreg::isSettingInRange (std::numeric_limits<double>::infinity (), 0, morphreg::kUnboundedSetting));
}
} // namespace

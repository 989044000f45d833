// SPDX-License-Identifier: BSD-3-Clause
// A settings table's entries as command-line options: switches with their off names, ranges as checks.
#include "table_options.h"

#include <morphreg/model/model_builder_options.h>
#include <morphreg/registration/registration_options.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace
{
/** \a settings after parsing \a arguments with every option of \a table added to a command. */
template <typename Settings>
Settings
parsed (const std::vector<morphreg::SettingOption<Settings>>& table, std::vector<std::string> arguments)
{
  Settings settings;
  CLI::App command ("table options");
  for (const auto& option : table)
    morphreg::tools::addTableOption (&command, settings, option);
  std::reverse (arguments.begin (), arguments.end ()); // CLI11 takes them last to first
  command.parse (arguments);
  return settings;
}
} // namespace

using morphreg::ModelBuilderSettings;
using morphreg::RegistrationSettings;

TEST (TableOptionTest, SwitchOnByDefaultIsTurnedOffByItsOffName)
{
  ASSERT_TRUE (ModelBuilderSettings ().align);
  EXPECT_FALSE (parsed (morphreg::modelBuilderOptions (), {"--no-procrustes"}).align);
  EXPECT_TRUE (parsed (morphreg::modelBuilderOptions (), {"--procrustes"}).align);
  EXPECT_TRUE (parsed (morphreg::modelBuilderOptions (), {}).align);
  ASSERT_TRUE (RegistrationSettings ().point_to_plane);
  EXPECT_FALSE (parsed (morphreg::registrationOptions (), {"--point-to-point"}).point_to_plane);
  EXPECT_TRUE (parsed (morphreg::registrationOptions (), {"--point-to-plane"}).point_to_plane);
}

TEST (TableOptionTest, NumberOutsideItsRangeIsRefusedWithTheRange)
{
  try {
    parsed (morphreg::modelBuilderOptions (), {"--blend-rings", "1001"});
    FAIL () << "--blend-rings 1001 was accepted";
  }
  catch (const CLI::ValidationError& error) {
    EXPECT_NE (std::string (error.what ()).find ("1001"), std::string::npos) << error.what ();
  }
  EXPECT_EQ (parsed (morphreg::modelBuilderOptions (), {"--blend-rings", "4"}).blend_rings, 4);
}

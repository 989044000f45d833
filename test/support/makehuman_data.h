// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The MakeHuman bodies of ../shared/data/makehuman_bodies for the warp tests, which skip when the folder is absent.
#include <filesystem>
#include <string>

namespace morphreg
{
namespace test
{
inline std::string
bodiesDirectory ()
{
  return std::string (MORPHREG_SHARED_DATA_DIR) + "/makehuman_bodies";
}
} // namespace test
} // namespace morphreg

#define REQUIRE_BODIES()                                                                                               \
  if (!std::filesystem::exists (morphreg::test::bodiesDirectory () + "/mh_joints.json"))                               \
  GTEST_SKIP () << "MakeHuman bodies not found in " << morphreg::test::bodiesDirectory ()                              \
                << " (../shared/data is absent)"

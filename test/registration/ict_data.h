// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The ICT-FaceKit model for the registration tests with real data: loaded once per executable, with the skip
// message used when ../shared/data is absent.
#include <morphreg/datasets/ict_facekit.h>

#include <filesystem>
#include <string>

namespace morphreg
{
namespace test
{
inline std::string
sharedDataPath (const std::string& relative)
{
  return std::string (MORPHREG_SHARED_DATA_DIR) + "/" + relative;
}

inline bool
ictAvailable ()
{
  return std::filesystem::exists (sharedDataPath ("ict_facekit/ict_head_pca_basis.npy"));
}

inline const MorphableModel::ConstPtr&
ictModel ()
{
  static const MorphableModel::ConstPtr model = loadIctFaceKit (sharedDataPath ("ict_facekit"));
  return model;
}

} // namespace test
} // namespace morphreg

#define MORPHREG_REQUIRE_ICT()                                                                                         \
  if (!morphreg::test::ictAvailable ())                                                                                \
  GTEST_SKIP () << "ICT-FaceKit data not found in " << morphreg::test::sharedDataPath ("ict_facekit")                  \
                << " (../shared/data is absent)"

// SPDX-License-Identifier: BSD-3-Clause
// Landmark pairs for a warp: landmarks on one point must go to one point.
#include <morphreg/common/error.h>
#include <morphreg/common/landmarks.h>

#include "support/expect_error.h"

#include <gtest/gtest.h>

using morphreg::LandmarkPositions;

TEST (LandmarksTest, CoincidentLandmarksWithOneTargetAreAccepted)
{
  // A bone's tail at the next bone's head, in both postures: a warp merges them.
  const LandmarkPositions source = {{"a", {0, 0, 0}}, {"b", {0, 0, 0}}, {"c", {10, 0, 0}}};
  const LandmarkPositions target = {{"a", {1, 1, 1}}, {"b", {1, 1, 1}}, {"c", {12, 0, 0}}};
  EXPECT_NO_THROW (morphreg::requireOneTargetPerPoint (source, target, "source.csv", "target.csv"));
}

TEST (LandmarksTest, CoincidentLandmarksSentToTwoPlacesAreNamed)
{
  const LandmarkPositions source = {
      {"nose_tip", {0, 30, 110}}, {"chin", {0, -40, 95}}, {"right_eyebrow", {0, 30, 110}}};
  LandmarkPositions target = source;
  target["right_eyebrow"] = {-30, 70, 80};
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> (
      [&] { morphreg::requireOneTargetPerPoint (source, target, "source.csv", "target.csv"); },
      "landmarks nose_tip and right_eyebrow are at one position (0, 30, 110) in source.csv but");
}

// SPDX-License-Identifier: BSD-3-Clause
// surfaceDistance on meshes with known answers: target samples to the closest fitted point, samples
// that only reach the fitted boundary dropped, statistics, and bad input.
#include <morphreg/common/error.h>
#include <morphreg/registration/surface_distance.h>
#include "support/test_meshes.h"

#include <gtest/gtest.h>

namespace
{
using morphreg::TriangleMesh;

TEST (SurfaceDistanceTest, ParallelPlanesAreTheirOffsetApart)
{
  const TriangleMesh target = morphreg::test::makeGrid (11, 2.0); // 20 x 20 mm at z = 0
  TriangleMesh fitted = morphreg::test::makeGrid (31, 2.0);       // 60 x 60 mm around it, 0.5 mm above
  fitted.vertices.row (0).array () -= 20.0;
  fitted.vertices.row (1).array () -= 20.0;
  fitted.vertices.row (2).array () += 0.5;
  const auto distance = morphreg::surfaceDistance (target, fitted);
  EXPECT_EQ (distance.samples, 100) << "one sample per 4 mm^2 of 400 mm^2";
  EXPECT_EQ (distance.dropped_on_boundary, 0);
  ASSERT_EQ (distance.distances.size (), 100u);
  EXPECT_NEAR (distance.median, 0.5, 1e-9);
  EXPECT_NEAR (distance.percentile95, 0.5, 1e-9);
  EXPECT_NEAR (distance.mean, 0.5, 1e-9);
  EXPECT_NEAR (distance.rms, 0.5, 1e-9);
  EXPECT_NEAR (distance.max, 0.5, 1e-9);
}

TEST (SurfaceDistanceTest, TargetPartsBeyondTheFittedBoundaryAreDropped)
{
  const TriangleMesh target = morphreg::test::makeGrid (21, 1.0); // [0, 20]^2
  const TriangleMesh fitted = morphreg::test::makeGrid (11, 1.0); // [0, 10]^2: a quarter of the target
  morphreg::SurfaceDistanceSettings settings;
  settings.area_per_sample = 0.25;
  const auto distance = morphreg::surfaceDistance (target, fitted, {}, settings);
  EXPECT_EQ (distance.samples, 1600);
  EXPECT_NEAR (distance.dropped_on_boundary, 1200, 80) << "three quarters lie beyond the fitted square";
  EXPECT_LT (distance.max, 1e-9) << "the kept samples lie on the fitted surface";

  settings.drop_boundary = false;
  const auto all = morphreg::surfaceDistance (target, fitted, {}, settings);
  EXPECT_EQ (all.dropped_on_boundary, 0);
  EXPECT_NEAR (all.max, std::sqrt (200.0), 0.5) << "the far corner (20, 20) is 10 sqrt 2 from (10, 10)";

  // Excluding the target triangles beyond the fitted square leaves only the overlap.
  std::vector<bool> outside (static_cast<size_t> (target.numTriangles ()));
  for (Eigen::Index t = 0; t < target.numTriangles (); ++t)
    outside[static_cast<size_t> (t)] = target.vertices.col (target.triangles (0, t)).maxCoeff () >= 10.0;
  const auto overlap = morphreg::surfaceDistance (target, fitted, outside, settings);
  EXPECT_EQ (overlap.samples, 400);
  EXPECT_LT (overlap.dropped_on_boundary, 40) << "only samples on the fitted border itself";
}

TEST (SurfaceDistanceTest, BadInputIsReported)
{
  const TriangleMesh grid = morphreg::test::makeGrid (5);
  EXPECT_THROW (morphreg::surfaceDistance (grid, TriangleMesh ()), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::surfaceDistance (TriangleMesh (), grid), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::surfaceDistance (grid, grid, {true, false}), morphreg::InvalidInputError);
  morphreg::SurfaceDistanceSettings settings;
  settings.area_per_sample = -4.0;
  EXPECT_THROW (morphreg::surfaceDistance (grid, grid, {}, settings), morphreg::InvalidInputError);
  // A target far beyond a small fitted patch reaches it only at its boundary: nothing is left to measure.
  TriangleMesh far = grid;
  far.vertices.row (0).array () += 100.0;
  EXPECT_THROW (morphreg::surfaceDistance (far, grid), morphreg::InvalidInputError);
}

} // namespace

namespace
{
TEST (SurfaceDistanceTest, StatisticsOverFlaggedFittedTriangles)
{
  const TriangleMesh target = morphreg::test::makeGrid (11, 2.0); // 20 x 20 mm at z = 0
  TriangleMesh fitted = target;                                   // the left half 1 mm above, the right half 3 mm
  for (Eigen::Index v = 0; v < fitted.vertices.cols (); ++v)
    fitted.vertices (2, v) = fitted.vertices (0, v) <= 10.0 ? 1.0 : 3.0;
  morphreg::SurfaceDistanceSettings settings;
  settings.drop_boundary = false;
  const auto all = morphreg::surfaceDistance (target, fitted, {}, settings);
  ASSERT_EQ (all.fitted_triangles.size (), all.distances.size ());
  std::vector<bool> left (static_cast<size_t> (fitted.triangles.cols ()));
  for (Eigen::Index t = 0; t < fitted.triangles.cols (); ++t) {
    double x = 0.0;
    for (int k = 0; k < 3; ++k)
      x = std::max (x, fitted.vertices (0, fitted.triangles (k, t)));
    left[static_cast<size_t> (t)] = x <= 10.0;
  }
  const auto over_left = morphreg::surfaceDistanceOver (all, left);
  EXPECT_GT (over_left.distances.size (), 0u);
  EXPECT_LT (over_left.distances.size (), all.distances.size ());
  EXPECT_NEAR (over_left.median, 1.0, 0.05) << "samples that land on the flat 1 mm half";
  EXPECT_THROW (morphreg::surfaceDistanceOver (all, std::vector<bool> (3, true)), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::surfaceDistanceOver (all, std::vector<bool> (left.size (), false)),
                morphreg::InvalidInputError);
}
} // namespace

// SPDX-License-Identifier: BSD-3-Clause
// The resampler's neighbour search: exact k nearest neighbours, checked against brute force on scan-like clouds,
// far queries, outliers that stretch the grid, and degenerate clouds.
#include "resampling/point_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

namespace
{
using morphreg::detail::PointGrid;

/** Points on a sphere of radius 100 mm with 0.2 mm noise: a head-sized scan surface. */
Eigen::Matrix3Xd
noisySphere (int count, std::mt19937& rng)
{
  std::normal_distribution<double> normal (0.0, 1.0);
  Eigen::Matrix3Xd points (3, count);
  for (int i = 0; i < count; ++i) {
    const Eigen::Vector3d direction = Eigen::Vector3d (normal (rng), normal (rng), normal (rng)).normalized ();
    points.col (i) = (100.0 + 0.2 * normal (rng)) * direction;
  }
  return points;
}

/** The squared distance of the k-th nearest column of \a points to \a query, by brute force. */
double
bruteKth (const Eigen::Matrix3Xd& points, const Eigen::Vector3d& query, int k)
{
  std::vector<double> squared (static_cast<std::size_t> (points.cols ()));
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    squared[i] = (points.col (i) - query).squaredNorm ();
  std::nth_element (squared.begin (), squared.begin () + (k - 1), squared.end ());
  return squared[k - 1];
}

/** Expects \a found to be k distinct points, none farther than the true k-th nearest (up to float rounding). */
void
expectNearest (const Eigen::Matrix3Xd& points, const Eigen::Vector3d& query, int k, const std::vector<int>& found)
{
  ASSERT_EQ (static_cast<int> (found.size ()), k);
  std::vector<int> sorted = found;
  std::sort (sorted.begin (), sorted.end ());
  EXPECT_EQ (std::adjacent_find (sorted.begin (), sorted.end ()), sorted.end ()) << "a point returned twice";
  const double kth = bruteKth (points, query, k);
  for (const int index : found)
    EXPECT_LE ((points.col (index) - query).squaredNorm (), kth * (1.0 + 1e-5) + 1e-9);
}

TEST (PointGridTest, KNearestMatchBruteForceNearAndOffTheSurface)
{
  std::mt19937 rng (7);
  const Eigen::Matrix3Xd points = noisySphere (20000, rng);
  const PointGrid grid (points, 2.0);
  std::normal_distribution<double> normal (0.0, 1.0);
  std::uniform_real_distribution<double> offset (-8.0, 8.0);
  std::vector<int> indices;
  std::vector<double> squared;
  for (int trial = 0; trial < 300; ++trial) {
    const Eigen::Vector3d direction = Eigen::Vector3d (normal (rng), normal (rng), normal (rng)).normalized ();
    const Eigen::Vector3d query = (100.0 + offset (rng)) * direction;
    for (const int k : {1, 5, 24}) {
      const double kth = grid.nearestK (query, k, std::numeric_limits<double>::infinity (), indices, squared);
      expectNearest (points, query, k, indices);
      EXPECT_NEAR (kth, bruteKth (points, query, k), 1e-4 * kth + 1e-9);
      EXPECT_EQ (indices.size (), squared.size ());
    }
  }
}

TEST (PointGridTest, QueriesFarOutsideTheGridFindTheNearest)
{
  std::mt19937 rng (8);
  const Eigen::Matrix3Xd points = noisySphere (2000, rng);
  const PointGrid grid (points, 3.0);
  std::vector<int> indices;
  std::vector<double> squared;
  for (const Eigen::Vector3d& query : {Eigen::Vector3d (0, 0, 0), Eigen::Vector3d (500, 0, 0),
                                       Eigen::Vector3d (-1e5, 3e4, 2e5), Eigen::Vector3d (0, -130, 40)}) {
    grid.nearestK (query, 10, std::numeric_limits<double>::infinity (), indices, squared);
    expectNearest (points, query, 10, indices);
  }
}

TEST (PointGridTest, NothingBeyondTheSearchRadius)
{
  std::mt19937 rng (9);
  const Eigen::Matrix3Xd points = noisySphere (5000, rng);
  const PointGrid grid (points, 2.0);
  std::vector<int> indices{1, 2};
  std::vector<double> squared{1.0};
  const Eigen::Vector3d centre = Eigen::Vector3d::Zero (); // every point is about 100 mm away
  EXPECT_TRUE (std::isinf (grid.nearestK (centre, 24, 50.0, indices, squared)));
  EXPECT_TRUE (indices.empty ());
  EXPECT_TRUE (squared.empty ());
  const double kth = grid.nearestK (centre, 24, 150.0, indices, squared);
  EXPECT_LT (kth, 150.0 * 150.0);
  expectNearest (points, centre, 24, indices);
}

TEST (PointGridTest, FarStraysKeepTheCellsSmallAndTheSearchExact)
{
  std::mt19937 rng (10);
  Eigen::Matrix3Xd points = noisySphere (3000, rng);
  points.col (0) = Eigen::Vector3d (1e7, -1e7, 1e7); // a grid of 0.5 mm cells over this would be 10^30 cells
  points.col (1) = Eigen::Vector3d (-1e7, 1e7, -1e7);
  const PointGrid grid (points, 0.5);
  const double sphere_cell = PointGrid (points.rightCols (2998), 0.5).cellSize (); // 0.5 mm would be too many cells
  EXPECT_NEAR (grid.cellSize (), sphere_cell, 0.01 * sphere_cell) << "two strays do not stretch the cells";
  std::vector<int> indices;
  std::vector<double> squared;
  for (const Eigen::Vector3d& query : {Eigen::Vector3d (100, 0, 0), Eigen::Vector3d (1e7, -1e7, 1e7),
                                       Eigen::Vector3d (-2e7, 5e6, 0), Eigen::Vector3d (0, 0, 101)}) {
    grid.nearestK (query, 8, std::numeric_limits<double>::infinity (), indices, squared);
    expectNearest (points, query, 8, indices);
  }
  Eigen::Matrix3Xd spread = noisySphere (3000, rng); // a tenth of the points far out: the grid spans them all
  spread.rightCols (300) *= 100.0;
  EXPECT_GT (PointGrid (spread, 0.5).cellSize (), 10.0 * sphere_cell);
}

TEST (PointGridTest, DegenerateClouds)
{
  std::vector<int> indices;
  std::vector<double> squared;
  const double unlimited = std::numeric_limits<double>::infinity ();

  const PointGrid single (Eigen::Matrix3Xd (Eigen::Vector3d (1, 2, 3)), 1.0);
  EXPECT_DOUBLE_EQ (single.nearestK (Eigen::Vector3d (1, 2, 4), 1, unlimited, indices, squared), 1.0);
  EXPECT_EQ (indices, std::vector<int>{0});

  const Eigen::Matrix3Xd same = Eigen::Vector3d (5, 5, 5).replicate (1, 30); // all one point
  const PointGrid same_grid (same, 1.0);
  same_grid.nearestK (Eigen::Vector3d (5, 5, 5), 30, unlimited, indices, squared);
  expectNearest (same, Eigen::Vector3d (5, 5, 5), 30, indices);

  Eigen::Matrix3Xd plane (3, 400); // flat: no extent along z
  for (int i = 0; i < 400; ++i)
    plane.col (i) = Eigen::Vector3d (i % 20, i / 20, 0.0);
  for (const double cell : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN (), 0.3}) {
    const PointGrid grid (plane, cell); // an unusable cell size falls back to a sensible one
    grid.nearestK (Eigen::Vector3d (7.2, 11.6, 0.4), 12, unlimited, indices, squared);
    expectNearest (plane, Eigen::Vector3d (7.2, 11.6, 0.4), 12, indices);
  }
}
} // namespace

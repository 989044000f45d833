// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/common/order_statistics.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

TEST (OrderStatisticsTest, PercentilesInterpolateBetweenOrderStatistics)
{
  EXPECT_DOUBLE_EQ (morphreg::percentile ({3.0, 1.0, 2.0}, 0.5), 2.0);
  EXPECT_DOUBLE_EQ (morphreg::percentile ({4.0, 1.0, 2.0, 3.0}, 0.5), 2.5);
  EXPECT_DOUBLE_EQ (morphreg::percentile ({0.0, 10.0}, 0.95), 9.5);
  EXPECT_DOUBLE_EQ (morphreg::percentile ({7.0}, 1.0), 7.0);
}

TEST (OrderStatisticsTest, MedianTakesTheUpperMiddleValue)
{
  EXPECT_DOUBLE_EQ (morphreg::median ({5.0, 1.0, 3.0}), 3.0);
  EXPECT_DOUBLE_EQ (morphreg::median ({4.0, 1.0, 2.0, 3.0}), 3.0);
}

// Small samples are ranked by counting, larger ones selected: both give the sorted sample's upper middle value, with
// ties, for vectors and for Eigen vectors.
TEST (OrderStatisticsTest, MedianOfSmallAndLargeSamplesWithTies)
{
  std::mt19937 rng (3);
  std::uniform_int_distribution<int> value (0, 9); // many ties
  for (int size = 1; size <= 100; ++size) {
    std::vector<double> sample (static_cast<std::size_t> (size));
    for (double& v : sample)
      v = value (rng);
    std::vector<double> sorted = sample;
    std::sort (sorted.begin (), sorted.end ());
    const double expected = sorted[sorted.size () / 2];
    EXPECT_DOUBLE_EQ (morphreg::median (sample), expected) << size << " values";
    const Eigen::VectorXd column = Eigen::Map<const Eigen::VectorXd> (sample.data (), size);
    EXPECT_DOUBLE_EQ (morphreg::median (column), expected) << size << " values";
    EXPECT_DOUBLE_EQ (morphreg::median ((2.0 * column.array ()).matrix ()), 2.0 * expected) << size << " values";
  }
  EXPECT_THROW (morphreg::median (Eigen::VectorXd ()), morphreg::InvalidInputError);
}

TEST (OrderStatisticsTest, TrimmedStatisticsKeepTheSmallestShare)
{
  const std::vector<double> values{10.0, 1.0, 2.0, 3.0, 1000.0};
  EXPECT_DOUBLE_EQ (morphreg::trimmedLimit (values, 0.6), 3.0);
  EXPECT_DOUBLE_EQ (morphreg::trimmedMean (values, 0.6), 2.0);
  EXPECT_DOUBLE_EQ (morphreg::trimmedLimit (values, 0.01), 1.0) << "at least one value is kept";
}

TEST (OrderStatisticsTest, PointsNearTheMedianLeaveOutliersOut)
{
  Eigen::Matrix3Xd points = Eigen::Matrix3Xd::Zero (3, 10);
  for (int i = 0; i < 10; ++i)
    points (0, i) = i;
  points.col (9) << 1e6, 1e6, 1e6;
  const Eigen::Matrix3Xd kept = morphreg::pointsNearMedian (points, 0.9, 4);
  EXPECT_EQ (kept.cols (), 9);
  EXPECT_LT (kept.maxCoeff (), 10.0);
  EXPECT_EQ (morphreg::pointsNearMedian (points.leftCols (3), 0.5, 4).cols (), 3) << "never more than there are";
  EXPECT_DOUBLE_EQ (morphreg::coordinateMedian (points) (0), 5.0);
}

TEST (OrderStatisticsTest, BadInputIsReported)
{
  EXPECT_THROW (morphreg::percentile ({}, 0.5), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::percentile ({1.0}, 1.5), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::median ({}), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::trimmedMean ({}, 0.5), morphreg::InvalidInputError);
}

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/warp/transformation_estimation_tps.h>

#include "tps_test_support.h"

#include <gtest/gtest.h>

using morphreg::InvalidInputError;
using morphreg::test::bend;
using morphreg::test::maxColumnDistance;
using morphreg::test::randomLandmarks;
using Estimation = morphreg::TransformationEstimationTPS<pcl::PointNormal, pcl::PointNormal>;

namespace
{
pcl::PointCloud<pcl::PointNormal>
toCloud (const Eigen::Matrix3Xd& points)
{
  pcl::PointCloud<pcl::PointNormal> cloud;
  cloud.resize (points.cols ());
  for (Eigen::Index j = 0; j < points.cols (); ++j)
    cloud[j].getVector3fMap () = points.col (j).cast<float> ();
  return cloud;
}

struct Landmarks
{
  Eigen::Matrix3Xd source = randomLandmarks (30, 41).cast<float> ().cast<double> ();
  Eigen::Matrix3Xd target = bend<3> (source).cast<float> ().cast<double> ();
  Eigen::Matrix3Xd queries = randomLandmarks (50, 42);
};
} // namespace

TEST (TransformationEstimationTpsTest, AllInputFormsGiveTheSameSpline)
{
  const Landmarks data;
  morphreg::ThinPlateSpline<double, 3> reference;
  reference.fit (data.source, data.target);
  const Eigen::Matrix3Xd expected = reference.evaluate (data.queries);

  // The source cloud has 10 extra points in front; index lists and correspondences skip them.
  Eigen::Matrix3Xd padded (3, 40);
  padded << randomLandmarks (10, 43), data.source;
  const auto source = toCloud (padded), target = toCloud (data.target);
  pcl::Indices indices_src, indices_tgt;
  pcl::Correspondences correspondences;
  for (int j = 0; j < 30; ++j) {
    indices_src.push_back (10 + j);
    indices_tgt.push_back (j);
    correspondences.emplace_back (10 + j, j, 0.0f);
  }
  const Estimation estimation;
  Estimation::Spline spline;
  estimation.estimateTransformation (toCloud (data.source), target, spline);
  EXPECT_LE (maxColumnDistance (spline.evaluate (data.queries), expected), 1e-9);
  estimation.estimateTransformation (source, indices_src, target, spline);
  EXPECT_LE (maxColumnDistance (spline.evaluate (data.queries), expected), 1e-9);
  estimation.estimateTransformation (source, indices_src, target, indices_tgt, spline);
  EXPECT_LE (maxColumnDistance (spline.evaluate (data.queries), expected), 1e-9);
  estimation.estimateTransformation (source, target, correspondences, spline);
  EXPECT_LE (maxColumnDistance (spline.evaluate (data.queries), expected), 1e-9);
}

TEST (TransformationEstimationTpsTest, PassesSettingsToTheSpline)
{
  const Landmarks data;
  Estimation estimation;
  estimation.setRegularization (50.0);
  EXPECT_EQ (estimation.getRegularization (), 50.0);
  morphreg::ThinPlateSpline<double, 3> reference;
  reference.setRegularization (50.0);
  reference.fit (data.source, data.target);
  Estimation::Spline spline;
  estimation.estimateTransformation (toCloud (data.source), toCloud (data.target), spline);
  EXPECT_EQ (spline.getRegularization (), 50.0);
  EXPECT_LE (maxColumnDistance (spline.evaluate (data.queries), reference.evaluate (data.queries)), 1e-9);
  EXPECT_THROW (estimation.setRegularization (-1.0), InvalidInputError);
  estimation.setMaxConditionNumber (2.0);
  EXPECT_THROW (estimation.estimateTransformation (toCloud (data.source), toCloud (data.target), spline),
                morphreg::NumericalError);
}

TEST (TransformationEstimationTpsTest, RejectsBadIndicesAndSizes)
{
  const Landmarks data;
  const auto source = toCloud (data.source), target = toCloud (data.target);
  const Estimation estimation;
  Estimation::Spline spline;
  EXPECT_THROW (estimation.estimateTransformation (source, toCloud (data.target.leftCols (29)), spline),
                InvalidInputError);
  EXPECT_THROW (estimation.estimateTransformation (source, pcl::Indices (), target, spline), InvalidInputError);
  pcl::Indices indices (30);
  for (int j = 0; j < 30; ++j)
    indices[j] = j;
  indices[4] = 30;
  EXPECT_THROW (estimation.estimateTransformation (source, indices, target, spline), InvalidInputError);
  indices[4] = 4;
  EXPECT_THROW (estimation.estimateTransformation (source, indices, target, pcl::Indices (3, 0), spline),
                InvalidInputError);
  pcl::Correspondences correspondences = {pcl::Correspondence (0, 99, 0.0f)};
  EXPECT_THROW (estimation.estimateTransformation (source, target, correspondences, spline), InvalidInputError);
}

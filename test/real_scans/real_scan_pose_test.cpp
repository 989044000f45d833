// SPDX-License-Identifier: BSD-3-Clause
// Landmark-free registration of the real head-and-shoulders scan from random similarity poses (required: every
// pose succeeds: register's checks pass and the face median is at most 0.85 mm).
#include "real_scan_support.h"
#include "support/sample_count.h"

#include <morphreg/registration/fit_plausibility.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace
{
using namespace morphreg::test;
using Icp = morphreg::MorphableICP<pcl::PointNormal>;

int
poseCount ()
{
  return sampleCount (24);
}

struct PoseRun
{
  double face_median;
  double seconds;
  bool converged;
  std::string unit;
};

/** Registers \a cloud under \a pose, written in a unit \a unit_scale times the mm (the unit left to MorphableICP's
 *  guess), and scores the fit in the scan's original frame. */
PoseRun
runPose (const pcl::PointCloud<pcl::PointNormal>& cloud, const Eigen::Matrix4d& pose, const char* name, int k,
         double unit_scale = 1.0)
{
  Icp icp;
  configureIctIcp (icp, ictModel30 ());
  icp.setInputTarget (posed (cloud, pose, unit_scale));
  pcl::PointCloud<pcl::PointNormal> output;
  const auto start = std::chrono::steady_clock::now ();
  icp.align (output);
  const double seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  const auto& report = icp.getRegistrationReport ();
  const auto face = faceDistance (fitInScanFrame (icp, pose, unit_scale));
  // register's checks, on the fit in mm (the fitted vertices and the similarity back from the scan's unit)
  const Eigen::Matrix3d linear = icp.getFinalTransformation ().topLeftCorner<3, 3> ().cast<double> ();
  const morphreg::MorphableModel& model = *icp.getModel ();
  const morphreg::FitPlausibility checks = morphreg::checkFitPlausibility (
      std::cbrt (linear.determinant ()) / unit_scale, icp.getFittedVertices () / unit_scale, icp.getVertexResiduals (),
      icp.getShapeCoefficients ().cwiseQuotient (model.variances (icp.getComponentSelection ()).cwiseSqrt ()), report);
  for (const std::string& failure : checks.failures)
    ADD_FAILURE () << name << " pose " << k << ": " << failure;
  std::printf ("[ real scan ] %s pose %2d: %s in %zu iterations, %.1f s, unit %s, confidence %.2f, %d points on the "
               "head; face median %.3f mm\n",
               name, k, morphreg::toString (report.termination).c_str (), report.history.size (), seconds,
               report.target_unit.c_str (), report.initialisation_confidence, report.head_points, face.median);
  return {face.median, seconds, icp.hasConverged (), report.target_unit};
}

TEST (RealScanPoseTest, Cloud82kFromRandomPoses)
{
  MORPHREG_REQUIRE_REAL_SCANS ();
  const auto cloud = leeScan82k ();
  for (int k = 0; k < poseCount (); ++k) {
    const PoseRun run = runPose (*cloud, k == 0 ? Eigen::Matrix4d::Identity () : randomPose (100 + k), "82k", k);
    EXPECT_LE (run.face_median, 0.85) << "pose " << k;
    EXPECT_TRUE (run.converged) << "pose " << k;
    EXPECT_EQ (run.unit, "mm") << "pose " << k;
  }
}

TEST (RealScanPoseTest, Cloud82kInMetresAndCentimetres)
{
  MORPHREG_REQUIRE_REAL_SCANS ();
  const auto cloud = leeScan82k ();
  for (const auto& unit : {std::make_pair (0.001, "m"), std::make_pair (0.1, "cm")})
    for (int k = 1; k <= sampleCount (6); ++k) {
      const PoseRun run = runPose (*cloud, randomPose (100 + k), unit.second, k, unit.first);
      EXPECT_EQ (run.unit, unit.second) << "pose " << k;
      EXPECT_LE (run.face_median, 0.85) << unit.second << " pose " << k;
      EXPECT_TRUE (run.converged) << unit.second << " pose " << k;
    }
}

TEST (RealScanPoseTest, VertexCloudFromRandomPoses)
{
  MORPHREG_REQUIRE_REAL_SCANS ();
  const auto cloud = leeVertexCloud ();
  for (int k = 0; k < poseCount (); ++k) {
    const PoseRun run = runPose (*cloud, k == 0 ? Eigen::Matrix4d::Identity () : randomPose (100 + k), "8.8k", k);
    EXPECT_LE (run.face_median, 0.85) << "pose " << k;
    EXPECT_TRUE (run.converged) << "pose " << k;
  }
}

} // namespace

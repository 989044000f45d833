// SPDX-License-Identifier: BSD-3-Clause
// Landmark-free registration of the real head-and-shoulders scan from random similarity poses (required: every
// pose succeeds: register's checks pass and the face median is at most 0.85 mm), each scored with its sample count,
// 95th percentile and pose (real_scan_support.h, FaceBounds), against the mean head carried by the fit's similarity.
#include "real_scan_support.h"
#include "support/accuracy_bound.h"
#include "support/sample_count.h"

#include <morphreg/registration/fit_plausibility.h>
#include <morphreg/registration/registration_result_json.h>
#include <morphreg/pipeline/scan_units.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <limits>

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
  FaceScore fit, mean_head; // the fit, and its no-op: the mean head carried by the fit's similarity
  double seconds;
  bool converged;
  std::string unit;
};

/** The worst scores over a test's poses, and the best its no-op reached. */
struct WorstScores
{
  double median = 0.0, percentile75 = 0.0, percentile95 = 0.0, landmarks = 0.0;
  int samples = INT_MAX;
  double mean_head_median = std::numeric_limits<double>::infinity ();

  void
  add (const PoseRun& run)
  {
    median = std::max (median, run.fit.face.median);
    percentile75 = std::max (percentile75, run.fit.percentile75);
    percentile95 = std::max (percentile95, run.fit.face.percentile95);
    landmarks = std::max (landmarks, run.fit.landmark_error);
    samples = std::min (samples, static_cast<int> (run.fit.face.distances.size ()));
    mean_head_median = std::min (mean_head_median, run.mean_head.face.median);
  }

  /** Expects FaceBounds within 1.3x of these figures, and the no-op outside the median's bound. */
  void
  expectTight () const
  {
    std::printf (
        "[ real scan ] worst over the poses: face median %.3f mm, 75th percentile %.3f mm, 95th percentile %.3f "
        "mm, landmarks within %.2f mm, %d face samples; the mean head's best face median %.3f mm\n",
        median, percentile75, percentile95, landmarks, samples, mean_head_median);
    EXPECT_PRED_FORMAT2 (tightUpperBound, median, FaceBounds::kMedian);
    EXPECT_PRED_FORMAT2 (tightUpperBound, percentile75, FaceBounds::kPercentile75);
    EXPECT_PRED_FORMAT2 (tightUpperBound, percentile95, FaceBounds::kPercentile95);
    EXPECT_PRED_FORMAT2 (tightUpperBound, landmarks, FaceBounds::kLandmarks);
    EXPECT_PRED_FORMAT2 (noOpFailsUpperBound, mean_head_median, FaceBounds::kMedian);
  }
};

/** Registers \a cloud under \a pose, written in a unit \a unit_scale times the mm (brought to mm by
 *  convertScanToMillimetres' guess, as `morphreg register` does), and scores the fit in the scan's original frame. */
PoseRun
runPose (const pcl::PointCloud<pcl::PointNormal>& cloud, const Eigen::Matrix4d& pose, const char* name, int k,
         double unit_scale = 1.0)
{
  Icp icp;
  configureIctIcp (icp, ictModel30 ());
  const auto target = posed (cloud, pose, unit_scale);
  const morphreg::LengthUnitGuess unit = morphreg::convertScanToMillimetres (*target, "auto", *ictModel30 (), name);
  const double fit_scale = unit_scale * unit.scale_to_mm; // the fit's frame over the mm of the posed scan
  icp.setInputTarget (target);
  pcl::PointCloud<pcl::PointNormal> output;
  const auto start = std::chrono::steady_clock::now ();
  icp.align (output);
  const double seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  const auto& report = icp.getRegistrationReport ();
  const FaceScore face = faceScore (fitInScanFrame (icp, pose, fit_scale));
  const FaceScore mean_head = faceScore (meanInScanFrame (icp, pose, fit_scale));
  // register's checks, on the fit in mm
  const morphreg::FitPlausibility checks = morphreg::checkRegistration (icp, *icp.getModel ());
  for (const std::string& failure : checks.failures)
    ADD_FAILURE () << name << " pose " << k << ": " << failure;
  std::printf (
      "[ real scan ] %s pose %2d: %s in %zu iterations, %.1f s, unit %s, confidence %.2f, %d points on the "
      "head; face median %.3f mm, 75th percentile %.3f mm, 95th %.3f mm over %zu samples, landmarks within %.2f "
      "mm; the mean head %.3f mm\n",
      name, k, morphreg::toString (report.termination).c_str (), report.history.size (), seconds,
      morphreg::toString (unit.unit).c_str (), report.initialisation_confidence, report.head_points, face.face.median,
      face.percentile75, face.face.percentile95, face.face.distances.size (), face.landmark_error,
      mean_head.face.median);
  expectFaceScore (face, std::string (name) + " pose " + std::to_string (k));
  return {face, mean_head, seconds, icp.hasConverged (), morphreg::toString (unit.unit)};
}

TEST (RealScanPoseTest, Cloud82kFromRandomPoses)
{
  MORPHREG_REQUIRE_REAL_SCANS ();
  const auto cloud = leeScan82k ();
  WorstScores worst;
  for (int k = 0; k < poseCount (); ++k) {
    const PoseRun run = runPose (*cloud, k == 0 ? Eigen::Matrix4d::Identity () : randomPose (100 + k), "82k", k);
    EXPECT_TRUE (run.converged) << "pose " << k;
    EXPECT_EQ (run.unit, "mm") << "pose " << k;
    worst.add (run);
  }
  worst.expectTight ();
}

TEST (RealScanPoseTest, Cloud82kInMetresAndCentimetres)
{
  MORPHREG_REQUIRE_REAL_SCANS ();
  const auto cloud = leeScan82k ();
  WorstScores worst;
  for (const auto& unit : {std::make_pair (0.001, "m"), std::make_pair (0.1, "cm")})
    for (int k = 1; k <= sampleCount (6); ++k) {
      const PoseRun run = runPose (*cloud, randomPose (100 + k), unit.second, k, unit.first);
      EXPECT_EQ (run.unit, unit.second) << "pose " << k;
      EXPECT_TRUE (run.converged) << unit.second << " pose " << k;
      worst.add (run);
    }
  worst.expectTight ();
}

TEST (RealScanPoseTest, VertexCloudFromRandomPoses)
{
  MORPHREG_REQUIRE_REAL_SCANS ();
  const auto cloud = leeVertexCloud ();
  WorstScores worst;
  for (int k = 0; k < poseCount (); ++k) {
    const PoseRun run = runPose (*cloud, k == 0 ? Eigen::Matrix4d::Identity () : randomPose (100 + k), "8.8k", k);
    EXPECT_TRUE (run.converged) << "pose " << k;
    worst.add (run);
  }
  worst.expectTight ();
}

} // namespace

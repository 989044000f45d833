// SPDX-License-Identifier: BSD-3-Clause
// MorphableICP with the ICT-FaceKit model under the scan protocol of scan_protocol.h: 20 heads with fixed seeds,
// scans with a random similarity, holes, noise, outliers and noisy landmarks; error = vertex RMS against the posed
// truth.
// The protocol's holes (crown cap at +Y, under the chin at +Z) fit the ICT frame (+Y up, +Z out of the face).
// 60 registrations: about 2 minutes of CPU time.
#include "scan_protocol.h"
#include "support/sample_count.h"
#include "ict_data.h"

#include <morphreg/common/order_statistics.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/registration/surface_distance.h>

#include "support/accuracy_bound.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <random>
#include <vector>

namespace
{
using morphreg::MorphableModel;
using Icp = morphreg::MorphableICP<pcl::PointNormal>;

constexpr int kHeads = 20;
constexpr int kFittedComponents = 30;
constexpr std::uint64_t kCoefficientSeed = 2024;
constexpr std::uint64_t kScanSeed = 9000;
/** lambda_2 for ICT's 30 global components (the library default, 3, suits the built-in population's 7 x 10 regional
 *  ones and is too weak here): against heads with all 100 components, components 31-100 are structured noise that
 *  the 30 fitted ones partly absorb, mostly in the scan's holes (head 7: 3.6 mm on the hole vertices, 2.2 mm on the
 *  covered ones); a stronger prior keeps them out. With lambda_2 = 3: head 7 at 2.06x its floor, 19/20 heads within
 *  2x, median 1.81 mm; the heads drawn within the 30 components stay within 1 mm either way.
 */
constexpr double kShapePrior = 5.0;

/** Landmarks of the start (ids of docs/landmarks.md the ICT model has), spread over the face and both ears. */
morphreg::LandmarkVertices
startLandmarks (const MorphableModel& model)
{
  morphreg::LandmarkVertices chosen;
  for (const char* name : {"nasion", "nose_tip", "left_tragus", "right_tragus", "chin", "left_mouth_corner",
                           "right_mouth_corner", "left_eye_outer", "right_eye_outer"})
    chosen[name] = model.landmarkVertex (name);
  return chosen;
}

/** Scale of the similarity \a pose (head -> scan). */
double
poseScale (const Eigen::Matrix4d& pose)
{
  return std::cbrt (pose.topLeftCorner<3, 3> ().determinant ());
}

struct Fit
{
  double rms = 0.0;
  size_t iterations = 0;
  double seconds = 0.0;
  std::string outcome; ///< termination and, if any, the report's message
};

/** Registers the first kFittedComponents components of the ICT model to \a scan (landmark or coarse start). */
Fit
fitScan (const morphreg::test::ProtocolScan& scan, bool landmark_start)
{
  const MorphableModel& model = *morphreg::test::ictModel ();
  Icp icp;
  icp.setModel (morphreg::test::ictModel ());
  icp.setComponentSelection (model.firstComponents (kFittedComponents));
  icp.setPointToPlane (true);
  icp.setMaximumIterations (50);
  icp.setSimilarityIterations (20);
  icp.setShapePriorWeight (kShapePrior);
  if (landmark_start)
    icp.setTargetLandmarks (scan.landmarks, 1.0);
  else
    icp.setInitialAlignment (morphreg::makeInitialAlignment ("coarse"));
  icp.setInputTarget (scan.cloud);
  pcl::PointCloud<pcl::PointNormal> output;
  icp.align (output);
  const auto& report = icp.getRegistrationReport ();
  Fit fit{morphreg::test::vertexRms (icp.getFittedVertices (), scan.truth), report.history.size (), 0.0,
          morphreg::toString (report.termination)};
  for (const auto& iteration : report.history)
    fit.seconds += iteration.seconds;
  if (!report.message.empty ())
    fit.outcome += " (" + report.message + ")";
  return fit;
}

double
median (const std::vector<double>& values)
{
  return morphreg::percentile (values, 0.5);
}

/** How many of \a values are at most \a limit. */
long
countAtMost (const std::vector<double>& values, double limit)
{
  return std::count_if (values.begin (), values.end (), [limit] (double v) { return v <= limit; });
}

TEST (IctIcpTest, HeadsWithinTheFittedComponentsFitFromLandmarkAndCoarseStarts)
{
  MORPHREG_REQUIRE_ICT ();
  const MorphableModel& model = *morphreg::test::ictModel ();
  const morphreg::ComponentSelection selection = model.firstComponents (kFittedComponents);
  std::mt19937_64 rng (kCoefficientSeed);
  std::vector<double> landmark_rms, coarse_rms;
  for (int head = 0; head < morphreg::test::sampleCount (kHeads); ++head) {
    const morphreg::TriangleMesh mesh = model.generateMesh (model.sampleCoefficients (rng, selection), selection);
    const auto scan = morphreg::test::simulateProtocolScan (mesh, startLandmarks (model), kScanSeed + head);
    for (const bool landmark_start : {true, false}) {
      const Fit fit = fitScan (scan, landmark_start);
      std::printf ("[ ICT within 30 ] head %2d %-8s start: RMS %.3f mm, %2zu iterations, %.1f s, %s\n", head,
                   landmark_start ? "landmark" : "coarse", fit.rms, fit.iterations, fit.seconds, fit.outcome.c_str ());
      (landmark_start ? landmark_rms : coarse_rms).push_back (fit.rms);
      EXPECT_LE (fit.iterations, 50u);
    }
  }
  const double worst_landmark = *std::max_element (landmark_rms.begin (), landmark_rms.end ());
  const double worst_coarse = *std::max_element (coarse_rms.begin (), coarse_rms.end ());
  std::printf ("[ ICT within 30 ] landmark start: median %.3f, worst %.3f mm, %ld/%zu <= 1 mm; coarse start: median "
               "%.3f, worst %.3f mm, %ld/%zu <= 1 mm\n",
               median (landmark_rms), worst_landmark, countAtMost (landmark_rms, 1.0), landmark_rms.size (),
               median (coarse_rms), worst_coarse, countAtMost (coarse_rms, 1.0), coarse_rms.size ());
  // Required: <= 0.85 mm on every head from both starts. At these settings the landmark start fits 20/20 heads
  // (median 0.520 mm, worst 0.674 mm), the coarse start (robustCoarseSimilarity) 20/20 (median 0.524 mm, worst
  // 0.682 mm), in at most 50 iterations.
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, worst_landmark, 0.85)
      << "landmark start: every head must fit within 0.85 mm";
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, worst_coarse, 0.85)
      << "coarse start: every head must fit within 0.85 mm";
}

TEST (IctIcpTest, HeadsWithAllComponentsFitWithin30ComponentsCloseToTheirFloor)
{
  MORPHREG_REQUIRE_ICT ();
  const MorphableModel& model = *morphreg::test::ictModel ();
  const morphreg::ComponentSelection all = model.allComponents ();
  const morphreg::ComponentSelection fitted = model.firstComponents (kFittedComponents);
  std::mt19937_64 rng (kCoefficientSeed + 1);
  std::vector<double> rms, ratio, floors;
  for (int head = 0; head < morphreg::test::sampleCount (kHeads); ++head) {
    const Eigen::VectorXd truth = model.sampleCoefficients (rng, all);
    const morphreg::TriangleMesh mesh = model.generateMesh (truth, all);
    const auto scan = morphreg::test::simulateProtocolScan (mesh, startLandmarks (model), kScanSeed + 100 + head);
    // The floor: what components 31-100 add to the head, in the scan's frame (scaled like the head).
    const Eigen::VectorXd head30 = truth.head (kFittedComponents);
    const double floor =
        poseScale (scan.pose) * morphreg::test::vertexRms (mesh.vertices, model.generateMesh (head30, fitted).vertices);
    const Fit fit = fitScan (scan, true);
    std::printf ("[ ICT all 100 ] head %2d: RMS %.3f mm, floor %.3f mm (%.2fx), %2zu iterations, %.1f s, %s\n", head,
                 fit.rms, floor, fit.rms / floor, fit.iterations, fit.seconds, fit.outcome.c_str ());
    rms.push_back (fit.rms);
    floors.push_back (floor);
    ratio.push_back (fit.rms / floor);
  }
  const double worst_ratio = *std::max_element (ratio.begin (), ratio.end ());
  std::printf ("[ ICT all 100 ] median RMS %.3f mm (floor median %.3f mm), worst ratio to floor %.2f, %ld/%zu <= 2x\n",
               median (rms), median (floors), worst_ratio, countAtMost (ratio, 2.0), ratio.size ());
  // Required: median <= 2.0 mm and every head <= 2x its floor. At these settings: median 1.78 mm (floors' median
  // 1.27 mm), 20/20 heads at 1.18-1.91x (head 7: 2.31 mm, floor 1.21 mm), 18-44 iterations.
  EXPECT_PRED_FORMAT2 (morphreg::test::suiteMedianUpperBound, median (rms), 2.0);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, worst_ratio, 2.0) << "every head must fit within 2x its floor";
}

// The no-op of the suite: the mean head at each head's true pose, scored like the fits of all 100 components.
TEST (IctIcpTest, TheMeanHeadFailsTheBoundsOfTheFits)
{
  MORPHREG_REQUIRE_ICT ();
  const MorphableModel& model = *morphreg::test::ictModel ();
  const morphreg::ComponentSelection all = model.allComponents ();
  const Eigen::Map<const Eigen::Matrix3Xd> mean (model.mean ().data (), 3, model.numVertices ());
  std::mt19937_64 rng (kCoefficientSeed + 1);
  std::vector<double> rms;
  for (int head = 0; head < morphreg::test::sampleCount (kHeads); ++head) {
    const morphreg::TriangleMesh mesh = model.generateMesh (model.sampleCoefficients (rng, all), all);
    const auto scan = morphreg::test::simulateProtocolScan (mesh, startLandmarks (model), kScanSeed + 100 + head);
    const Eigen::Matrix3Xd posed =
        (scan.pose.topLeftCorner<3, 3> () * mean).colwise () + scan.pose.topRightCorner<3, 1> ();
    rms.push_back (morphreg::test::vertexRms (posed, scan.truth));
  }
  std::printf ("[ ICT no-op ] the mean head at the true pose: median RMS %.3f mm (the fits' bound 2.0)\n",
               median (rms));
  EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, median (rms), 2.0);
}

} // namespace

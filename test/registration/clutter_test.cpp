// SPDX-License-Identifier: BSD-3-Clause
// The global start and MorphableICP on scans that hold what real scans carry beyond the head: shoulders and torso,
// a chair back, hair-like noise on the crown, no normals, any rotation. 20 heads of the built-in population.
#include "scan_protocol.h"
#include "support/sample_count.h"

#include <morphreg/model/model_builder.h>
#include <morphreg/registration/global_alignment.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/mesh/surface_sampling.h>

#include "support/accuracy_bound.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace
{
using morphreg::MorphableModel;
using morphreg::TriangleMesh;
using Icp = morphreg::MorphableICP<pcl::PointNormal>;
constexpr double kWorstBound = 1.1; ///< mm, the vertex RMS every head must reach

/** Points spread over the torso below the neck: an elliptic cylinder 380 x 220 mm, 250 mm high, with the shoulders'
 *  top as a flat ring from the neck outwards; about one point per \a area mm^2. */
void
addTorso (const TriangleMesh& head, double area, std::mt19937_64& random, std::vector<Eigen::Vector3d>& points)
{
  std::uniform_real_distribution<double> unit (0.0, 1.0);
  const double bottom = head.vertices.row (1).minCoeff ();
  const double a = 190.0, b = 110.0, height = 250.0, top = bottom + 10.0;
  const int side = static_cast<int> (M_PI * (a + b) * height / area);
  for (int k = 0; k < side; ++k) {
    const double angle = 2.0 * M_PI * unit (random);
    points.emplace_back (a * std::cos (angle), top - height * unit (random), b * std::sin (angle) - 20.0);
  }
  const int ring = static_cast<int> (M_PI * a * b * 0.8 / area);
  for (int k = 0; k < ring; ++k) {
    const double angle = 2.0 * M_PI * unit (random), r = std::sqrt (0.12 + 0.88 * unit (random));
    points.emplace_back (a * r * std::cos (angle), top, b * r * std::sin (angle) - 20.0);
  }
}

/** A chair back: a 500 x 400 mm plane 80 mm behind the head. */
void
addChairBack (const TriangleMesh& head, double area, std::mt19937_64& random, std::vector<Eigen::Vector3d>& points)
{
  std::uniform_real_distribution<double> unit (0.0, 1.0);
  const double back = head.vertices.row (2).minCoeff () - 80.0, bottom = head.vertices.row (1).minCoeff ();
  for (int k = 0; k < static_cast<int> (500.0 * 400.0 / area); ++k)
    points.emplace_back (-250.0 + 500.0 * unit (random), bottom - 200.0 + 400.0 * unit (random), back);
}

/** Hair-like noise: points up to 30 mm above the top 50 mm of the head. */
void
addHair (const Eigen::Matrix3Xd& head_points, std::mt19937_64& random, std::vector<Eigen::Vector3d>& points)
{
  std::uniform_real_distribution<double> unit (0.0, 1.0);
  const double top = head_points.row (1).maxCoeff ();
  for (Eigen::Index i = 0; i < head_points.cols (); ++i)
    if (head_points (1, i) > top - 50.0 && unit (random) < 0.3) {
      const Eigen::Vector3d outward = (head_points.col (i) - Eigen::Vector3d (0.0, top - 90.0, 0.0)).normalized ();
      points.push_back (head_points.col (i) + 30.0 * unit (random) * outward +
                        2.0 * Eigen::Vector3d (unit (random) - 0.5, unit (random) - 0.5, unit (random) - 0.5));
    }
}

struct ClutteredScan
{
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud; ///< no normals (NaN): they are estimated
  Eigen::Matrix4d pose;                         ///< head frame -> scan frame
  size_t head_points;
};

ClutteredScan
clutteredScan (const TriangleMesh& head, std::uint64_t seed)
{
  std::mt19937_64 random (seed);
  const double area = 6.0; // mm^2 per point
  const Eigen::Matrix3Xd head_points = morphreg::sampleSurfaceUniformly (head, area, seed).points;
  std::vector<Eigen::Vector3d> points;
  for (Eigen::Index i = 0; i < head_points.cols (); ++i)
    points.push_back (head_points.col (i));
  addTorso (head, area, random, points);
  addChairBack (head, 3.0 * area, random, points);
  addHair (head_points, random, points);

  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> unit (0.0, 1.0);
  const Eigen::Quaterniond rotation =
      Eigen::Quaterniond (normal (random), normal (random), normal (random), normal (random)).normalized ();
  Eigen::Matrix4d pose = Eigen::Matrix4d::Identity ();
  pose.topLeftCorner<3, 3> () = (0.9 + 0.2 * unit (random)) * rotation.toRotationMatrix ();
  pose.topRightCorner<3, 1> () =
      500.0 * Eigen::Vector3d (unit (random) - 0.5, unit (random) - 0.5, unit (random) - 0.5);
  ClutteredScan scan{pcl::PointCloud<pcl::PointNormal>::Ptr (new pcl::PointCloud<pcl::PointNormal>), pose,
                     static_cast<size_t> (head_points.cols ())};
  for (const Eigen::Vector3d& p : points) {
    pcl::PointNormal point;
    const Eigen::Vector3d noisy = p + 0.3 * Eigen::Vector3d (normal (random), normal (random), normal (random));
    point.getVector3fMap () = (pose.topLeftCorner<3, 3> () * noisy + pose.topRightCorner<3, 1> ()).cast<float> ();
    point.getNormalVector3fMap () = Eigen::Vector3f::Constant (std::nanf (""));
    scan.cloud->push_back (point);
  }
  return scan;
}

TEST (ClutterTest, EveryHeadOfTwentyFitsThroughShouldersChairAndHair)
{
  morphreg::synthetic::HeadGenerator generator;
  std::vector<TriangleMesh> meshes;
  for (auto& head : generator.population (100, 1000))
    meshes.push_back (std::move (head.mesh));
  morphreg::ModelBuilderSettings settings;
  settings.max_components = 10;
  const MorphableModel::ConstPtr model = morphreg::ModelBuilder (settings).build (meshes, generator.regions ());
  std::mt19937_64 rng (3);
  int failures = 0;
  double worst = 0.0;
  std::vector<double> no_op; // the mean head at the true pose
  for (int head = 0; head < morphreg::test::sampleCount (20); ++head) {
    const Eigen::VectorXd truth_m = model->sampleCoefficients (rng, model->firstComponents (10));
    const TriangleMesh truth = model->generateMesh (truth_m, model->firstComponents (10));
    const ClutteredScan scan = clutteredScan (truth, 700 + head);
    Icp icp;
    icp.setModel (model);
    icp.setMaximumIterations (50);
    icp.setSimilarityIterations (20);
    icp.setPointToPlane (true);
    icp.setInputTarget (scan.cloud);
    pcl::PointCloud<pcl::PointNormal> output;
    icp.align (output);
    const Eigen::Matrix3Xd posed_truth =
        (scan.pose.topLeftCorner<3, 3> () * truth.vertices).colwise () + scan.pose.topRightCorner<3, 1> ();
    const double scale = std::cbrt (scan.pose.topLeftCorner<3, 3> ().determinant ());
    const double rms = morphreg::test::vertexRms (icp.getFittedVertices (), posed_truth) / scale;
    const auto& report = icp.getRegistrationReport ();
    std::printf ("[ clutter ] head %2d: %zu points (%zu on the head), confidence %.2f, %d found on the head; vertex "
                 "RMS %.3f mm, %s\n",
                 head, scan.cloud->size (), scan.head_points, report.initialisation_confidence, report.head_points, rms,
                 morphreg::toString (report.termination).c_str ());
    std::printf ("  %s\n", report.initialisation_detail.c_str ());

    failures += rms > kWorstBound ? 1 : 0;
    worst = std::max (worst, rms);
    const Eigen::Map<const Eigen::Matrix3Xd> mean (model->mean ().data (), 3, model->numVertices ());
    const Eigen::Matrix3Xd posed_mean =
        (scan.pose.topLeftCorner<3, 3> () * mean).colwise () + scan.pose.topRightCorner<3, 1> ();
    no_op.push_back (morphreg::test::vertexRms (posed_mean, posed_truth) / scale);
  }
  EXPECT_EQ (failures, 0);
  // Measured: the worst head 0.863 mm; the no-op (the mean head at the true pose) lies a median of 3.41 mm off.
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, worst, kWorstBound);
  std::nth_element (no_op.begin (), no_op.begin () + no_op.size () / 2, no_op.end ());
  std::printf ("[ clutter no-op ] the mean head at the true pose: median vertex RMS %.3f mm\n",
               no_op[no_op.size () / 2]);
  EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, no_op[no_op.size () / 2], kWorstBound);
}

} // namespace

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/scan_simulator.h>

#include <pcl/conversions.h>
#include <pcl/kdtree/kdtree_flann.h>

#include "support/accuracy_bound.h"
#include "support/synthetic_heads.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

using morphreg::synthetic::HeadGenerator;
using morphreg::synthetic::HeadRegion;
using morphreg::synthetic::ScanSimulator;
using morphreg::synthetic::SimulatedScan;

namespace
{
const morphreg::synthetic::HeadGenerator&
generator ()
{
  return morphreg::test::headGenerator ();
}

const morphreg::TriangleMesh&
head ()
{
  static const morphreg::TriangleMesh mesh = generator ().sample (21).mesh;
  return mesh;
}

/** The noise-free head point a scan point came from. */
Eigen::Vector3d
truePoint (const SimulatedScan& scan, std::size_t i)
{
  Eigen::Vector3d p = Eigen::Vector3d::Zero ();
  for (int k = 0; k < 3; ++k)
    p += scan.barycentric (k, i) * head ().vertices.col (head ().triangles (k, scan.source_triangle[i]));
  return p;
}

/** Fraction of the vertices selected by \a select with no noise-free scan point within 3 mm. */
double
missedFraction (const SimulatedScan& scan, const std::function<bool (int)>& select)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr truth (new pcl::PointCloud<pcl::PointXYZ>);
  for (std::size_t i = 0; i < scan.source_triangle.size (); ++i)
    if (scan.source_triangle[i] >= 0) {
      pcl::PointXYZ p;
      p.getVector3fMap () = truePoint (scan, i).cast<float> ();
      truth->push_back (p);
    }
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud (truth);
  int selected = 0, missed = 0;
  std::vector<int> index (1);
  std::vector<float> squared_distance (1);
  for (int v = 0; v < head ().numVertices (); ++v)
    if (select (v)) {
      ++selected;
      pcl::PointXYZ query;
      query.getVector3fMap () = head ().vertices.col (v).cast<float> ();
      tree.nearestKSearch (query, 1, index, squared_distance);
      missed += squared_distance[0] > 9.0f ? 1 : 0;
    }
  EXPECT_GT (selected, 5) << "the test selected too few vertices";
  return selected ? static_cast<double> (missed) / selected : 0.0;
}
} // namespace

TEST (ScanSimulatorTest, DefaultScanIsDenseAndDeterministic)
{
  const ScanSimulator scanner;
  const SimulatedScan a = scanner.scan (head (), 3);
  const SimulatedScan b = scanner.scan (head (), 3);
  EXPECT_GE (a.cloud->size (), 30000u);
  EXPECT_LE (a.cloud->size (), 100000u);
  ASSERT_EQ (a.cloud->size (), b.cloud->size ());
  for (std::size_t i = 0; i < a.cloud->size (); i += 97)
    EXPECT_EQ ((*a.cloud)[i].getVector3fMap (), (*b.cloud)[i].getVector3fMap ());
  EXPECT_TRUE (a.head_to_scan.isApprox (b.head_to_scan));
  EXPECT_FALSE (a.head_to_scan.isApprox (scanner.scan (head (), 4).head_to_scan));
  EXPECT_EQ (a.source_triangle.size (), a.cloud->size ());
  EXPECT_EQ (static_cast<std::size_t> (a.barycentric.cols ()), a.cloud->size ());
}

TEST (ScanSimulatorTest, GroundTruthMapsEveryPointToItsHeadTriangle)
{
  ScanSimulator::Parameters parameters;
  parameters.noise_sigma = 0.0;
  const SimulatedScan scan = ScanSimulator (parameters).scan (head (), 9);
  double worst = 0.0;
  int facing = 0;
  const Eigen::Matrix3d rotation = scan.head_to_scan.linear () / scan.scale;
  const Eigen::Matrix3Xd face_normals = morphreg::faceNormals (head ());
  for (std::size_t i = 0; i < scan.cloud->size () - scan.num_outliers; ++i) {
    ASSERT_GE (scan.source_triangle[i], 0);
    EXPECT_NEAR (scan.barycentric.col (i).sum (), 1.0, 1e-9);
    EXPECT_GE (scan.barycentric.col (i).minCoeff (), -1e-9);
    const Eigen::Vector3d expected = scan.head_to_scan * truePoint (scan, i);
    worst = std::max (worst, (expected - (*scan.cloud)[i].getVector3fMap ().cast<double> ()).norm ());
    const Eigen::Vector3d normal = (*scan.cloud)[i].getNormalVector3fMap ().cast<double> ();
    facing += normal.dot (rotation * face_normals.col (scan.source_triangle[i])) > 0.8 ? 1 : 0;
  }
  EXPECT_LT (worst, 1e-3) << "mm";
  EXPECT_GT (facing, 0.99 * (scan.cloud->size () - scan.num_outliers)) << "normals agree with their surface";
}

TEST (ScanSimulatorTest, NoiseAndOutliersMatchTheConfiguration)
{
  ScanSimulator::Parameters parameters;
  parameters.noise_sigma = 0.5;
  parameters.outlier_fraction = 0.05;
  const SimulatedScan scan = ScanSimulator (parameters).scan (head (), 5);
  const std::size_t inliers = scan.cloud->size () - scan.num_outliers;
  EXPECT_NEAR (static_cast<double> (scan.num_outliers) / scan.cloud->size (), 0.05, 1e-3);
  const Eigen::Affine3d scan_to_head = scan.head_to_scan.inverse ();
  double sum_sq = 0.0;
  for (std::size_t i = 0; i < inliers; ++i) {
    const Eigen::Vector3d measured = scan_to_head * (*scan.cloud)[i].getVector3fMap ().cast<double> ();
    sum_sq += (measured - truePoint (scan, i)).squaredNorm ();
  }
  EXPECT_NEAR (std::sqrt (sum_sq / inliers), 0.5, 0.025) << "RMS range error is the configured sigma (mm)";
  // Outliers are flagged with triangle -1, lie in the grown bounding box and are mostly far from the head.
  Eigen::Vector3f low = Eigen::Vector3f::Constant (1e9), high = -low;
  for (std::size_t i = 0; i < inliers; ++i) {
    low = low.cwiseMin ((*scan.cloud)[i].getVector3fMap ());
    high = high.cwiseMax ((*scan.cloud)[i].getVector3fMap ());
  }
  const Eigen::Vector3f margin = 0.1f * (high - low) + Eigen::Vector3f::Constant (1e-3f);
  for (std::size_t i = inliers; i < scan.cloud->size (); ++i) {
    EXPECT_EQ (scan.source_triangle[i], -1);
    const Eigen::Vector3f p = (*scan.cloud)[i].getVector3fMap ();
    EXPECT_TRUE ((p.array () >= (low - margin).array ()).all () && (p.array () <= (high + margin).array ()).all ());
  }
}

TEST (ScanSimulatorTest, PoseIsARandomSimilarityWithinLimits)
{
  ScanSimulator::Parameters parameters;
  parameters.max_rotation_deg = 30.0;
  parameters.max_scale_deviation = 0.1;
  parameters.max_translation = 50.0;
  const ScanSimulator scanner (parameters);
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    const SimulatedScan scan = scanner.scan (head (), seed);
    const Eigen::Matrix3d rotation = scan.head_to_scan.linear () / scan.scale;
    EXPECT_TRUE ((rotation.transpose () * rotation).isIdentity (1e-9));
    EXPECT_NEAR (rotation.determinant (), 1.0, 1e-9);
    EXPECT_LE (Eigen::AngleAxisd (rotation).angle (), 30.0 * M_PI / 180.0 + 1e-9);
    EXPECT_LE (std::abs (scan.scale - 1.0), 0.1 + 1e-12);
    EXPECT_LE (scan.head_to_scan.translation ().norm (), 50.0 + 1e-9);
  }
  parameters.max_rotation_deg = parameters.max_scale_deviation = parameters.max_translation = 0.0;
  EXPECT_TRUE (ScanSimulator (parameters).scan (head (), 1).head_to_scan.isApprox (Eigen::Affine3d::Identity ()));
}

TEST (ScanSimulatorTest, HolesWhereScannersMiss)
{
  ScanSimulator::Parameters parameters;
  parameters.outlier_fraction = 0.0;
  const SimulatedScan scan = ScanSimulator (parameters).scan (head (), 2);
  const Eigen::Matrix3Xd normals = morphreg::vertexNormals (head ());
  const auto& regions = generator ().regionLabels ();
  const double top = head ().vertices.row (1).maxCoeff ();
  const double crown = missedFraction (scan, [&] (int v) { return head ().vertices (1, v) > top - 5.0; });
  const double under_chin =
      missedFraction (scan, [&] (int v) { return regions[v] == HeadRegion::chin && normals (1, v) < -0.8; });
  const double nostrils =
      missedFraction (scan, [&] (int v) { return regions[v] == HeadRegion::nose && normals (1, v) < -0.75; });
  const double under_ears =
      missedFraction (scan, [&] (int v) { return regions[v] == HeadRegion::ears && normals (1, v) < -0.6; });
  const double face = missedFraction (scan, [&] (int v) { return regions[v] == HeadRegion::cheeks; });
  std::cout << "missed: crown " << crown << ", under chin " << under_chin << ", nostrils " << nostrils
            << ", ear undersides " << under_ears << ", cheeks " << face << '\n';
  // Measured: crown 1, under the chin 1, nostrils 0.833, ear undersides 0.727, cheeks 0.
  EXPECT_PRED_FORMAT2 (morphreg::test::tightLowerBound, crown, 1.0);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightLowerBound, under_chin, 1.0);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightLowerBound, nostrils, 0.8);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightLowerBound, under_ears, 0.67);
  EXPECT_LT (face, 0.05) << "the cheeks face the scanner (none missed: no ratio applies to 0)";
}

TEST (ScanSimulatorTest, RangeMeshConnectsNeighbouringReturns)
{
  ScanSimulator::Parameters parameters;
  parameters.range_mesh = true;
  const SimulatedScan scan = ScanSimulator (parameters).scan (head (), 8);
  ASSERT_GT (scan.range_mesh.polygons.size (), scan.cloud->size ());
  pcl::PointCloud<pcl::PointNormal> vertices;
  pcl::fromPCLPointCloud2 (scan.range_mesh.cloud, vertices);
  ASSERT_EQ (vertices.size (), scan.cloud->size ());
  const int inliers = static_cast<int> (scan.cloud->size ()) - scan.num_outliers;
  int outward = 0;
  for (const auto& polygon : scan.range_mesh.polygons) {
    ASSERT_EQ (polygon.vertices.size (), 3u);
    for (auto v : polygon.vertices)
      ASSERT_LT (static_cast<int> (v), inliers) << "outliers are not connected";
    const Eigen::Vector3f a = vertices[polygon.vertices[0]].getVector3fMap ();
    const Eigen::Vector3f b = vertices[polygon.vertices[1]].getVector3fMap ();
    const Eigen::Vector3f c = vertices[polygon.vertices[2]].getVector3fMap ();
    outward += (b - a).cross (c - a).dot (vertices[polygon.vertices[0]].getNormalVector3fMap ()) > 0.0f ? 1 : 0;
  }
  EXPECT_GT (outward, 0.95 * scan.range_mesh.polygons.size ()) << "triangles face outward";
}

TEST (ScanSimulatorTest, BadInputIsRejectedWithItsName)
{
  ScanSimulator::Parameters parameters;
  parameters.noise_sigma = -1.0;
  try {
    ScanSimulator scanner (parameters);
    FAIL () << "negative noise accepted";
  }
  catch (const morphreg::InvalidInputError& e) {
    EXPECT_NE (std::string (e.what ()).find ("scanner setting noise = -1"), std::string::npos) << e.what ();
  }
  parameters = ScanSimulator::Parameters ();
  parameters.outlier_fraction = 0.9;
  EXPECT_THROW (ScanSimulator{parameters}, morphreg::InvalidInputError);
  parameters = ScanSimulator::Parameters ();
  parameters.max_incidence_deg = 90.0;
  EXPECT_THROW (ScanSimulator{parameters}, morphreg::InvalidInputError);

  const ScanSimulator scanner;
  EXPECT_THROW (scanner.scan (morphreg::TriangleMesh (), 1), morphreg::InvalidInputError);
  morphreg::TriangleMesh broken = head ();
  broken.vertices (0, 10) = std::nan ("");
  EXPECT_THROW (scanner.scan (broken, 1), morphreg::InvalidInputError);
  morphreg::TriangleMesh flat = head ();
  flat.vertices.row (1).setZero (); // squashed to a plane: no horizontal ray meets it
  EXPECT_THROW (scanner.scan (flat, 1), morphreg::InvalidInputError);
}

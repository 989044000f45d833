// SPDX-License-Identifier: BSD-3-Clause
// The PCL side of ThinPlateSpline: fits from clouds and correspondences, warping clouds and polygon meshes.
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/warp/thin_plate_spline.h>

#include "support/test_meshes.h"
#include "tps_test_support.h"

#include <pcl/conversions.h>

#include <Eigen/LU>
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

using morphreg::InvalidInputError;
using morphreg::ThinPlateSpline;
using morphreg::test::bend;
using morphreg::test::extent;
using morphreg::test::maxColumnDistance;
using morphreg::test::randomLandmarks;

namespace
{
template <typename PointT>
pcl::PointCloud<PointT>
toCloud (const Eigen::Matrix3Xd& points)
{
  pcl::PointCloud<PointT> cloud;
  cloud.resize (points.cols ());
  for (Eigen::Index j = 0; j < points.cols (); ++j)
    cloud[j].getVector3fMap () = points.col (j).cast<float> ();
  return cloud;
}

const Eigen::Matrix3d kLinear = (Eigen::Matrix3d () << 1.2, 0.1, 0.0, -0.1, 0.8, 0.2, 0.0, 0.3, 1.1).finished ();
const Eigen::Vector3d kShift (5.0, -3.0, 10.0);

/** A spline that is exactly the affine map kLinear x + kShift. */
ThinPlateSpline<double, 3>
affineSpline ()
{
  const Eigen::Matrix3Xd source = randomLandmarks (12, 21);
  ThinPlateSpline<double, 3> tps;
  tps.fit (source, (kLinear * source).colwise () + kShift);
  return tps;
}
} // namespace

TEST (TpsTest, FitsFromCloudsAndFromCorrespondences)
{
  // Float clouds: compare with the matrix fit of the same float-rounded coordinates.
  const Eigen::Matrix3Xd source = randomLandmarks (40, 22).cast<float> ().cast<double> ();
  const Eigen::Matrix3Xd target = bend<3> (source).cast<float> ().cast<double> ();
  ThinPlateSpline<double, 3> reference;
  reference.fit (source, target);
  const Eigen::Matrix3Xd queries = randomLandmarks (100, 23);

  const auto source_cloud = toCloud<pcl::PointXYZ> (source);
  const auto target_cloud = toCloud<pcl::PointXYZ> (target);
  ThinPlateSpline<double, 3> from_clouds;
  from_clouds.fit (source_cloud, target_cloud);
  EXPECT_LE (maxColumnDistance (from_clouds.evaluate (queries), reference.evaluate (queries)), 1e-9);

  // The target cloud in reverse order with one extra point, paired by correspondences.
  pcl::PointCloud<pcl::PointXYZ> shuffled;
  for (int j = 39; j >= 0; --j)
    shuffled.push_back (target_cloud[j]);
  shuffled.push_back (pcl::PointXYZ (1e4f, 1e4f, 1e4f));
  pcl::Correspondences correspondences;
  for (int j = 0; j < 40; ++j)
    correspondences.emplace_back (j, 39 - j, 0.0f);
  ThinPlateSpline<double, 3> from_correspondences;
  from_correspondences.fit (source_cloud, shuffled, correspondences);
  EXPECT_LE (maxColumnDistance (from_correspondences.evaluate (queries), reference.evaluate (queries)), 1e-9);

  EXPECT_THROW (from_clouds.fit (source_cloud, shuffled), InvalidInputError); // 40 vs 41 points
  correspondences[3].index_match = 41;
  EXPECT_THROW (from_correspondences.fit (source_cloud, shuffled, correspondences), InvalidInputError);
  correspondences[3].index_match = -1;
  EXPECT_THROW (from_correspondences.fit (source_cloud, shuffled, correspondences), InvalidInputError);
  EXPECT_THROW (from_correspondences.fit (source_cloud, shuffled, pcl::Correspondences ()), InvalidInputError);
  auto with_nan = source_cloud;
  with_nan[7].y = std::numeric_limits<float>::quiet_NaN ();
  EXPECT_THROW (from_clouds.fit (with_nan, target_cloud), InvalidInputError);
}

TEST (TpsTest, TransformCloudKeepsFieldsAndMapsNormals)
{
  const ThinPlateSpline<double, 3> tps = affineSpline ();
  const Eigen::Matrix3Xd positions = randomLandmarks (50, 24);
  auto cloud = toCloud<pcl::PointXYZRGBNormal> (positions);
  for (std::size_t j = 0; j < cloud.size (); ++j) {
    cloud[j].getNormalVector3fMap () = Eigen::Vector3f::Random ().normalized ();
    cloud[j].r = static_cast<std::uint8_t> (j);
    cloud[j].curvature = 0.5f;
  }
  pcl::PointCloud<pcl::PointXYZRGBNormal> warped;
  tps.transformCloud (cloud, warped);
  ASSERT_EQ (warped.size (), cloud.size ());
  const Eigen::Matrix3d normal_map = kLinear.inverse ().transpose ();
  for (std::size_t j = 0; j < cloud.size (); ++j) {
    const Eigen::Vector3d expected = kLinear * cloud[j].getVector3fMap ().cast<double> () + kShift;
    EXPECT_LE ((warped[j].getVector3fMap ().cast<double> () - expected).norm (), 1e-4);
    const Eigen::Vector3d normal = (normal_map * cloud[j].getNormalVector3fMap ().cast<double> ()).normalized ();
    EXPECT_LE ((warped[j].getNormalVector3fMap ().cast<double> () - normal).norm (), 1e-6);
    EXPECT_EQ (warped[j].r, cloud[j].r);
    EXPECT_EQ (warped[j].curvature, 0.5f);
  }
  // In place gives the same result.
  tps.transformCloud (cloud, cloud);
  for (std::size_t j = 0; j < cloud.size (); ++j)
    EXPECT_EQ (cloud[j].getVector3fMap (), warped[j].getVector3fMap ());
}

TEST (TpsTest, TwoDimensionalSplineWarpsXYAndKeepsZ)
{
  const Eigen::Matrix2Xd source = randomLandmarks<2> (20, 25);
  ThinPlateSpline<double, 2> tps;
  tps.fit (source, bend<2> (source));
  pcl::PointCloud<pcl::PointXYZ> cloud = toCloud<pcl::PointXYZ> (randomLandmarks (30, 26));
  pcl::PointCloud<pcl::PointXYZ> warped;
  tps.transformCloud (cloud, warped);
  for (std::size_t j = 0; j < cloud.size (); ++j) {
    EXPECT_EQ (warped[j].z, cloud[j].z);
    const Eigen::Vector2d expected = tps.transformPoint (cloud[j].getVector3fMap ().head<2> ().cast<double> ());
    EXPECT_LE ((warped[j].getVector3fMap ().head<2> ().cast<double> () - expected).norm (), 1e-4);
  }
}

TEST (TpsTest, TransformPolygonMeshMovesVerticesAndRecomputesNormals)
{
  const ThinPlateSpline<double, 3> tps = affineSpline ();
  const morphreg::TriangleMesh cube = morphreg::test::makeCube (40.0);
  const pcl::PolygonMesh input = morphreg::toPolygonMesh (cube); // PointNormal vertices
  pcl::PolygonMesh warped;
  tps.transformMesh (input, warped);
  ASSERT_EQ (warped.polygons.size (), input.polygons.size ());
  for (std::size_t t = 0; t < input.polygons.size (); ++t)
    EXPECT_EQ (warped.polygons[t].vertices, input.polygons[t].vertices);

  morphreg::TriangleMesh expected = cube;
  expected.vertices = (kLinear * cube.vertices).colwise () + kShift;
  const Eigen::Matrix3Xd expected_normals = morphreg::vertexNormals (expected);
  pcl::PointCloud<pcl::PointNormal> vertices;
  pcl::fromPCLPointCloud2 (warped.cloud, vertices);
  for (std::size_t j = 0; j < vertices.size (); ++j) {
    EXPECT_LE ((vertices[j].getVector3fMap ().cast<double> () - expected.vertices.col (j)).norm (), 1e-4);
    EXPECT_LE ((vertices[j].getNormalVector3fMap ().cast<double> () - expected_normals.col (j)).norm (), 1e-5);
  }
  // The TriangleMesh overload agrees, and a mesh without normals is warped too.
  EXPECT_LE (maxColumnDistance (tps.transformMesh (cube).vertices, expected.vertices), 1e-9);
  pcl::PolygonMesh plain;
  pcl::toPCLPointCloud2 (toCloud<pcl::PointXYZ> (cube.vertices), plain.cloud);
  plain.polygons = input.polygons;
  tps.transformMesh (plain, plain);
  pcl::PointCloud<pcl::PointXYZ> plain_vertices;
  pcl::fromPCLPointCloud2 (plain.cloud, plain_vertices);
  EXPECT_LE ((plain_vertices[5].getVector3fMap ().cast<double> () - expected.vertices.col (5)).norm (), 1e-4);
}

TEST (TpsTest, TransformPolygonMeshRejectsBadMeshes)
{
  const ThinPlateSpline<double, 3> tps = affineSpline ();
  pcl::PolygonMesh no_z;
  pcl::PointCloud<pcl::PointXY> flat;
  flat.resize (3);
  pcl::toPCLPointCloud2 (flat, no_z.cloud);
  pcl::PolygonMesh out;
  EXPECT_THROW (tps.transformMesh (no_z, out), InvalidInputError);
  pcl::PolygonMesh bad_index = morphreg::toPolygonMesh (morphreg::test::makeCube ());
  bad_index.polygons[2].vertices[1] = 99;
  EXPECT_THROW (tps.transformMesh (bad_index, out), InvalidInputError);
}

// SPDX-License-Identifier: BSD-3-Clause
// Closest points on triangles and meshes (with the open-boundary flag), area-uniform surface samples and the flat
// cap finder, on meshes with known answers.
#include <morphreg/common/error.h>
#include <morphreg/mesh/planar_cap.h>
#include <morphreg/mesh/surface_sampling.h>
#include <morphreg/mesh/triangle_locator.h>
#include "support/test_meshes.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <limits>
#include <random>

namespace
{
using morphreg::TriangleLocator;
using morphreg::TriangleMesh;

const Eigen::Vector3d kA (0.0, 0.0, 0.0), kB (4.0, 0.0, 0.0), kC (0.0, 4.0, 0.0);

Eigen::Vector3d
onTriangle (const Eigen::Vector3d& weights)
{
  return weights[0] * kA + weights[1] * kB + weights[2] * kC;
}

TEST (TriangleLocatorTest, ClosestPointOnATriangleInEveryRegion)
{
  // Above the face: the foot of the perpendicular.
  EXPECT_TRUE (onTriangle (morphreg::closestPointOnTriangle ({1.0, 1.0, 3.0}, kA, kB, kC))
                   .isApprox (Eigen::Vector3d (1.0, 1.0, 0.0)));
  // Beyond the hypotenuse: on the edge b-c, with the weight of a exactly 0.
  const Eigen::Vector3d edge = morphreg::closestPointOnTriangle ({3.0, 3.0, 1.0}, kA, kB, kC);
  EXPECT_EQ (edge[0], 0.0);
  EXPECT_TRUE (onTriangle (edge).isApprox (Eigen::Vector3d (2.0, 2.0, 0.0)));
  // Beyond the edge a-b.
  EXPECT_TRUE (onTriangle (morphreg::closestPointOnTriangle ({2.0, -3.0, 0.0}, kA, kB, kC))
                   .isApprox (Eigen::Vector3d (2.0, 0.0, 0.0)));
  // In the corner regions: the corners themselves.
  EXPECT_EQ (morphreg::closestPointOnTriangle ({-1.0, -1.0, 2.0}, kA, kB, kC), Eigen::Vector3d (1.0, 0.0, 0.0));
  EXPECT_EQ (morphreg::closestPointOnTriangle ({6.0, -1.0, 0.0}, kA, kB, kC), Eigen::Vector3d (0.0, 1.0, 0.0));
  EXPECT_EQ (morphreg::closestPointOnTriangle ({-1.0, 7.0, 0.0}, kA, kB, kC), Eigen::Vector3d (0.0, 0.0, 1.0));
  // A degenerate (collinear) triangle: the closest point of its segment.
  const Eigen::Vector3d flat =
      morphreg::closestPointOnTriangle ({2.0, 1.0, 0.0}, kA, kB, Eigen::Vector3d (2.0, 0.0, 0.0));
  EXPECT_TRUE (flat.allFinite ());
  EXPECT_NEAR (flat.sum (), 1.0, 1e-12);
  EXPECT_TRUE ((flat[0] * kA + flat[1] * kB + flat[2] * Eigen::Vector3d (2.0, 0.0, 0.0))
                   .isApprox (Eigen::Vector3d (2.0, 0.0, 0.0)));
}

TEST (TriangleLocatorTest, DistancesToACubeAreExact)
{
  const TriangleLocator locator (morphreg::test::makeCube (2.0));
  EXPECT_NEAR (locator.closestPoint ({3.0, 0.2, -0.3}).distance, 2.0, 1e-12);
  EXPECT_NEAR (locator.closestPoint ({0.5, 0.1, 0.0}).distance, 0.5, 1e-12) << "inside, nearest face x = 1";
  EXPECT_NEAR (locator.closestPoint ({2.0, 2.0, 2.0}).distance, std::sqrt (3.0), 1e-12) << "corner region";
  EXPECT_NEAR (locator.closestPoint ({2.0, 2.0, 0.0}).distance, std::sqrt (2.0), 1e-12) << "edge region";
  EXPECT_TRUE (locator.closestPoint ({2.0, 2.0, 2.0}).point.isApprox (Eigen::Vector3d (1.0, 1.0, 1.0)));
  EXPECT_FALSE (locator.closestPoint ({2.0, 2.0, 2.0}).on_boundary) << "a closed mesh has no boundary";
}

TEST (TriangleLocatorTest, AgreesWithBruteForceOnABumpySurface)
{
  TriangleMesh mesh = morphreg::test::makeGrid (30, 2.0);
  for (Eigen::Index v = 0; v < mesh.numVertices (); ++v)
    mesh.vertices (2, v) = 5.0 * std::sin (0.2 * mesh.vertices (0, v)) * std::cos (0.15 * mesh.vertices (1, v));
  const TriangleLocator locator (mesh);
  std::mt19937_64 rng (3);
  std::uniform_real_distribution<double> coordinate (-10.0, 70.0);
  for (int q = 0; q < 300; ++q) {
    const Eigen::Vector3d query (coordinate (rng), coordinate (rng), 0.3 * coordinate (rng));
    double best = std::numeric_limits<double>::infinity ();
    for (Eigen::Index t = 0; t < mesh.numTriangles (); ++t) {
      const Eigen::Vector3d a = mesh.vertices.col (mesh.triangles (0, t)),
                            b = mesh.vertices.col (mesh.triangles (1, t)),
                            c = mesh.vertices.col (mesh.triangles (2, t));
      const Eigen::Vector3d w = morphreg::closestPointOnTriangle (query, a, b, c);
      best = std::min (best, (w[0] * a + w[1] * b + w[2] * c - query).norm ());
    }
    const auto hit = locator.closestPoint (query);
    ASSERT_NEAR (hit.distance, best, 1e-9) << "query " << q;
    EXPECT_NEAR ((hit.point - query).norm (), hit.distance, 1e-9);
  }
}

TEST (TriangleLocatorTest, FlagsPointsOnTheOpenBoundary)
{
  const TriangleLocator locator (morphreg::test::makeGrid (5, 1.0)); // the square [0, 4]^2 at z = 0
  EXPECT_FALSE (locator.closestPoint ({2.2, 1.7, 1.0}).on_boundary) << "above the interior";
  EXPECT_FALSE (locator.closestPoint ({2.0, 2.0, 0.5}).on_boundary) << "onto an interior vertex";
  EXPECT_FALSE (locator.closestPoint ({1.5, 1.5, 0.5}).on_boundary) << "onto an interior edge";
  const auto side = locator.closestPoint ({-1.0, 2.5, 0.0});
  EXPECT_TRUE (side.on_boundary) << "beyond the side x = 0";
  EXPECT_TRUE (side.point.isApprox (Eigen::Vector3d (0.0, 2.5, 0.0)));
  EXPECT_TRUE (locator.closestPoint ({-1.0, -1.0, 0.0}).on_boundary) << "beyond the corner";
  EXPECT_TRUE (locator.closestPoint ({4.0, 2.0, 1.0}).on_boundary) << "onto a vertex of the border";
}

TEST (TriangleLocatorTest, BadInputIsReported)
{
  TriangleMesh broken = morphreg::test::makeCube ();
  broken.triangles (0, 3) = 99;
  EXPECT_THROW (TriangleLocator{broken}, morphreg::InvalidInputError);
  EXPECT_THROW (TriangleLocator{TriangleMesh ()}, morphreg::InvalidInputError);
  const TriangleLocator locator (morphreg::test::makeCube ());
  EXPECT_THROW (locator.closestPoint (Eigen::Vector3d (std::nan (""), 0.0, 0.0)), morphreg::InvalidInputError);
}

TEST (SurfaceSamplingTest, SamplesAreUniformByAreaAndOnTheSurface)
{
  // Two triangles of areas 1 and 9 (mm^2): one sample per 0.01 mm^2, shared 1 : 9.
  TriangleMesh mesh;
  mesh.vertices.resize (3, 6);
  mesh.vertices << 0, 1, 0, 10, 13, 10, //
      0, 0, 2, 0, 0, 6,                 //
      0, 0, 0, 5, 5, 5;
  mesh.triangles.resize (3, 2);
  mesh.triangles << 0, 3, 1, 4, 2, 5;
  const auto samples = morphreg::sampleSurfaceUniformly (mesh, 0.01, 7);
  ASSERT_EQ (samples.points.cols (), 1000);
  int on_small = 0;
  for (Eigen::Index i = 0; i < samples.points.cols (); ++i) {
    const int t = samples.triangles[static_cast<size_t> (i)];
    on_small += t == 0 ? 1 : 0;
    const Eigen::Vector3d p = samples.points.col (i);
    const Eigen::Vector3d w = morphreg::closestPointOnTriangle (p, mesh.vertices.col (mesh.triangles (0, t)),
                                                                mesh.vertices.col (mesh.triangles (1, t)),
                                                                mesh.vertices.col (mesh.triangles (2, t)));
    const Eigen::Vector3d foot = w[0] * mesh.vertices.col (mesh.triangles (0, t)) +
                                 w[1] * mesh.vertices.col (mesh.triangles (1, t)) +
                                 w[2] * mesh.vertices.col (mesh.triangles (2, t));
    ASSERT_LT ((foot - p).norm (), 1e-9) << "sample " << i << " lies on its triangle";
  }
  EXPECT_NEAR (on_small, 100, 30); // a sampling tolerance: about 3 standard deviations of the binomial count (9.5)
  // Uniform inside a triangle: the sample mean is the centroid.
  const Eigen::Vector3d centroid = mesh.vertices.rightCols (3).rowwise ().mean ();
  Eigen::Vector3d mean = Eigen::Vector3d::Zero ();
  for (Eigen::Index i = 0; i < samples.points.cols (); ++i)
    if (samples.triangles[static_cast<size_t> (i)] == 1)
      mean += samples.points.col (i) / static_cast<double> (samples.points.cols () - on_small);
  EXPECT_LT ((mean - centroid).norm (), 0.2);
  // Excluded triangles get no samples and no share of the count.
  const auto without_large = morphreg::sampleSurfaceUniformly (mesh, 0.01, 7, {false, true});
  EXPECT_EQ (without_large.points.cols (), 100);
  for (const int t : without_large.triangles)
    EXPECT_EQ (t, 0);
  // The same seed gives the same samples.
  EXPECT_EQ (morphreg::sampleSurfaceUniformly (mesh, 0.01, 7).points, samples.points);
}

TEST (SurfaceSamplingTest, BadInputIsReported)
{
  const TriangleMesh cube = morphreg::test::makeCube ();
  EXPECT_THROW (morphreg::sampleSurfaceUniformly (cube, 0.0, 1), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::sampleSurfaceUniformly (cube, std::nan (""), 1), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::sampleSurfaceUniformly (cube, 1.0, 1, {true}), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::sampleSurfaceUniformly (cube, 1.0, 1, std::vector<bool> (12, true)),
                morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::sampleSurfaceUniformly (TriangleMesh (), 1.0, 1), morphreg::InvalidInputError);
}

TEST (PlanarCapTest, FindsTheBottomOfATiltedBox)
{
  TriangleMesh box = morphreg::test::makeCube (100.0);
  const Eigen::Matrix3d tilt =
      Eigen::AngleAxisd (0.15, Eigen::Vector3d (1.0, 0.5, 0.0).normalized ()).toRotationMatrix ();
  box.vertices = tilt * box.vertices;
  const std::vector<bool> cap = morphreg::findPlanarCap (box);
  // The cube's bottom (z = -50 before tilting) is triangles 0 and 1 of makeCube.
  for (size_t t = 0; t < cap.size (); ++t)
    EXPECT_EQ (cap[t], t < 2) << "triangle " << t;
  // No seed facing the direction: nothing found.
  morphreg::PlanarCapSettings diagonal;
  diagonal.direction = Eigen::Vector3d (1.0, 1.0, 1.0).normalized ();
  for (const bool flag : morphreg::findPlanarCap (box, diagonal))
    EXPECT_FALSE (flag);
}

TEST (PlanarCapTest, BadInputIsReported)
{
  const TriangleMesh cube = morphreg::test::makeCube ();
  morphreg::PlanarCapSettings settings;
  settings.direction = Eigen::Vector3d::Zero ();
  EXPECT_THROW (morphreg::findPlanarCap (cube, settings), morphreg::InvalidInputError);
  settings = {};
  settings.rounds = 0;
  EXPECT_THROW (morphreg::findPlanarCap (cube, settings), morphreg::InvalidInputError);
  settings = {};
  settings.max_distance = -1.0;
  EXPECT_THROW (morphreg::findPlanarCap (cube, settings), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::findPlanarCap (TriangleMesh ()), morphreg::InvalidInputError);
}

} // namespace

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>

#include "support/test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>

using morphreg::MeshTopology;
using morphreg::TriangleMesh;

TEST (MeshTopologyTest, CubeIsClosedGenusZero)
{
  const MeshTopology topology (morphreg::test::makeCube ());
  EXPECT_EQ (topology.numVertices (), 8);
  EXPECT_EQ (topology.edges ().size (), 18u);
  EXPECT_EQ (topology.eulerCharacteristic (), 2);
  EXPECT_TRUE (topology.isClosedManifold ());
  EXPECT_TRUE (topology.boundaryEdges ().empty ());
  for (const auto& edge : topology.edges ())
    EXPECT_EQ (edge.face_count, 2);
}

TEST (MeshTopologyTest, GridHasBoundaryAndNeighbours)
{
  const int n = 5;
  const MeshTopology topology (morphreg::test::makeGrid (n));
  EXPECT_FALSE (topology.isClosedManifold ());
  EXPECT_EQ (topology.boundaryEdges ().size (), static_cast<std::size_t> (4 * (n - 1)));
  EXPECT_EQ (topology.boundaryVertices ().size (), static_cast<std::size_t> (4 * (n - 1)));
  EXPECT_EQ (topology.eulerCharacteristic (), 1); // a disc
  // The centre vertex of a regular diagonal grid has six neighbours, none of them itself.
  const int centre = 2 * n + 2;
  EXPECT_EQ (topology.valence (centre), 6);
  const auto [begin, end] = topology.neighbours (centre);
  for (const int* it = begin; it != end; ++it)
    EXPECT_NE (*it, centre);
  EXPECT_FALSE (topology.boundaryVertexMask ()[centre]);
  EXPECT_TRUE (topology.boundaryVertexMask ()[0]);
}

TEST (MeshTopologyTest, RingIndexGrowsOneRingPerStep)
{
  const int n = 9;
  const MeshTopology topology (morphreg::test::makeGrid (n));
  const int centre = 4 * n + 4;
  const std::vector<int> rings = topology.ringIndex ({centre}, 2);
  EXPECT_EQ (rings[centre], 0);
  EXPECT_EQ (rings[centre + 1], 1);
  EXPECT_EQ (rings[centre + 2], 2);
  EXPECT_EQ (rings[centre + 3], -1);
  EXPECT_EQ (std::count (rings.begin (), rings.end (), 1), 6);
}

TEST (MeshTopologyTest, GeodesicDistancesFollowEdges)
{
  const int n = 6;
  const TriangleMesh grid = morphreg::test::makeGrid (n, 2.0);
  const MeshTopology topology (grid);
  const std::vector<double> distances = topology.geodesicDistances (grid.vertices, {0});
  EXPECT_DOUBLE_EQ (distances[0], 0.0);
  EXPECT_DOUBLE_EQ (distances[n - 1], 2.0 * (n - 1));                        // along the bottom row
  EXPECT_NEAR (distances[n * n - 1], 2.0 * std::sqrt (2.0) * (n - 1), 1e-9); // along the diagonal edges
  const std::vector<double> limited = topology.geodesicDistances (grid.vertices, {0}, 3.0);
  EXPECT_TRUE (std::isinf (limited[n - 1]));
  EXPECT_DOUBLE_EQ (limited[1], 2.0);
}

TEST (MeshTopologyTest, CubeNormalsPointOutward)
{
  const TriangleMesh cube = morphreg::test::makeCube ();
  const Eigen::Matrix3Xd normals = morphreg::vertexNormals (cube);
  for (Eigen::Index v = 0; v < cube.numVertices (); ++v) {
    EXPECT_NEAR (normals.col (v).norm (), 1.0, 1e-12);
    EXPECT_GT (normals.col (v).dot (cube.vertices.col (v)), 0.0);
  }
  EXPECT_NEAR (morphreg::triangleAreas (cube).sum (), 24.0, 1e-12);
  const Eigen::Matrix3Xd face_normals = morphreg::faceNormals (cube);
  EXPECT_NEAR (face_normals.col (0).z (), -1.0, 1e-12);
}

TEST (MeshTopologyTest, ValidateMeshNamesTheProblem)
{
  TriangleMesh mesh = morphreg::test::makeCube ();
  mesh.vertices (1, 3) = std::nan ("");
  try {
    morphreg::validateMesh (mesh, "my scan");
    FAIL () << "a NaN vertex was accepted";
  }
  catch (const morphreg::InvalidInputError& e) {
    EXPECT_NE (std::string (e.what ()).find ("my scan"), std::string::npos) << e.what ();
  }
  mesh = morphreg::test::makeCube ();
  mesh.triangles (0, 0) = 8;
  EXPECT_THROW (morphreg::validateMesh (mesh, "cube"), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::validateMesh (TriangleMesh (), "empty"), morphreg::InvalidInputError);
  TriangleMesh other = morphreg::test::makeGrid (3);
  EXPECT_THROW (morphreg::requireSameTopology (morphreg::test::makeCube (), other, "grid"),
                morphreg::InvalidInputError);
}

TEST (MeshTopologyTest, PolygonMeshConversionRoundTrips)
{
  const TriangleMesh cube = morphreg::test::makeCube (3.0);
  const TriangleMesh back = morphreg::fromPolygonMesh (morphreg::toPolygonMesh (cube));
  EXPECT_TRUE (back.vertices.isApprox (cube.vertices, 1e-6));
  EXPECT_EQ (back.triangles, cube.triangles);
  pcl::PolygonMesh quads = morphreg::toPolygonMesh (cube);
  quads.polygons[0].vertices.push_back (4);
  EXPECT_THROW (morphreg::fromPolygonMesh (quads, "quads"), morphreg::InvalidInputError);
}

// Two closed tetrahedra joined at one vertex: every edge has two triangles, but the shared vertex's star is two
// fans, not one disc, so the surface is not a closed manifold.
TEST (MeshTopologyTest, TetrahedraSharingAVertexAreNotAManifold)
{
  TriangleMesh mesh;
  mesh.vertices.resize (3, 7);
  mesh.vertices << 0, 1, 0, 0, -1, 0, 0, //
      0, 0, 1, 0, 0, -1, 0,              //
      0, 0, 0, 1, 0, 0, -1;
  mesh.triangles.resize (3, 8);
  mesh.triangles << 0, 0, 0, 1, 0, 0, 0, 4, //
      2, 3, 1, 2, 5, 6, 4, 5,               //
      1, 2, 3, 3, 4, 5, 6, 6;
  const MeshTopology topology (mesh);
  EXPECT_EQ (topology.edges ().size (), 12u);
  for (const auto& edge : topology.edges ())
    EXPECT_EQ (edge.face_count, 2) << edge.a << "-" << edge.b;
  EXPECT_FALSE (topology.isClosedManifold ());

  TriangleMesh first = mesh; // one tetrahedron alone (vertex 4-6 unused would fail; keep 0-3)
  first.vertices = mesh.vertices.leftCols (4);
  first.triangles = mesh.triangles.leftCols (4);
  EXPECT_TRUE (MeshTopology (first).isClosedManifold ());
}

// A triangle that uses a vertex twice: its edges are counted as they occur, and the surface is not a manifold.
TEST (MeshTopologyTest, TriangleUsingAVertexTwice)
{
  TriangleMesh mesh;
  mesh.vertices = Eigen::Matrix3Xd::Random (3, 3);
  mesh.triangles.resize (3, 1);
  mesh.triangles << 0, 0, 1;
  const MeshTopology topology (mesh);
  ASSERT_EQ (topology.edges ().size (), 2u);
  EXPECT_EQ (topology.edges ()[0].a, 0);
  EXPECT_EQ (topology.edges ()[0].b, 0);
  EXPECT_EQ (topology.edges ()[0].face_count, 1);
  EXPECT_EQ (topology.edges ()[1].b, 1);
  EXPECT_EQ (topology.edges ()[1].face_count, 2);
  EXPECT_FALSE (topology.isClosedManifold ());
}

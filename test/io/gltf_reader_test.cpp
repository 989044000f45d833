// SPDX-License-Identifier: BSD-3-Clause
// morphreg's glTF reader on files the tests write (test/support/glb_writer.h): node transforms, merged primitives,
// strips, fans and points, .gltf with external and data-URI buffers, Draco, colours and textures, the loaders that
// gain glTF through it; and broken files, each refused with the file and the problem named.
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/coloured_surface_io.h>
#include <morphreg/io/file_validation.h>
#include <morphreg/io/gltf_reader.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/rgb_image_io.h>

#include "support/expect_error.h"
#include "support/glb_writer.h"
#include "support/temp_directory.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <pcl/conversions.h>

#include <fstream>
#include <iterator>

namespace gltf = morphreg::test::gltf;
using morphreg::FormatError;
using morphreg::TriangleMesh;
using morphreg::test::TempDirectory;

namespace
{
/** A closed octahedron in mm, 50 mm from its centre (10, 20, 30) to each corner. */
TriangleMesh
octahedron ()
{
  TriangleMesh mesh;
  mesh.vertices.resize (3, 6);
  mesh.vertices << 50, -50, 0, 0, 0, 0, 0, 0, 50, -50, 0, 0, 0, 0, 0, 0, 50, -50;
  mesh.vertices.colwise () += Eigen::Vector3d (10, 20, 30);
  mesh.triangles.resize (3, 8);
  mesh.triangles << 0, 2, 1, 3, 0, 3, 1, 2, 2, 1, 3, 0, 3, 1, 2, 0, 4, 4, 4, 4, 5, 5, 5, 5;
  return mesh;
}

morphreg::VertexColours
rainbow (Eigen::Index n)
{
  morphreg::VertexColours colours (3, n);
  for (Eigen::Index i = 0; i < n; ++i)
    colours.col (i) << static_cast<unsigned char> (40 * i), static_cast<unsigned char> (255 - 30 * i),
        static_cast<unsigned char> (7 + 11 * i);
  return colours;
}

std::string
writeGlb (const TempDirectory& dir, const std::string& name, const gltf::Document& document)
{
  const std::string path = dir.file (name);
  gltf::writeGlb (path, gltf::build (document));
  return path;
}

void
expectPointsNear (const Eigen::Matrix3Xd& actual, const Eigen::Matrix3Xd& expected, double tolerance = 1e-4)
{
  ASSERT_EQ (actual.cols (), expected.cols ());
  EXPECT_LT ((actual - expected).cwiseAbs ().maxCoeff (), tolerance);
}

std::vector<unsigned char>
fileBytes (const std::string& path)
{
  std::ifstream in (path, std::ios::binary);
  return {std::istreambuf_iterator<char> (in), std::istreambuf_iterator<char> ()};
}
} // namespace

TEST (GltfReaderTest, GlbInMetresIsReadInMillimetres)
{
  TempDirectory dir;
  const TriangleMesh mesh = octahedron ();
  const auto content =
      morphreg::readGltfFile (writeGlb (dir, "plain.glb", gltf::singleNode (gltf::meshPrimitive (mesh))));
  expectPointsNear (content.surface.points, mesh.vertices);
  EXPECT_EQ (content.surface.triangles, mesh.triangles);
  EXPECT_FALSE (content.surface.hasColours ());
  EXPECT_EQ (content.normals.cols (), 0);
  EXPECT_EQ (morphreg::sniffFileFormat (dir.file ("plain.glb")), morphreg::FileFormat::Glb);
  EXPECT_EQ (morphreg::specifiedLengthUnit (morphreg::FileFormat::Glb), morphreg::LengthUnit::metre);
}

TEST (GltfReaderTest, NodeHierarchyMatrixAndTrsAreApplied)
{
  TempDirectory dir;
  const TriangleMesh mesh = octahedron ();
  gltf::Document document = gltf::singleNode (gltf::meshPrimitive (mesh));
  const Eigen::Quaterniond q (Eigen::AngleAxisd (0.7, Eigen::Vector3d (1, 2, 3).normalized ()));
  gltf::Node parent;
  parent.translation = {0.1, -0.2, 0.3};
  parent.rotation = {q.x (), q.y (), q.z (), q.w ()};
  parent.scale = {2.0, 2.0, 2.0};
  parent.children = {1};
  Eigen::Affine3d child = Eigen::Affine3d::Identity ();
  child.translate (Eigen::Vector3d (0.05, 0.0, -0.01)).rotate (Eigen::AngleAxisd (-0.4, Eigen::Vector3d::UnitY ()));
  document.nodes = {parent, document.nodes[0]};
  document.nodes[1].matrix.assign (child.matrix ().data (), child.matrix ().data () + 16);
  document.scene = {0};
  const auto content = morphreg::readGltfFile (writeGlb (dir, "nodes.glb", document));
  Eigen::Affine3d global = Eigen::Affine3d::Identity ();
  global.translate (Eigen::Vector3d (0.1, -0.2, 0.3)).rotate (q).scale (2.0);
  global = global * child;
  const Eigen::Matrix3Xd expected = 1000.0 * (global * (mesh.vertices / 1000.0));
  expectPointsNear (content.surface.points, expected, 1e-3);
  EXPECT_EQ (content.surface.triangles, mesh.triangles);
}

TEST (GltfReaderTest, MirroringNodeKeepsTrianglesCounterClockwise)
{
  TempDirectory dir;
  const TriangleMesh mesh = octahedron ();
  gltf::Node mirror;
  mirror.scale = {-1.0, 1.0, 1.0};
  const auto content =
      morphreg::readGltfFile (writeGlb (dir, "mirror.glb", gltf::singleNode (gltf::meshPrimitive (mesh), mirror)));
  for (Eigen::Index t = 0; t < mesh.triangles.cols (); ++t) {
    EXPECT_EQ (content.surface.triangles (0, t), mesh.triangles (0, t));
    EXPECT_EQ (content.surface.triangles (1, t), mesh.triangles (2, t));
    EXPECT_EQ (content.surface.triangles (2, t), mesh.triangles (1, t));
  }
}

TEST (GltfReaderTest, PrimitivesAndMeshesAreMerged)
{
  TempDirectory dir;
  const TriangleMesh mesh = octahedron ();
  gltf::Primitive first = gltf::meshPrimitive (mesh), second = first, shared;
  first.indices.resize (12); // the first four triangles
  second.indices.erase (second.indices.begin (), second.indices.begin () + 12);
  shared.indices = second.indices;
  shared.shares_vertices_of = 0;
  gltf::Document document;
  document.meshes = {{first, shared}, {second}};
  document.nodes.resize (2);
  document.nodes[0].mesh = 0;
  document.nodes[1].mesh = 1;
  document.nodes[1].translation = {0.1, 0.0, 0.0};
  document.scene = {0, 1};
  const auto content = morphreg::readGltfFile (writeGlb (dir, "merged.glb", document));
  // mesh 0: its two primitives share their vertices, read once; mesh 1: a copy of the vertices 100 mm along x
  ASSERT_EQ (content.surface.points.cols (), 12);
  expectPointsNear (content.surface.points.leftCols (6), mesh.vertices);
  expectPointsNear (content.surface.points.rightCols (6), mesh.vertices.colwise () + Eigen::Vector3d (100, 0, 0));
  ASSERT_EQ (content.surface.triangles.cols (), 12);
  EXPECT_EQ (content.surface.triangles.leftCols (8), mesh.triangles);
  EXPECT_EQ (content.surface.triangles.rightCols (4), (mesh.triangles.rightCols (4).array () + 6).matrix ());
}

TEST (GltfReaderTest, StripsFansAndPoints)
{
  TempDirectory dir;
  gltf::Primitive strip, fan, points;
  strip.positions = Eigen::Matrix3Xf::Random (3, 5);
  strip.mode = 5; // triangles 012, 213, 234
  fan.positions = Eigen::Matrix3Xf::Random (3, 5);
  fan.mode = 6; // triangles 120, 230, 340
  points.positions = Eigen::Matrix3Xf::Random (3, 4);
  points.mode = 0;
  points.indices = {3, 1};
  gltf::Document document = gltf::singleNode (strip);
  document.meshes[0] = {strip, fan, points};
  const auto content = morphreg::readGltfFile (writeGlb (dir, "modes.glb", document));
  ASSERT_EQ (content.surface.points.cols (), 12);
  Eigen::Matrix3Xi expected (3, 6);
  expected << 0, 1, 2, 6, 7, 8, 1, 3, 3, 7, 8, 9, 2, 2, 4, 5, 5, 5;
  EXPECT_EQ (content.surface.triangles, expected);
  expectPointsNear (content.surface.points.col (10), 1000.0 * points.positions.col (3).cast<double> ());
  expectPointsNear (content.surface.points.col (11), 1000.0 * points.positions.col (1).cast<double> ());
}

TEST (GltfReaderTest, GltfWithExternalAndDataUriBuffersReadsAsGlb)
{
  TempDirectory dir;
  const TriangleMesh mesh = octahedron ();
  const gltf::Parts parts = gltf::build (gltf::singleNode (gltf::meshPrimitive (mesh, 1.0, rainbow (6))));
  gltf::writeGltf (dir.file ("external.gltf"), parts, "external.bin");
  gltf::writeGltf (dir.file ("embedded.gltf"), parts, "");
  gltf::writeGlb (dir.file ("binary.glb"), parts);
  const auto binary = morphreg::readGltfFile (dir.file ("binary.glb"));
  for (const char* name : {"external.gltf", "embedded.gltf"}) {
    EXPECT_EQ (morphreg::sniffFileFormat (dir.file (name)), morphreg::FileFormat::Gltf);
    const auto content = morphreg::readGltfFile (dir.file (name));
    EXPECT_EQ (content.surface.points, binary.surface.points) << name;
    EXPECT_EQ (content.surface.triangles, binary.surface.triangles) << name;
    EXPECT_EQ (content.surface.colours, rainbow (6)) << name;
  }
}

TEST (GltfReaderTest, DracoMeshesDecodeToTheGeometry)
{
  TempDirectory dir;
  const TriangleMesh mesh = octahedron ();
  gltf::Primitive lossless = gltf::meshPrimitive (mesh, 1.0, rainbow (6));
  lossless.draco = true;
  lossless.draco_method = draco::MESH_SEQUENTIAL_ENCODING;
  const auto exact = morphreg::readGltfFile (writeGlb (dir, "lossless.glb", gltf::singleNode (lossless)));
  expectPointsNear (exact.surface.points, mesh.vertices);
  EXPECT_EQ (exact.surface.triangles, mesh.triangles);
  EXPECT_EQ (exact.surface.colours, rainbow (6));

  gltf::Primitive quantized = gltf::meshPrimitive (mesh);
  quantized.draco = true;
  quantized.position_bits = 11; // 100 mm over 2047 steps: within 0.025 mm
  const auto coarse = morphreg::readGltfFile (writeGlb (dir, "quantized.glb", gltf::singleNode (quantized)));
  ASSERT_EQ (coarse.surface.points.cols (), 6);
  ASSERT_EQ (coarse.surface.triangles.cols (), 8);
  for (Eigen::Index v = 0; v < 6; ++v) // Edgebreaker may reorder the vertices
    EXPECT_LT ((mesh.vertices.colwise () - coarse.surface.points.col (v)).colwise ().norm ().minCoeff (), 0.05);
}

TEST (GltfReaderTest, ColoursTextureAndFactorAreKept)
{
  TempDirectory dir;
  morphreg::RgbImage image{2, 1, {200, 150, 100, 10, 20, 30}}; // left half skin-coloured, right half dark
  morphreg::saveRgbImage (dir.file ("texture.png"), image);
  gltf::Primitive textured = gltf::meshPrimitive (octahedron ());
  textured.uv = Eigen::Matrix2Xf::Constant (2, 6, 0.5f);
  textured.uv.row (0) << 0.25f, 0.75f, 0.25f, 0.25f, 0.25f, 0.25f;
  textured.material = 0;
  gltf::Document document = gltf::singleNode (textured);
  document.images = {{fileBytes (dir.file ("texture.png")), "image/png"}};
  document.materials = {{0, {}}};
  const auto content = morphreg::readGltfFile (writeGlb (dir, "textured.glb", document));
  ASSERT_TRUE (content.surface.hasColours ());
  ASSERT_EQ (content.surface.textures.size (), 1u);
  const morphreg::VertexColours colours = morphreg::pointColours (content.surface);
  EXPECT_EQ (colours.col (0), morphreg::Rgb8 (200, 150, 100));
  EXPECT_EQ (colours.col (1), morphreg::Rgb8 (10, 20, 30));
  const pcl::PolygonMesh polygons = morphreg::loadPolygonMesh (dir.file ("textured.glb"));
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  pcl::fromPCLPointCloud2 (polygons.cloud, cloud);
  EXPECT_EQ (cloud[0].r, 200);
  EXPECT_EQ (cloud[1].b, 30);

  document.materials = {{0, {0.5, 1.0, 1.0, 1.0}}}; // the factor multiplies the texture (in linear light)
  const auto halved = morphreg::readGltfFile (writeGlb (dir, "factor.glb", document));
  const int red = morphreg::pointColours (halved.surface) (0, 0);
  EXPECT_NEAR (gltf::srgbToLinear (static_cast<unsigned char> (red)), 0.5 * gltf::srgbToLinear (200), 0.01);
}

TEST (GltfReaderTest, LoadersReadGltfAndGlb)
{
  TempDirectory dir;
  const TriangleMesh mesh = octahedron ();
  const gltf::Parts parts = gltf::build (gltf::singleNode (gltf::meshPrimitive (mesh, 1.0, rainbow (6))));
  gltf::writeGlb (dir.file ("mesh.glb"), parts);
  gltf::writeGltf (dir.file ("mesh.gltf"), parts, "mesh.bin");
  for (const char* name : {"mesh.glb", "mesh.gltf"}) {
    const TriangleMesh loaded = morphreg::loadTriangleMesh (dir.file (name));
    expectPointsNear (loaded.vertices, mesh.vertices);
    EXPECT_EQ (loaded.triangles, mesh.triangles);
    const auto cloud = morphreg::loadCloud<pcl::PointXYZRGBNormal> (dir.file (name));
    ASSERT_EQ (cloud->size (), 6u);
    EXPECT_EQ ((*cloud)[2].g, rainbow (6) (1, 2));
    EXPECT_NO_THROW (morphreg::validateGeometryFile (dir.file (name)));
    EXPECT_EQ (morphreg::loadColouredSurface (dir.file (name)).colours, rainbow (6));
  }
}

TEST (GltfReaderTest, VerticesRepeatedAtOnePositionAreMerged)
{
  TempDirectory dir;
  const TriangleMesh mesh = octahedron ();
  gltf::Primitive split = gltf::meshPrimitive (mesh); // a vertex per triangle corner, as texture seams make them
  split.positions.resize (3, 24);
  for (int c = 0; c < 24; ++c)
    split.positions.col (c) = (mesh.vertices.col (mesh.triangles.data ()[c]) / 1000.0).cast<float> ();
  for (std::uint32_t c = 0; c < 24; ++c)
    split.indices[c] = c;
  const auto content = morphreg::readGltfFile (writeGlb (dir, "split.glb", gltf::singleNode (split)));
  ASSERT_EQ (content.surface.points.cols (), 6);
  for (Eigen::Index t = 0; t < 8; ++t)
    for (int k = 0; k < 3; ++k)
      EXPECT_LT (
          (content.surface.points.col (content.surface.triangles (k, t)) - mesh.vertices.col (mesh.triangles (k, t)))
              .norm (),
          1e-4);
}

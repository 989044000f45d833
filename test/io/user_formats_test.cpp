// SPDX-License-Identifier: BSD-3-Clause
// The formats users bring: iBUG-68 .pts files and ids, scalismo/BFM landmark JSON, STL and OFF scans, PLY files
// with double coordinates.
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_io.h>

#include "support/expect_error.h"
#include "support/temp_directory.h"
#include "support/test_meshes.h"

#include <gtest/gtest.h>

#include <fstream>

using morphreg::test::expectErrorContaining;
using morphreg::test::TempDirectory;

namespace
{
void
writeText (const std::string& path, const std::string& text)
{
  std::ofstream (path) << text;
}

/** An iBUG .pts file of \a count points, point k at (k, 2k[, 3k]). */
std::string
ptsText (int count, int dim, int declared = 68)
{
  std::string text = "version: 1\nn_points:  " + std::to_string (declared) + "\n{\n";
  for (int k = 0; k < count; ++k)
    text += std::to_string (k) + " " + std::to_string (2 * k) + (dim == 3 ? " " + std::to_string (3 * k) : "") + "\n";
  return text + "}\n";
}

/** A binary little-endian PLY of the three points (k, 2k, -3k) / 10, k = 1..3, as doubles, with one triangle when
 *  \a with_face; point 1's x is \a first_x. */
std::string
doublePly (bool with_face, double first_x = 0.1)
{
  std::string text = "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
                     "property double z\nproperty float quality\n";
  if (with_face)
    text += "element face 1\nproperty list uchar int vertex_indices\n";
  text += "end_header\n";
  for (int k = 1; k <= 3; ++k) {
    const double xyz[3] = {k == 1 ? first_x : k / 10.0, 2 * k / 10.0, -3 * k / 10.0};
    text.append (reinterpret_cast<const char*> (xyz), sizeof (xyz));
    const float quality = k;
    text.append (reinterpret_cast<const char*> (&quality), sizeof (quality));
  }
  if (with_face) {
    const int corners[3] = {0, 1, 2};
    text.push_back (3);
    text.append (reinterpret_cast<const char*> (corners), sizeof (corners));
  }
  return text;
}

} // namespace

TEST (UserFormatsTest, ReadsIbugPtsAsIbug68Ids)
{
  TempDirectory dir;
  writeText (dir.file ("face.pts"), ptsText (68, 3));
  const auto landmarks = morphreg::loadLandmarks (dir.file ("face.pts"));
  ASSERT_EQ (landmarks.size (), 68u);
  EXPECT_EQ (landmarks.at ("ibug68_00"), Eigen::Vector3d (0, 0, 0));
  EXPECT_EQ (landmarks.at ("ibug68_30"), Eigen::Vector3d (30, 60, 90));
  EXPECT_EQ (landmarks.at ("ibug68_67"), Eigen::Vector3d (67, 134, 201));
  writeText (dir.file ("photo.pts"), ptsText (68, 2));
  EXPECT_EQ (morphreg::loadLandmarkPixels (dir.file ("photo.pts")).at ("ibug68_08"), Eigen::Vector2d (8, 16));
}

TEST (UserFormatsTest, BadPtsFilesAreNamedWithTheLine)
{
  TempDirectory dir;
  const auto load = [&] (const std::string& name, const std::string& text) {
    writeText (dir.file (name), text);
    return [path = dir.file (name)] { morphreg::loadLandmarks (path); };
  };
  expectErrorContaining<morphreg::FormatError> (load ("short.pts", ptsText (67, 3)),
                                                "short.pts: 67 points, but n_points is 68");
  expectErrorContaining<morphreg::FormatError> (load ("n49.pts", ptsText (49, 3, 49)),
                                                "n49.pts: n_points is 49; iBUG-68");
  expectErrorContaining<morphreg::FormatError> (load ("flat.pts", ptsText (68, 2)),
                                                "flat.pts:4: expected 3 coordinates");
  std::string text = ptsText (68, 3);
  text.replace (text.find ("\n5 10 15"), 8, "\n5 ten 15");
  expectErrorContaining<morphreg::FormatError> (load ("word.pts", text), "word.pts:9: coordinate y 'ten'");
  expectErrorContaining<morphreg::FormatError> (load ("open.pts", "n_points: 68\n{\n1 2 3\n"), "not enclosed");
  expectErrorContaining<morphreg::FormatError> (load ("huge.pts", "n_points: 1e300\n{\n}\n"),
                                                "huge.pts:1: n_points '1e300' is not a point count");
  expectErrorContaining<morphreg::FormatError> (load ("half.pts", "n_points: 67.5\n{\n}\n"),
                                                "half.pts:1: n_points '67.5' is not a point count");
  expectErrorContaining<morphreg::FormatError> (load ("header.pts", "points 68\n{\n}\n"),
                                                "header.pts:1: expected 'version:'");
}

TEST (UserFormatsTest, Ibug68IdsAreAcceptedInEveryFormat)
{
  TempDirectory dir;
  const morphreg::LandmarkPositions marked = {
      {"ibug68_30", {1, 2, 3}}, {"nose_tip", {4, 5, 6}}, {"ibug68_08", {7, 8, 9}}};
  for (const std::string name : {"i.pp", "i.json", "i.csv"}) {
    morphreg::saveLandmarks (dir.file (name), marked);
    EXPECT_EQ (morphreg::loadLandmarks (dir.file (name)), marked) << name;
  }
  writeText (dir.file ("range.csv"), "id,x,y,z\nibug68_68,1,2,3\n");
  expectErrorContaining<morphreg::InvalidInputError> ([&] { morphreg::loadLandmarks (dir.file ("range.csv")); },
                                                      "unknown landmark id 'ibug68_68'");
}

TEST (UserFormatsTest, ReadsScalismoLandmarkJsonWithBaselIds)
{
  TempDirectory dir;
  writeText (dir.file ("bfm.json"), R"([{"id": "center.nose.tip", "coordinates": [1.5, 2, 3], "uncertainty": {}},
    {"id": "left.eye.corner_outer", "coordinates": [40, 30, 20]}, {"id": "ibug68_30", "coordinates": [0, 0, 1]}])");
  const auto landmarks = morphreg::loadLandmarks (dir.file ("bfm.json"));
  ASSERT_EQ (landmarks.size (), 3u);
  EXPECT_EQ (landmarks.at ("nose_tip"), Eigen::Vector3d (1.5, 2, 3));
  EXPECT_EQ (landmarks.at ("left_eye_outer"), Eigen::Vector3d (40, 30, 20));
  EXPECT_EQ (landmarks.at ("ibug68_30"), Eigen::Vector3d (0, 0, 1));

  writeText (dir.file ("two.json"), R"([{"id": "center.nose.tip", "coordinates": [1, 2]}])");
  expectErrorContaining<morphreg::FormatError> (
      [&] { morphreg::loadLandmarks (dir.file ("two.json")); },
      "two.json: [0] ('center.nose.tip'): \"coordinates\" must be an array of 3");
  writeText (dir.file ("noid.json"), R"([{"coordinates": [1, 2, 3]}])");
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadLandmarks (dir.file ("noid.json")); },
                                                "noid.json: [0]");
  writeText (dir.file ("unmapped.json"), R"([{"id": "left.ear.helix.top", "coordinates": [1, 2, 3]}])");
  expectErrorContaining<morphreg::InvalidInputError> ([&] { morphreg::loadLandmarks (dir.file ("unmapped.json")); },
                                                      "unknown landmark id 'left.ear.helix.top'");
  // A model file's metadata keeps ids without a project equivalent.
  EXPECT_EQ (morphreg::parseScalismoLandmarks (R"([{"id": "left.ear.helix.top", "coordinates": [1, 2, 3]}])", "m")
                 .count ("left.ear.helix.top"),
             1u);
}

TEST (UserFormatsTest, ReadsStlAndOffScansAndMeshes)
{
  TempDirectory dir;
  const morphreg::TriangleMesh cube = morphreg::test::makeCube (10.0);
  std::string off = "OFF # a cube\n8 12 0\n";
  for (int i = 0; i < 8; ++i)
    off += std::to_string (cube.vertices (0, i)) + " " + std::to_string (cube.vertices (1, i)) + " " +
           std::to_string (cube.vertices (2, i)) + "\n";
  for (int t = 0; t < 12; ++t)
    off += "3 " + std::to_string (cube.triangles (0, t)) + " " + std::to_string (cube.triangles (1, t)) + " " +
           std::to_string (cube.triangles (2, t)) + " 255 0 0\n";
  writeText (dir.file ("cube.off"), off);
  const morphreg::TriangleMesh loaded = morphreg::loadTriangleMesh (dir.file ("cube.off"));
  EXPECT_TRUE (loaded.vertices.isApprox (cube.vertices, 1e-5));
  EXPECT_EQ (loaded.triangles, cube.triangles);
  EXPECT_EQ (morphreg::loadCloud<pcl::PointNormal> (dir.file ("cube.off"))->size (), 8u);

  // STL through VTK (written here as ASCII STL: the triangles with their corners, no shared vertices).
  std::string stl = "solid cube\n";
  for (int t = 0; t < 12; ++t) {
    stl += "facet normal 0 0 0\nouter loop\n";
    for (int c = 0; c < 3; ++c) {
      const Eigen::Vector3d v = cube.vertices.col (cube.triangles (c, t));
      stl += "vertex " + std::to_string (v.x ()) + " " + std::to_string (v.y ()) + " " + std::to_string (v.z ()) + "\n";
    }
    stl += "endloop\nendfacet\n";
  }
  writeText (dir.file ("cube.stl"), stl + "endsolid cube\n");
  const auto scan = morphreg::loadCloud<pcl::PointXYZ> (dir.file ("cube.stl"));
  EXPECT_EQ (scan->size (), 8u) << "VTK's STL reader merges the shared corners";
  EXPECT_EQ (morphreg::loadPolygonMesh (dir.file ("cube.stl")).polygons.size (), 12u);
  writeText (dir.file ("cut.stl"), "solid cut\nfacet normal 0 0 0\nouter loop\nvertex 1 2\n");
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadCloud<pcl::PointXYZ> (dir.file ("cut.stl")); },
                                                "cut.stl:4: vertex has 2 coordinates, expected 3");
}

TEST (UserFormatsTest, BadOffFilesAreNamedWithTheLine)
{
  TempDirectory dir;
  const auto load = [&] (const std::string& name, const std::string& text) {
    writeText (dir.file (name), text);
    return [path = dir.file (name)] { morphreg::loadCloud<pcl::PointXYZ> (path); };
  };
  expectErrorContaining<morphreg::FormatError> (load ("coff.off", "COFF\n3 1 0\n"), "coff.off: not an ASCII OFF file");
  expectErrorContaining<morphreg::FormatError> (load ("corner.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
                                                "corner.off:6: face 0 corner 7 is not a whole number in [0, 3)");
  expectErrorContaining<morphreg::FormatError> (load ("nan.off", "OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n"),
                                                "nan.off:4: vertex 1 coordinate y 'nan' is not a finite number");
  expectErrorContaining<morphreg::FormatError> (load ("cut.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n"),
                                                "cut.off: header claims 1 faces (at least 8 bytes) but the file holds");
  // an OFF file of points alone is a cloud (as PLY and PCD are), but not a mesh
  writeText (dir.file ("points.off"), "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
  EXPECT_EQ (morphreg::loadCloud<pcl::PointXYZ> (dir.file ("points.off"))->size (), 3u);
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadPolygonMesh (dir.file ("points.off")); },
                                                "points.off: mesh has no polygons");
}

// Open3D and trimesh write "property double x": PCL copies only fields of the point type's own (float) type, and such
// a file loaded as all zeros ("all 3 points are identical (0,0,0)"). The doubles are narrowed to float on loading.
TEST (UserFormatsTest, ReadsPlyWithDoubleCoordinates)
{
  TempDirectory dir;
  std::ofstream (dir.file ("cloud.ply"), std::ios::binary) << doublePly (false);
  const auto cloud = morphreg::loadCloud<pcl::PointXYZ> (dir.file ("cloud.ply"));
  ASSERT_EQ (cloud->size (), 3u);
  for (int k = 1; k <= 3; ++k)
    EXPECT_TRUE ((*cloud)[k - 1].getVector3fMap ().isApprox (Eigen::Vector3f (k, 2 * k, -3 * k) / 10.0f, 1e-6f)) << k;

  std::ofstream (dir.file ("mesh.ply"), std::ios::binary) << doublePly (true);
  const morphreg::TriangleMesh mesh = morphreg::loadTriangleMesh (dir.file ("mesh.ply"));
  EXPECT_TRUE (mesh.vertices.col (2).isApprox (Eigen::Vector3d (0.3, 0.6, -0.9), 1e-6));

  std::ofstream (dir.file ("huge.ply"), std::ios::binary) << doublePly (false, 1e39);
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadCloud<pcl::PointXYZ> (dir.file ("huge.ply")); },
                                                "huge.ply: property 'x' of point 0 is");
}

// SPDX-License-Identifier: BSD-3-Clause
// morphreg's OBJ reader: what it takes from a file (positions, colours, normals, polygons) and that the lines PCL's
// reader crashed on are read or refused with the line.
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/mesh_io.h>

#include "support/temp_directory.h"
#include "support/text_file.h"

#include <gtest/gtest.h>
#include <pcl/conversions.h>

using morphreg::test::TempDirectory;

namespace
{
std::string
writeObj (const TempDirectory& dir, const std::string& name, const std::string& text)
{
  const std::string path = dir.file (name);
  morphreg::test::writeText (path, text);
  return path;
}

bool
hasField (const pcl::PolygonMesh& mesh, const std::string& name)
{
  for (const auto& field : mesh.cloud.fields)
    if (field.name == name)
      return true;
  return false;
}
} // namespace

TEST (ObjReaderTest, PositionsPolygonsAndRelativeIndices)
{
  TempDirectory dir;
  const auto mesh =
      morphreg::readObjFile (writeObj (dir, "quad.obj",
                                       "# a quad and a triangle\nv 0 0 0\nv 1 0 0\nv 1 1 0 1\nv 0 1 0\nvt 0 0\n"
                                       "f 1/1 2/1 3/1 4/1\nf -4 -2 -1\nmtllib skin.mtl\nusemtl skin\n"));
  pcl::PointCloud<pcl::PointXYZ> points;
  pcl::fromPCLPointCloud2 (mesh.cloud, points);
  ASSERT_EQ (points.size (), 4u);
  EXPECT_FLOAT_EQ (points[2].x, 1.0f);
  EXPECT_FLOAT_EQ (points[2].y, 1.0f);
  ASSERT_EQ (mesh.polygons.size (), 2u);
  EXPECT_EQ (mesh.polygons[0].vertices, (std::vector<pcl::index_t>{0, 1, 2, 3}));
  EXPECT_EQ (mesh.polygons[1].vertices, (std::vector<pcl::index_t>{0, 2, 3}));
  EXPECT_FALSE (hasField (mesh, "rgb"));
  EXPECT_FALSE (hasField (mesh, "normal_x"));
}

TEST (ObjReaderTest, ColoursAndNormalsPerVertex)
{
  TempDirectory dir;
  const auto mesh = morphreg::readObjFile (
      writeObj (dir, "coloured.obj",
                "v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 1 0\nf 1//1 2//2 3//3\n"));
  ASSERT_TRUE (hasField (mesh, "rgb"));
  ASSERT_TRUE (hasField (mesh, "normal_x"));
  pcl::PointCloud<pcl::PointXYZRGBNormal> points;
  pcl::fromPCLPointCloud2 (mesh.cloud, points);
  EXPECT_EQ (points[0].r, 255);
  EXPECT_EQ (points[1].g, 255);
  EXPECT_EQ (points[2].b, 255);
  EXPECT_FLOAT_EQ (points[2].normal_y, 1.0f);
  // Fewer normals than vertices cannot be normals per vertex: the cloud goes without them.
  const auto partial = morphreg::readObjFile (writeObj (dir, "partial.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\n"));
  EXPECT_FALSE (hasField (partial, "normal_x"));
}

TEST (ObjReaderTest, AVertexOnlyFileIsACloudButNoMesh)
{
  TempDirectory dir;
  const std::string path = writeObj (dir, "points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n");
  EXPECT_EQ (morphreg::loadCloud<pcl::PointXYZ> (path)->size (), 4u);
  EXPECT_THROW (morphreg::loadPolygonMesh (path), morphreg::FormatError);
}

TEST (ObjReaderTest, LinesThatCrashedPclsReaderAreReadOrRefused)
{
  TempDirectory dir;
  // Unknown keywords beginning with v, and material lines with garbage names: ignored, as the format allows.
  const auto mesh = morphreg::readObjFile (writeObj (
      dir, "odd.obj", "v 0 0 0\nv 10 0 0\nvd0 # x\nvrahedr\nmtllib \xe8\xe8.\xff\xff\nv 0 10 0\nf 1 2 3\n\r\n\r\r\r"));
  EXPECT_EQ (mesh.polygons.size (), 1u);
  EXPECT_EQ (mesh.cloud.width * mesh.cloud.height, 3u);
  EXPECT_THROW (
      morphreg::readObjFile (writeObj (dir, "huge.obj", "v 0 0 0\nv 10 0 777777777777777777777777777777777777777\n")),
      morphreg::FormatError);
}

TEST (ObjReaderTest, WhatMorphregWritesItReadsBack)
{
  TempDirectory dir;
  morphreg::TriangleMesh mesh;
  mesh.vertices = Eigen::Matrix3Xd::Random (3, 5) * 100.0;
  mesh.triangles.resize (3, 3);
  mesh.triangles << 0, 1, 2, 1, 2, 3, 2, 3, 4;
  morphreg::saveTriangleMesh (dir.file ("mesh.obj"), mesh); // with vertex normals
  const morphreg::TriangleMesh back = morphreg::loadTriangleMesh (dir.file ("mesh.obj"));
  EXPECT_TRUE (back.vertices.isApprox (mesh.vertices, 1e-6));
  EXPECT_EQ (back.triangles, mesh.triangles);
}

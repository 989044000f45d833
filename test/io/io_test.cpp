// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/common/cloud_checks.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/mesh_io.h>

#include "support/temp_directory.h"
#include "support/text_file.h"
#include "support/test_meshes.h"

#include <gtest/gtest.h>

#include <fstream>

using morphreg::test::TempDirectory;
using morphreg::test::writeText;

namespace
{
pcl::PointCloud<pcl::PointNormal>
makeCloud ()
{
  pcl::PointCloud<pcl::PointNormal> cloud;
  for (int i = 0; i < 50; ++i) {
    pcl::PointNormal p;
    p.x = 0.5f * i;
    p.y = -1.25f * i;
    p.z = 100.0f + i;
    p.normal_x = 0.0f;
    p.normal_y = 0.6f;
    p.normal_z = 0.8f;
    p.curvature = 0.0f;
    cloud.push_back (p);
  }
  return cloud;
}

/** Expects \a call to throw an error of type E whose message names \a path. */
template <typename E, typename F>
void
expectErrorNaming (F call, const std::string& path)
{
  try {
    call ();
    FAIL () << "no error for " << path;
  }
  catch (const E& e) {
    EXPECT_NE (std::string (e.what ()).find (path), std::string::npos) << e.what ();
  }
}
} // namespace

TEST (IoTest, CloudRoundTripsThroughPcdPlyAndObj)
{
  TempDirectory dir;
  const auto cloud = makeCloud ();
  for (const std::string name : {"c.pcd", "c.ply", "c.obj"}) {
    morphreg::saveCloud (dir.file (name), cloud);
    const auto loaded = morphreg::loadCloud<pcl::PointXYZ> (dir.file (name));
    ASSERT_EQ (loaded->size (), cloud.size ()) << name;
    for (std::size_t i = 0; i < cloud.size (); ++i)
      EXPECT_TRUE (loaded->points[i].getVector3fMap ().isApprox (cloud[i].getVector3fMap (), 1e-5f)) << name;
  }
  const auto with_normals = morphreg::loadCloud<pcl::PointNormal> (dir.file ("c.pcd"));
  EXPECT_FLOAT_EQ ((*with_normals)[7].normal_z, 0.8f);
}

TEST (IoTest, MeshRoundTripsThroughPlyObjAndVtk)
{
  TempDirectory dir;
  const morphreg::TriangleMesh cube = morphreg::test::makeCube (10.0);
  for (const std::string name : {"m.ply", "m.obj", "m.vtk"}) {
    morphreg::saveTriangleMesh (dir.file (name), cube);
    const morphreg::TriangleMesh loaded = morphreg::loadTriangleMesh (dir.file (name));
    EXPECT_TRUE (loaded.vertices.isApprox (cube.vertices, 1e-6)) << name;
    EXPECT_EQ (loaded.triangles, cube.triangles) << name;
  }
  EXPECT_EQ (morphreg::loadPolygonMesh (dir.file ("m.ply")).polygons.size (), 12u);
}

TEST (IoTest, MissingEmptyAndCorruptFilesAreNamed)
{
  TempDirectory dir;
  const std::string missing = dir.file ("missing.ply");
  expectErrorNaming<morphreg::IoError> ([&] { morphreg::loadTriangleMesh (missing); }, missing);
  expectErrorNaming<morphreg::IoError> ([&] { morphreg::loadCloud<pcl::PointXYZ> (missing); }, missing);

  const std::string empty = dir.file ("empty.pcd");
  writeText (empty, "");
  expectErrorNaming<morphreg::FormatError> ([&] { morphreg::loadCloud<pcl::PointXYZ> (empty); }, empty);

  const std::string garbage = dir.file ("garbage.ply");
  writeText (garbage, "this is not a ply file\n\x01\x02\x03");
  expectErrorNaming<morphreg::FormatError> ([&] { morphreg::loadPolygonMesh (garbage); }, garbage);
  expectErrorNaming<morphreg::FormatError> ([&] { morphreg::loadCloud<pcl::PointXYZ> (garbage); }, garbage);

  const std::string pcd_garbage = dir.file ("garbage.pcd");
  writeText (pcd_garbage, "VERSION .7\nFIELDS x y z\nthis is broken\n");
  expectErrorNaming<morphreg::FormatError> ([&] { morphreg::loadCloud<pcl::PointXYZ> (pcd_garbage); }, pcd_garbage);

  const std::string unknown = dir.file ("scan.xyz");
  writeText (unknown, "1 2 3\n");
  expectErrorNaming<morphreg::IoError> ([&] { morphreg::loadCloud<pcl::PointXYZ> (unknown); }, unknown);

  expectErrorNaming<morphreg::IoError> ([&] { morphreg::loadTriangleMesh (dir.file ("")); }, dir.file (""));
}

TEST (IoTest, PointCloudIsNotAMesh)
{
  TempDirectory dir;
  const std::string path = dir.file ("points.ply");
  morphreg::saveCloud (path, makeCloud ());
  expectErrorNaming<morphreg::FormatError> ([&] { morphreg::loadPolygonMesh (path); }, path);
}

TEST (IoTest, WritingFailuresAreNamed)
{
  TempDirectory dir;
  const std::string unwritable = dir.file ("no/such/folder/c.pcd");
  expectErrorNaming<morphreg::IoError> ([&] { morphreg::saveCloud (unwritable, makeCloud ()); }, unwritable);
  const std::string wrong = dir.file ("mesh.stl");
  expectErrorNaming<morphreg::IoError> ([&] { morphreg::saveTriangleMesh (wrong, morphreg::test::makeCube ()); },
                                        wrong);
  expectErrorNaming<morphreg::InvalidInputError> (
      [&] { morphreg::saveCloud (dir.file ("e.pcd"), pcl::PointCloud<pcl::PointXYZ> ()); }, dir.file ("e.pcd"));
}

TEST (IoTest, NonFiniteCloudsAreRejectedByName)
{
  auto cloud = makeCloud ();
  morphreg::requireFiniteNonEmpty (cloud, "target");
  cloud[3].y = std::numeric_limits<float>::quiet_NaN ();
  expectErrorNaming<morphreg::InvalidInputError> ([&] { morphreg::requireFiniteNonEmpty (cloud, "target"); },
                                                  "point 3");
  expectErrorNaming<morphreg::InvalidInputError> (
      [&] { morphreg::requireFiniteNonEmpty (pcl::PointCloud<pcl::PointXYZ> (), "source"); }, "source");
}

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/file_format.h>
#include <morphreg/io/mesh_io.h>

#include "support/expect_error.h"
#include "support/temp_directory.h"
#include "support/text_file.h"
#include "support/test_meshes.h"

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <filesystem>
#include <fstream>

using morphreg::FileFormat;
using morphreg::test::expectErrorContaining;
using morphreg::test::TempDirectory;
using morphreg::test::writeText;

namespace
{
/** A binary STL of \a triangles zero triangles whose 80-byte header starts with \a header_text. */
std::string
binaryStl (std::uint32_t triangles, const std::string& header_text)
{
  std::string bytes = header_text;
  bytes.resize (80, ' ');
  for (int i = 0; i < 4; ++i)
    bytes.push_back (static_cast<char> ((triangles >> (8 * i)) & 0xffu));
  return bytes + std::string (50 * triangles, '\0');
}

pcl::PointCloud<pcl::PointXYZ>
threePoints ()
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  cloud.push_back ({0.0f, 0.0f, 0.0f});
  cloud.push_back ({1.0f, 0.0f, 0.0f});
  cloud.push_back ({0.0f, 1.0f, 0.0f});
  return cloud;
}
} // namespace

TEST (FileFormatTest, RecognisesEveryFormatFromItsContentWhateverTheName)
{
  TempDirectory dir;
  pcl::io::savePLYFileBinary (dir.file ("binary_ply.dat"), threePoints ());
  pcl::io::savePLYFileASCII (dir.file ("ascii_ply.dat"), threePoints ());
  pcl::io::savePCDFileBinaryCompressed (dir.file ("pcd.dat"), threePoints ());
  writeText (dir.file ("commented_pcd.dat"), "# .PCD v0.7 - Point Cloud Data file format\nVERSION 0.7\n");
  writeText (dir.file ("obj.dat"), "# a comment\n\nmtllib m.mtl\nv 0 0 0\n");
  writeText (dir.file ("ascii_stl.dat"), "  solid cube\nendsolid cube\n");
  writeText (dir.file ("binary_stl.dat"), binaryStl (2, "binary STL"));
  writeText (dir.file ("solid_binary_stl.dat"), binaryStl (3, "solid, but binary"));
  writeText (dir.file ("vtk.dat"), "# vtk DataFile Version 3.0\nmesh\nASCII\n");
  writeText (dir.file ("off.dat"), "# comment\nOFF\n3 1 0\n");
  writeText (dir.file ("coff.dat"), "COFF\n3 1 0\n");
  writeText (dir.file ("text.dat"), "this is not a mesh\n");
  writeText (dir.file ("comments_only.dat"), "# v 1 2 3\n");
  writeText (dir.file ("short_binary_stl.dat"), binaryStl (2, "binary STL").substr (0, 150));
  const std::pair<const char*, FileFormat> expected[] = {{"binary_ply.dat", FileFormat::Ply},
                                                         {"ascii_ply.dat", FileFormat::Ply},
                                                         {"pcd.dat", FileFormat::Pcd},
                                                         {"commented_pcd.dat", FileFormat::Pcd},
                                                         {"obj.dat", FileFormat::Obj},
                                                         {"ascii_stl.dat", FileFormat::StlAscii},
                                                         {"binary_stl.dat", FileFormat::StlBinary},
                                                         {"solid_binary_stl.dat", FileFormat::StlBinary},
                                                         {"vtk.dat", FileFormat::VtkLegacy},
                                                         {"off.dat", FileFormat::Off},
                                                         {"coff.dat", FileFormat::Off},
                                                         {"text.dat", FileFormat::Unknown},
                                                         {"comments_only.dat", FileFormat::Unknown},
                                                         {"short_binary_stl.dat", FileFormat::Unknown}};
  for (const auto& [name, format] : expected)
    EXPECT_EQ (morphreg::sniffFileFormat (dir.file (name)), format) << name;
  expectErrorContaining<morphreg::IoError> ([&] { morphreg::sniffFileFormat (dir.file ("missing.ply")); },
                                            "missing.ply: cannot be opened");
}

TEST (FileFormatTest, NamesAndExtensions)
{
  EXPECT_EQ (morphreg::fileFormatName (FileFormat::Ply), "PLY");
  EXPECT_EQ (morphreg::fileFormatName (FileFormat::StlBinary), "STL");
  EXPECT_EQ (morphreg::fileFormatName (FileFormat::VtkLegacy), "VTK");
  EXPECT_EQ (morphreg::fileFormatName (FileFormat::Unknown), "unknown");
  EXPECT_EQ (morphreg::fileFormatExtension (FileFormat::StlAscii), ".stl");
  EXPECT_EQ (morphreg::fileFormatExtension (FileFormat::VtkLegacy), ".vtk");
  EXPECT_EQ (morphreg::fileFormatExtension (FileFormat::Pcd), ".pcd");
  EXPECT_EQ (morphreg::fileFormatExtension (FileFormat::Unknown), "");
}

TEST (FileFormatTest, ARenamedFileIsRejectedNamingBothFormats)
{
  TempDirectory dir;
  morphreg::saveTriangleMesh (dir.file ("head.ply"), morphreg::test::makeCube ());
  std::filesystem::copy_file (dir.file ("head.ply"), dir.file ("scan.pcd"));
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadCloud<pcl::PointXYZ> (dir.file ("scan.pcd")); },
                                                "scan.pcd: the content is a PLY file, not PCD; rename it to .ply");
  pcl::io::savePCDFileBinary (dir.file ("cloud.pcd"), threePoints ());
  std::filesystem::copy_file (dir.file ("cloud.pcd"), dir.file ("mesh.obj"));
  expectErrorContaining<morphreg::FormatError> (
      [&] { morphreg::loadPolygonMesh (dir.file ("mesh.obj")); },
      "mesh.obj: the content is a PCD file, not OBJ; a mesh must be one of .ply .obj .vtk .stl .off");
  writeText (dir.file ("garbage.ply"), "this is not a mesh\nat all\n");
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadPolygonMesh (dir.file ("garbage.ply")); },
                                                "garbage.ply: the content is none of the supported");
  writeText (dir.file ("cut.stl"), binaryStl (4, "binary STL").substr (0, 200));
  expectErrorContaining<morphreg::FormatError> (
      [&] { morphreg::loadPolygonMesh (dir.file ("cut.stl")); },
      "cut.stl: not an STL file: it does not start with 'solid' (ASCII STL), and its 200 bytes are not the 84 + 50 x "
      "4 = 284 bytes");
}

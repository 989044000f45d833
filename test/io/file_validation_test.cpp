// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/file_validation.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>

#include "support/expect_error.h"
#include "support/temp_directory.h"
#include "support/text_file.h"
#include "support/test_meshes.h"

#include <gtest/gtest.h>
#include <pcl/io/obj_io.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/io/vtk_io.h>
#include <pcl/io/vtk_lib_io.h>

#include <algorithm>
#include <cstring>
#include <limits>
#include <filesystem>
#include <fstream>
#include <iterator>

using morphreg::FileFormat;
using morphreg::test::expectErrorContaining;
using morphreg::test::readBytes;
using morphreg::test::TempDirectory;
using morphreg::test::writeText;

namespace
{
pcl::PointCloud<pcl::PointNormal>
makeCloud (int n)
{
  pcl::PointCloud<pcl::PointNormal> cloud;
  for (int i = 0; i < n; ++i) {
    pcl::PointNormal p;
    p.getVector3fMap () = Eigen::Vector3f (0.5f * i, -1.0f * i, 100.0f + i);
    p.getNormalVector3fMap () = Eigen::Vector3f (0.0f, 0.6f, 0.8f);
    p.curvature = 0.0f;
    cloud.push_back (p);
  }
  return cloud;
}

/** Expects validateGeometryFile to reject \a name (written with \a text in \a dir) with \a fragment. */
void
expectRejected (const TempDirectory& dir, const std::string& name, const std::string& text, const std::string& fragment)
{
  writeText (dir.file (name), text);
  SCOPED_TRACE (name);
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::validateGeometryFile (dir.file (name)); },
                                                name + fragment);
}

const std::string ply_cube_header = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                    "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                    "end_header\n";
const std::string pcd_fields = "VERSION .7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
const std::string pcd_xyz_header = pcd_fields + "WIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 2\n";
} // namespace

TEST (FileValidationTest, FilesWrittenByPclAndVtkPassAndLoad)
{
  TempDirectory dir;
  const pcl::PolygonMesh cube = morphreg::toPolygonMesh (morphreg::test::makeCube (10.0));
  const auto cloud = makeCloud (40);
  pcl::io::savePLYFileBinary (dir.file ("binary.ply"), cube);
  pcl::io::savePLYFile (dir.file ("ascii.ply"), cube);
  pcl::io::savePCDFileASCII (dir.file ("ascii.pcd"), cloud);
  pcl::io::savePCDFileBinary (dir.file ("binary.pcd"), cloud);
  pcl::io::savePCDFileBinaryCompressed (dir.file ("compressed.pcd"), cloud);
  pcl::io::saveOBJFile (dir.file ("mesh.obj"), cube);
  pcl::io::saveVTKFile (dir.file ("classic.vtk"), cube);
  pcl::io::savePolygonFileVTK (dir.file ("binary.vtk"), cube, true);
  pcl::io::savePolygonFileVTK (dir.file ("ascii.vtk"), cube, false);
  pcl::io::savePolygonFileSTL (dir.file ("binary.stl"), cube, true);
  pcl::io::savePolygonFileSTL (dir.file ("ascii.stl"), cube, false);
  const std::pair<const char*, FileFormat> expected[] = {
      {"binary.ply", FileFormat::Ply},        {"ascii.ply", FileFormat::Ply},
      {"ascii.pcd", FileFormat::Pcd},         {"binary.pcd", FileFormat::Pcd},
      {"compressed.pcd", FileFormat::Pcd},    {"mesh.obj", FileFormat::Obj},
      {"classic.vtk", FileFormat::VtkLegacy}, {"binary.vtk", FileFormat::VtkLegacy},
      {"ascii.vtk", FileFormat::VtkLegacy},   {"binary.stl", FileFormat::StlBinary},
      {"ascii.stl", FileFormat::StlAscii}};
  for (const auto& [name, format] : expected) {
    EXPECT_EQ (morphreg::validateGeometryFile (dir.file (name)), format) << name;
    if (std::string (name).find (".pcd") != std::string::npos)
      EXPECT_EQ (morphreg::loadCloud<pcl::PointNormal> (dir.file (name))->size (), 40u) << name;
    else
      EXPECT_EQ (morphreg::loadPolygonMesh (dir.file (name)).polygons.size (), 12u) << name;
  }
}

TEST (FileValidationTest, EveryCutOfABinaryPlyOrPcdIsRejected)
{
  TempDirectory dir;
  morphreg::saveTriangleMesh (dir.file ("mesh.ply"), morphreg::test::makeCube ());
  morphreg::saveCloud (dir.file ("cloud.pcd"), makeCloud (20));
  morphreg::saveCloud (dir.file ("cloud.ply"), makeCloud (20));
  for (const std::string name : {"mesh.ply", "cloud.pcd", "cloud.ply"}) {
    const std::string bytes = readBytes (dir.file (name));
    const std::string cut = dir.file ("cut_" + name);
    for (std::size_t size = 1; size < bytes.size (); ++size) {
      writeText (cut, bytes.substr (0, size));
      SCOPED_TRACE (name + " cut to " + std::to_string (size) + " bytes");
      expectErrorContaining<morphreg::FormatError> ([&] { morphreg::validateGeometryFile (cut); }, cut);
      expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadCloud<pcl::PointXYZ> (cut); }, cut);
    }
  }
}

TEST (FileValidationTest, HeadersClaimingMoreThanTheFileHoldsAreRejectedBeforeAnyAllocation)
{
  TempDirectory dir;
  expectRejected (dir, "huge.ply",
                  "ply\nformat binary_little_endian 1.0\nelement vertex 2000000000\nproperty float x\n"
                  "property float y\nproperty float z\nend_header\n0123456789ab",
                  ": header claims 2000000000 'vertex' elements (at least 24 GB) but the file holds 12 bytes");
  expectRejected (dir, "huge_ascii.ply",
                  "ply\nformat ascii 1.0\nelement vertex 2000000000\nproperty float x\nend_header\n1\n",
                  ": header claims 2000000000 'vertex' elements");
  expectRejected (dir, "huge.pcd", pcd_fields + "WIDTH 2000000000\nHEIGHT 1\nPOINTS 2000000000\nDATA binary\n0123",
                  ": header claims 2000000000 points (at least 24 GB) but the file holds 4 bytes");
  expectRejected (dir, "huge_ascii.pcd",
                  pcd_fields + "WIDTH 2000000000\nHEIGHT 1\nPOINTS 2000000000\nDATA ascii\n1 2 3\n",
                  ": header claims 2000000000 points");
  expectRejected (dir, "huge.off", "OFF\n2000000000 1 0\n0 0 0\n", ": header claims 2000000000 vertices");
  expectRejected (dir, "huge.vtk",
                  "# vtk DataFile Version 3.0\nm\nASCII\nDATASET POLYDATA\nPOINTS 2000000000 float\n0 0 0\n",
                  ": header claims 2000000000 points");
  expectRejected (
      dir, "huge_cells.vtk",
      "# vtk DataFile Version 3.0\nm\nASCII\nDATASET POLYDATA\nPOINTS 1 float\n0 0 0\nPOLYGONS 1 2000000000\n",
      ": header claims 2000000000 POLYGONS values");
}

TEST (FileValidationTest, MalformedPlyIsRejectedWithTheLine)
{
  TempDirectory dir;
  const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
  expectRejected (dir, "word.ply", ply_cube_header + "0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n",
                  ":11: property 'y' value 'zero' is not a finite number");
  expectRejected (dir, "short_row.ply", ply_cube_header + "0 0 0\n1 0\n0 1 0\n3 0 1 2\n",
                  ":11: 'vertex' row 1 has too few");
  expectRejected (dir, "long_row.ply", ply_cube_header + vertices + "3 0 1 2 7\n",
                  ":13: 'face' row 0 has 5 values, expected 4");
  expectRejected (dir, "index.ply", ply_cube_header + vertices + "3 0 1 3\n",
                  ":13: face 0 has vertex index 3, outside [0, 3)");
  expectRejected (dir, "list.ply", ply_cube_header + vertices + "9 0 1 2\n", ":13: list 'vertex_indices' count '9'");
  expectRejected (dir, "rows.ply", ply_cube_header + vertices, ": header claims 1 'face' elements");
  expectRejected (dir, "face_cut.ply", ply_cube_header + vertices + "\n\n\n",
                  ":13: 'face' row 0 has too few values (0)");
  expectRejected (dir, "type.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float3 x\nend_header\n",
                  ":4: unknown PLY property type 'float3'");
  expectRejected (dir, "format.ply", "ply\nformat binary 1.0\n", ":2: the format line must be");
  expectRejected (dir, "no_end.ply", "ply\nformat ascii 1.0\nelement vertex 1\n", ": the PLY header has no end_header");

  // Binary: an out-of-range face index, and a negative list count.
  const pcl::PolygonMesh cube = morphreg::toPolygonMesh (morphreg::test::makeCube ());
  pcl::io::savePLYFileBinary (dir.file ("cube.ply"), cube);
  std::string bytes = readBytes (dir.file ("cube.ply"));
  const std::size_t last_index = bytes.size () - 4;
  bytes[last_index] = 8; // the last face's last corner names vertex 8 of 8
  expectRejected (dir, "binary_index.ply", bytes, ": face 11 has vertex index 8, outside [0, 8)");
  bytes[last_index - 9] = static_cast<char> (0xff); // the last face's uchar count: 255 corners overrun the file
  expectRejected (dir, "binary_list.ply", bytes, ": the file ends inside 'face' row 11 of 12");
}

/** Vertex layouts that made PCL's PLY reader abort (assertions on writes outside its buffers), refused first. */
TEST (FileValidationTest, PlyVertexLayoutsPclCannotReadAreRejected)
{
  TempDirectory dir;
  const std::string start = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\n"
                            "property float z\n";
  expectRejected (dir, "vertex_list.ply", start + "property list uchar int vertex_indices\nend_header\n0 0 0 1 0\n",
                  ": the PLY vertex element has the list property 'vertex_indices'");
  expectRejected (dir, "blue_only.ply", start + "property uchar blue\nend_header\n0 0 0 9\n",
                  ": the PLY vertex colour property 'blue' is out of order");
  expectRejected (dir, "red_green.ply", start + "property uchar red\nproperty uchar green\nend_header\n0 0 0 1 2\n",
                  ": the PLY vertex colours are incomplete");
  expectRejected (dir, "twice.ply", start + "property float x\nend_header\n0 0 0 0\n",
                  ": the PLY vertex element has the property 'x' twice");
  expectRejected (dir, "two_vertex_elements.ply", start + "element vertex 1\nproperty float x\nend_header\n0 0 0\n0\n",
                  ": PLY element 'vertex' is declared twice");
  expectRejected (dir, "indented.ply", start + "\t obj_info num_cols 1\nend_header\n0 0 0\n",
                  ":7: a PLY header line starts with white space");
  // Colours as PCL writes them, and alpha after them, pass.
  const std::string coloured = start + "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                                       "property uchar alpha\nend_header\n0 0 0 1 2 3 4\n";
  std::ofstream (dir.file ("coloured.ply")) << coloured;
  EXPECT_NO_THROW (morphreg::validateGeometryFile (dir.file ("coloured.ply")));
}

TEST (FileValidationTest, MalformedPcdIsRejectedWithTheLine)
{
  TempDirectory dir;
  const std::string ascii = pcd_xyz_header + "DATA ascii\n";
  EXPECT_EQ (morphreg::validateGeometryFile (
                 (writeText (dir.file ("nan.pcd"), ascii + "nan nan nan\n1 2 3\n"), dir.file ("nan.pcd"))),
             FileFormat::Pcd)
      << "NaN is how PCL writes invalid points";
  expectRejected (dir, "word.pcd", ascii + "0 0 0\n1 two 3\n", ":12: value 'two' of point 1 is not a number");
  expectRejected (dir, "short.pcd", ascii + "0 0 0\n1.5 2.5\n", ":12: point 1 has 2 values, expected 3");
  expectRejected (dir, "small.pcd", ascii + "0 0 0\n",
                  ": header claims 2 points (at least 12 bytes) but the file holds 6 bytes");
  expectRejected (dir, "cut.pcd", ascii + "0.000 0.000 0.000\n", ": the file ends after 1 of its 2 points");
  expectRejected (dir, "width.pcd", pcd_fields + "WIDTH 3\nHEIGHT 1\nPOINTS 2\nDATA ascii\n0 0 0\n1 2 3\n",
                  ": the PCD header's WIDTH 3 times HEIGHT 1 is not its POINTS 2");
  expectRejected (dir, "fields.pcd",
                  "VERSION .7\nFIELDS x y z\nSIZE 4 4\nTYPE F F F\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n0 0 0\n",
                  ": the PCD header lists 3 FIELDS but 2 SIZE");
  expectRejected (dir, "type.pcd", "VERSION .7\nFIELDS x\nSIZE 2\nTYPE F\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n0\n",
                  ": PCD field 'x' has TYPE F and SIZE 2");
  expectRejected (dir, "data.pcd", pcd_xyz_header + "DATA text\n", ":10: the DATA line must be");
  expectRejected (dir, "no_data.pcd", pcd_xyz_header, ": the PCD header has no DATA line");
  expectRejected (dir, "keyword.pcd", "VERSION .7\nFIELD x\n", ":2: unexpected PCD header line");

  // binary_compressed: the sizes before the data lie about the file or about POINTS.
  pcl::io::savePCDFileBinaryCompressed (dir.file ("compressed.pcd"), makeCloud (50));
  const std::string bytes = readBytes (dir.file ("compressed.pcd"));
  const std::size_t sizes = bytes.find ("DATA binary_compressed\n") + 23;
  const auto withSize = [&] (std::size_t at, std::uint32_t value) {
    std::string patched = bytes;
    for (int i = 0; i < 4; ++i)
      patched[at + i] = static_cast<char> ((value >> (8 * i)) & 0xffu);
    return patched;
  };
  expectRejected (dir, "compressed_long.pcd", withSize (sizes, 1u << 30),
                  ": the compressed PCD data claims 1073741824 bytes but the file holds");
  expectRejected (dir, "compressed_unpacked.pcd", withSize (sizes + 4, 4000000000u),
                  ": the compressed PCD data unpacks to 4000000000 bytes but POINTS 50");
  expectRejected (dir, "compressed_cut.pcd", bytes.substr (0, sizes + 6), ": the compressed PCD data has no sizes");
}

TEST (FileValidationTest, MalformedObjIsRejectedWithTheLine)
{
  TempDirectory dir;
  const std::string triangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  writeText (dir.file ("good.obj"), "# comment\no name\n" + triangle +
                                        "vt 0.5\nvt 0 1 0\nvn 0 0 1\n"
                                        "s off\nusemtl skin\nf 1/1/1 2//1 -1/2\nf -3 -2 -1\nl 1 2\n");
  EXPECT_EQ (morphreg::validateGeometryFile (dir.file ("good.obj")), FileFormat::Obj);
  EXPECT_EQ (morphreg::loadPolygonMesh (dir.file ("good.obj")).polygons.size (), 2u);
  expectRejected (dir, "short_vertex.obj", "v 0 0 0\nv 1 0 0\nv 1 2\nf 1 2 3\n",
                  ":3: vertex has 2 coordinates, expected 3 (x y z), 4 (x y z w) or 6 (x y z r g b)");
  expectRejected (dir, "not_a_number.obj", "v 0 0 x\n", ":1: vertex coordinate 'x' is not a finite number");
  expectRejected (dir, "inf.obj", "v 0 0 1e39\n", ":1: vertex coordinate '1e39' is not a finite number");
  expectRejected (dir, "tab.obj", "v\t0 0 0\n", ":1: separate 'v' from its coordinates with a space");
  expectRejected (dir, "normal.obj", triangle + "vn 0 1\n", ":4: vertex normal has 2 coordinates, expected 3");
  expectRejected (dir, "texture.obj", triangle + "vt\n", ":4: texture coordinate has 0 coordinates, expected 1 to 3");
  expectRejected (dir, "out_of_range.obj", triangle + "f 1 2 9\n", ":4: face vertex index 9 is beyond the file's 3");
  expectRejected (dir, "back.obj", triangle + "f 1 2 -4\n", ":4: face vertex index -4 refers back past the 3");
  expectRejected (dir, "zero.obj", triangle + "f 0 1 2\n", ":4: face vertex index '0' is not a nonzero whole");
  expectRejected (dir, "two.obj", triangle + "f 1 2\n", ":4: face has 2 corners, expected at least 3");
  expectRejected (dir, "slashes.obj", triangle + "f 1/1/1/1 2 3\n", ":4: face corner '1/1/1/1' has more than 3");
  expectRejected (dir, "texture_index.obj", triangle + "vt 0 0\nf 1/2 2/1 3/1\n",
                  ":5: face texture coordinate index 2 is beyond the file's 1");
  expectRejected (dir, "no_vertices.obj", "o empty\n", ": the OBJ file has no vertices");
}

TEST (FileValidationTest, MalformedStlIsRejectedWithTheLine)
{
  TempDirectory dir;
  const std::string facet = "facet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\n"
                            "endfacet\n";
  writeText (dir.file ("two_solids.stl"), "solid a\n" + facet + "endsolid a\n\nsolid b\n" + facet + "endsolid\n");
  EXPECT_EQ (morphreg::validateGeometryFile (dir.file ("two_solids.stl")), FileFormat::StlAscii);
  expectRejected (dir, "malformed.stl",
                  "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0\nvertex 0 1 0\nendloop\n"
                  "endfacet\nendsolid s\n",
                  ":5: vertex has 2 coordinates, expected 3");
  expectRejected (dir, "nan.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 nan\n",
                  ":4: vertex coordinate 'nan' is not a finite number");
  expectRejected (dir, "four.stl", "solid s\n" + facet.substr (0, 69) + "vertex 1 1 0\n",
                  ":7: expected 'endloop', found 'vertex 1 1 0'");
  expectRejected (dir, "normal.stl", "solid s\nfacet 0 0 1\n", ":2: expected 'facet normal nx ny nz'");
  expectRejected (dir, "cut.stl", "solid s\n" + facet.substr (0, 43), ": the file ends inside a facet");
  expectRejected (dir, "open.stl", "solid s\n" + facet, ": the STL file has no 'endsolid'");
  expectRejected (dir, "tail.stl", "solid s\nendsolid s\ngarbage\n", ":3: expected 'solid', found 'garbage'");
  // Bytes that are not text make VTK read the file as binary (and allocate for the count in bytes 80 to 83).
  expectRejected (dir, "control.stl", "solid\n\nendsolid\t{d\x03\x03\x03\x03\n\nsolid\n",
                  ":3: byte 3 is not text, in an ASCII STL file");
  expectRejected (dir, "high.stl", "solid s\xe9\nendsolid s\n", ":1: byte 233 is not text, in an ASCII STL file");
  expectRejected (dir, "blank.stl", "solid s\n" + facet + std::string (3, '\0') + "\nendsolid s\n",
                  ":9: byte 0 is not text, in an ASCII STL file");
}

TEST (FileValidationTest, MalformedVtkIsRejectedWithTheLine)
{
  TempDirectory dir;
  const std::string header = "# vtk DataFile Version 3.0\nhead\nASCII\nDATASET POLYDATA\n";
  const std::string points = "POINTS 3 float\n0 0 0 1 0 0\n0 1 0\n";
  const std::string attributes = "POINT_DATA 3\nNORMALS n float\n0 0 1 0 0 1 0 0 1\nSCALARS s float 1\n"
                                 "LOOKUP_TABLE default\n1 2 3\nFIELD f 1\nq 2 3 double\n1 2 3 4 5 6\nCELL_DATA 1\n"
                                 "COLOR_SCALARS c 3\n0.5 0.5 nan\n";
  writeText (dir.file ("good.vtk"), header + points + "POLYGONS 1 4\n3 0 1 2\n" + attributes);
  EXPECT_EQ (morphreg::validateGeometryFile (dir.file ("good.vtk")), FileFormat::VtkLegacy);
  expectRejected (dir, "normals.vtk",
                  header + points + "POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nNORMALS n float\n0 0 1 0 0\n",
                  ": header claims 9 NORMALS values");
  expectRejected (dir, "scalars.vtk", header + points + "POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nSCALARS s float\n1 2 3\n",
                  ":12: expected 'LOOKUP_TABLE <name>' after SCALARS");
  expectRejected (dir, "attribute.vtk", header + points + "POLYGONS 1 4\n3 0 1 2\nPOINT_DATA 3\nGLOBAL_IDS g int\n",
                  ":11: unexpected 'GLOBAL_IDS g int' among the attributes");
  expectRejected (dir, "too_few_points.vtk", header + "POINTS 1000 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 2\n",
                  ": header claims 1000 points");
  expectRejected (dir, "few_points.vtk", header + "POINTS 4 float\n0 0 0 1 0 0 0 1 0\nPOLYGONS 1 4\n3 0 1 2\n",
                  ":7: point coordinate value 'POLYGONS' is not a number");
  expectRejected (dir, "index.vtk", header + points + "POLYGONS 1 4\n3 0 1 3\n",
                  ":9: POLYGONS index 3 is outside the 3 points");
  expectRejected (dir, "size.vtk", header + points + "POLYGONS 1 5\n3 0 1 2\n7\n",
                  ":9: the POLYGONS cells hold 4 values but the section's header claims 5");
  expectRejected (dir, "corners.vtk", header + points + "POLYGONS 1 4\n4 0 1 2 0\n",
                  ":9: POLYGONS cell 0 has 4 indices");
  expectRejected (dir, "extra.vtk", header + points + "POLYGONS 1 4\n3 0 1 2 2\n",
                  ":9: '2' is one value more than the section's header claims");
  expectRejected (dir, "grid.vtk", "# vtk DataFile Version 3.0\nh\nASCII\nDATASET UNSTRUCTURED_GRID\n",
                  ":4: the dataset is UNSTRUCTURED_GRID; only POLYDATA");
  expectRejected (dir, "encoding.vtk", "# vtk DataFile Version 3.0\nh\nXML\n",
                  ":3: the third line must be ASCII or BINARY");
  expectRejected (dir, "no_points.vtk", header, ": the VTK file has no POINTS");
  expectRejected (dir, "cells_first.vtk", header + "POLYGONS 1 4\n3 0 1 2\n",
                  ":5: unexpected 'POLYGONS 1 4' before POINTS");
  expectRejected (dir, "offsets.vtk",
                  "# vtk DataFile Version 5.1\nh\nASCII\nDATASET POLYDATA\n" + points +
                      "POLYGONS 2 3\nOFFSETS vtktypeint64\n0 4\nCONNECTIVITY vtktypeint64\n0 1 2\n",
                  ":10: POLYGONS offset 1 is 4; offsets must start at 0 and rise to the connectivity size 3");

  // BINARY, as VTK writes it: every cut is rejected.
  pcl::io::savePolygonFileVTK (dir.file ("binary.vtk"), morphreg::toPolygonMesh (morphreg::test::makeCube ()), true);
  const std::string bytes = readBytes (dir.file ("binary.vtk"));
  const std::size_t cells = bytes.find ("POLYGONS");
  for (const std::size_t size : {cells - 30, cells + 40, bytes.size () - 20}) {
    writeText (dir.file ("cut.vtk"), bytes.substr (0, size));
    for (const std::string& fragment : {dir.file ("cut.vtk: "), std::string ("cut short")})
      expectErrorContaining<morphreg::FormatError> ([&] { morphreg::validateGeometryFile (dir.file ("cut.vtk")); },
                                                    fragment);
  }
}

namespace
{
/** \a value's bytes, most significant first, as a BINARY VTK file holds them. */
template <typename T>
std::string
bigEndian (T value)
{
  char bytes[sizeof (T)];
  std::memcpy (bytes, &value, sizeof (T));
  std::reverse (bytes, bytes + sizeof (T));
  return std::string (bytes, sizeof (T));
}

void
expectSameMesh (const pcl::PolygonMesh& expected, const pcl::PolygonMesh& actual, const std::string& name)
{
  SCOPED_TRACE (name);
  pcl::PointCloud<pcl::PointXYZ> expected_points, actual_points;
  pcl::fromPCLPointCloud2 (expected.cloud, expected_points);
  pcl::fromPCLPointCloud2 (actual.cloud, actual_points);
  ASSERT_EQ (actual_points.size (), expected_points.size ());
  for (std::size_t i = 0; i < expected_points.size (); ++i)
    EXPECT_EQ (actual_points[i].getVector3fMap (), expected_points[i].getVector3fMap ()) << "point " << i;
  ASSERT_EQ (actual.polygons.size (), expected.polygons.size ());
  for (std::size_t p = 0; p < expected.polygons.size (); ++p)
    EXPECT_EQ (actual.polygons[p].vertices, expected.polygons[p].vertices) << "polygon " << p;
}
} // namespace

TEST (FileValidationTest, OwnVtkReaderReadsWhatVtksReaderReads)
{
  TempDirectory dir;
  const pcl::PolygonMesh cube = morphreg::toPolygonMesh (morphreg::test::makeCube (10.0));
  pcl::io::saveVTKFile (dir.file ("classic.vtk"), cube);             // format 3, ASCII, PCL's own writer
  pcl::io::savePolygonFileVTK (dir.file ("binary.vtk"), cube, true); // VTK's writer: format 5, OFFSETS
  pcl::io::savePolygonFileVTK (dir.file ("ascii.vtk"), cube, false);
  for (const std::string name : {"classic.vtk", "binary.vtk", "ascii.vtk"}) {
    pcl::PolygonMesh by_vtk;
    ASSERT_GT (pcl::io::loadPolygonFile (dir.file (name), by_vtk), 0) << name;
    expectSameMesh (by_vtk, morphreg::loadPolygonMesh (dir.file (name)), name);
  }
}

TEST (FileValidationTest, OwnVtkReaderCutsStripsAndReadsEveryBinaryType)
{
  TempDirectory dir;
  const std::string header = "# vtk DataFile Version 3.0\nhead\n";
  writeText (dir.file ("strip.vtk"), header + "ASCII\nDATASET POLYDATA\nPOINTS 5 float\n0 0 0 1 0 0 0 1 0 1 1 0 "
                                              "2 1 0\nLINES 1 3\n2 0 1\nTRIANGLE_STRIPS 1 6\n5 0 1 2 3 4\n");
  const pcl::PolygonMesh strip = morphreg::loadPolygonMesh (dir.file ("strip.vtk"));
  ASSERT_EQ (strip.polygons.size (), 3u); // the line is not kept; the strip's triangles keep its orientation
  EXPECT_EQ (strip.polygons[0].vertices, (pcl::Indices{0, 1, 2}));
  EXPECT_EQ (strip.polygons[1].vertices, (pcl::Indices{2, 1, 3}));
  EXPECT_EQ (strip.polygons[2].vertices, (pcl::Indices{2, 3, 4}));

  std::string doubles = header + "BINARY\nDATASET POLYDATA\nPOINTS 3 double\n";
  for (const double value : {0.0, 0.0, 0.0, 1.5, 0.0, 0.0, 0.0, -2.25, 7.0})
    doubles += bigEndian (value);
  const std::string triangle = "\nPOLYGONS 1 4\n" + bigEndian<std::int32_t> (3) + bigEndian<std::int32_t> (0) +
                               bigEndian<std::int32_t> (1) + bigEndian<std::int32_t> (2) + "\n";
  writeText (dir.file ("doubles.vtk"), doubles + triangle);
  pcl::PointCloud<pcl::PointXYZ> points;
  pcl::fromPCLPointCloud2 (morphreg::loadPolygonMesh (dir.file ("doubles.vtk")).cloud, points);
  ASSERT_EQ (points.size (), 3u);
  EXPECT_EQ (points[1].x, 1.5f);
  EXPECT_EQ (points[2].getVector3fMap (), Eigen::Vector3f (0.0f, -2.25f, 7.0f));

  std::string shorts = header + "BINARY\nDATASET POLYDATA\nPOINTS 3 short\n";
  for (const std::int16_t value : {0, 0, 0, -300, 0, 0, 0, 2, 1})
    shorts += bigEndian (value);
  writeText (dir.file ("shorts.vtk"), shorts + triangle);
  pcl::fromPCLPointCloud2 (morphreg::loadPolygonMesh (dir.file ("shorts.vtk")).cloud, points);
  EXPECT_EQ (points[1].x, -300.0f);

  std::string nan = header + "BINARY\nDATASET POLYDATA\nPOINTS 3 float\n";
  for (int i = 0; i < 9; ++i)
    nan += bigEndian (i == 4 ? std::numeric_limits<float>::quiet_NaN () : 1.0f);
  writeText (dir.file ("nan.vtk"), nan + triangle);
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadPolygonMesh (dir.file ("nan.vtk")); },
                                                "nan.vtk: point 1 has a coordinate that is not a finite number");
  expectRejected (dir, "huge.vtk", header + "ASCII\nDATASET POLYDATA\nPOINTS 1 float\n0 1e39 0\n",
                  ":6: point 0 has a coordinate that is not a finite number");
}

TEST (FileValidationTest, EmptyFilesFoldersAndUnknownContentAreNamed)
{
  TempDirectory dir;
  writeText (dir.file ("empty.ply"), "");
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::validateGeometryFile (dir.file ("empty.ply")); },
                                                "empty.ply: file is empty");
  std::filesystem::create_directory (dir.file ("folder.ply"));
  expectErrorContaining<morphreg::IoError> ([&] { morphreg::validateGeometryFile (dir.file ("folder.ply")); },
                                            "folder.ply: is a directory");
  expectErrorContaining<morphreg::IoError> ([&] { morphreg::loadPolygonMesh (dir.file ("folder.ply")); },
                                            "folder.ply: is a directory");
  expectRejected (dir, "points.xyz", "0 0 0\n1 0 0\n", ": the content is none of the supported");
  expectRejected (dir, "bad_count.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n",
                  ":6: face 0 corner 7 is not a whole number in [0, 3)");
}

TEST (FileValidationTest, RealFilesOfTheSharedDataPassAndLoad)
{
  const std::filesystem::path data (MORPHREG_SHARED_DATA_DIR);
  if (!std::filesystem::exists (data / "real_head_scans"))
    GTEST_SKIP () << "shared data not found at " << data;
  for (const char* mesh : {"real_head_scans/leeperrysmith_head_mm.ply", "ict_facekit/ict_head_mean.ply",
                           "mediapipe_canonical_face/canonical_face_model.obj", "mne_fsaverage_head/fsaverage_head.ply",
                           "makehuman_bodies/mh_base.ply", "pcl_test/cube.ply"}) {
    SCOPED_TRACE (mesh);
    EXPECT_NO_THROW (morphreg::validateGeometryFile ((data / mesh).string ()));
    EXPECT_FALSE (morphreg::loadPolygonMesh ((data / mesh).string ()).polygons.empty ());
  }
  EXPECT_EQ (morphreg::loadCloud<pcl::PointNormal> ((data / "real_head_scans/leeperrysmith_scan_82k_mm.ply").string ())
                 ->size (),
             82360u);
  for (const auto& entry : std::filesystem::directory_iterator (data / "pcl_test"))
    if (entry.path ().extension () == ".pcd") {
      SCOPED_TRACE (entry.path ().string ());
      EXPECT_NO_THROW (morphreg::validateGeometryFile (entry.path ().string ()));
      EXPECT_FALSE (morphreg::loadCloud<pcl::PointXYZ> (entry.path ().string ())->empty ());
    }
}

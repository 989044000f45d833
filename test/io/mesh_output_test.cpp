// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>

#include "support/temp_directory.h"
#include "support/test_meshes.h"
#include "support/text_file.h"

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>

using morphreg::test::TempDirectory;

namespace
{
/** A cube whose eight vertices have distinct colours and residuals. */
struct ColouredCube
{
  morphreg::TriangleMesh mesh = morphreg::test::makeCube (10.0);
  Eigen::Matrix<unsigned char, 3, Eigen::Dynamic> colours;
  Eigen::VectorXd residuals;

  ColouredCube () : colours (3, mesh.numVertices ()), residuals (mesh.numVertices ())
  {
    for (Eigen::Index i = 0; i < mesh.numVertices (); ++i) {
      colours.col (i) << static_cast<unsigned char> (30 * i), static_cast<unsigned char> (255 - 20 * i),
          static_cast<unsigned char> (7 * i + 1);
      residuals[i] = 0.37 * static_cast<double> (i) + 0.01;
    }
  }
};

/** The header of a PLY file, up to end_header. */
std::string
plyHeader (const std::string& path)
{
  const std::string bytes = morphreg::test::readBytes (path);
  return bytes.substr (0, bytes.find ("end_header"));
}

/** The float field \a name of every point of \a cloud. */
std::vector<float>
floatField (const pcl::PCLPointCloud2& cloud, const std::string& name)
{
  const int field = pcl::getFieldIndex (cloud, name);
  EXPECT_GE (field, 0) << "no field " << name;
  std::vector<float> values (cloud.width * cloud.height);
  for (std::size_t i = 0; field >= 0 && i < values.size (); ++i)
    std::memcpy (&values[i], cloud.data.data () + i * cloud.point_step + cloud.fields[field].offset, sizeof (float));
  return values;
}

void
expectColours (const pcl::PolygonMesh& mesh, const ColouredCube& cube, const std::string& name)
{
  pcl::PointCloud<pcl::PointXYZRGB> points;
  pcl::fromPCLPointCloud2 (mesh.cloud, points);
  ASSERT_EQ (points.size (), static_cast<std::size_t> (cube.mesh.numVertices ())) << name;
  for (std::size_t i = 0; i < points.size (); ++i)
    EXPECT_EQ (Eigen::Vector3i (points[i].r, points[i].g, points[i].b), cube.colours.col (i).cast<int> ())
        << name << " vertex " << i;
}
} // namespace

TEST (MeshOutputTest, PlyCarriesColoursAndTheResidualAsQuality)
{
  TempDirectory dir;
  const ColouredCube cube;
  morphreg::savePolygonMesh (dir.file ("fit.ply"), morphreg::toPolygonMesh (cube.mesh, cube.colours, cube.residuals));
  const std::string header = plyHeader (dir.file ("fit.ply"));
  for (const char* property :
       {"property uchar red", "property uchar green", "property uchar blue", "property float quality"})
    EXPECT_NE (header.find (property), std::string::npos) << property << " missing from\n" << header;
  EXPECT_EQ (header.find ("curvature"), std::string::npos) << header;

  const pcl::PolygonMesh loaded = morphreg::loadPolygonMesh (dir.file ("fit.ply"));
  const std::vector<float> quality = floatField (loaded.cloud, "quality");
  ASSERT_EQ (quality.size (), 8u);
  for (std::size_t i = 0; i < quality.size (); ++i)
    EXPECT_FLOAT_EQ (quality[i], static_cast<float> (cube.residuals[i])) << "vertex " << i;
  expectColours (loaded, cube, "fit.ply");
  EXPECT_TRUE (morphreg::savedVertexData (dir.file ("fit.ply")).colours);
  EXPECT_TRUE (morphreg::savedVertexData (dir.file ("fit.ply")).quality);
}

TEST (MeshOutputTest, ColouredMeshWithoutValuesHasNoCurvatureField)
{
  const ColouredCube cube;
  const pcl::PolygonMesh mesh = morphreg::toPolygonMesh (cube.mesh, cube.colours);
  EXPECT_EQ (pcl::getFieldIndex (mesh.cloud, "curvature"), -1);
  EXPECT_EQ (pcl::getFieldIndex (mesh.cloud, "quality"), -1);
  EXPECT_GE (pcl::getFieldIndex (mesh.cloud, "rgb"), 0);
  EXPECT_GE (pcl::getFieldIndex (mesh.cloud, "normal_z"), 0);
}

TEST (MeshOutputTest, ObjCarriesColoursAsVxyzrgbLines)
{
  TempDirectory dir;
  const ColouredCube cube;
  morphreg::savePolygonMesh (dir.file ("fit.obj"), morphreg::toPolygonMesh (cube.mesh, cube.colours, cube.residuals));
  std::istringstream text (morphreg::test::readBytes (dir.file ("fit.obj")));
  int vertex_lines = 0;
  for (std::string line; std::getline (text, line);)
    if (line.rfind ("v ", 0) == 0) {
      std::istringstream fields (line.substr (2));
      std::vector<double> values;
      for (double value; fields >> value;)
        values.push_back (value);
      ASSERT_EQ (values.size (), 6u) << line;
      for (int c = 0; c < 3; ++c)
        EXPECT_NEAR (values[3 + c], cube.colours (c, vertex_lines) / 255.0, 1e-6) << line;
      ++vertex_lines;
    }
  EXPECT_EQ (vertex_lines, 8);
  expectColours (morphreg::readObjFile (dir.file ("fit.obj")), cube, "fit.obj");
  EXPECT_TRUE (morphreg::savedVertexData (dir.file ("fit.obj")).colours);
  EXPECT_FALSE (morphreg::savedVertexData (dir.file ("fit.obj")).quality);

  morphreg::saveTriangleMesh (dir.file ("plain.obj"), cube.mesh); // no colours: v x y z
  const std::string plain = morphreg::test::readBytes (dir.file ("plain.obj"));
  EXPECT_NE (plain.find ("\nv 5 5 5\n"), std::string::npos) << plain;
}

TEST (MeshOutputTest, VtkCarriesWhatSavedVertexDataSays)
{
  TempDirectory dir;
  const ColouredCube cube;
  morphreg::savePolygonMesh (dir.file ("fit.vtk"), morphreg::toPolygonMesh (cube.mesh, cube.colours, cube.residuals));
  const std::string text = morphreg::test::readBytes (dir.file ("fit.vtk"));
  const morphreg::SavedVertexData kept = morphreg::savedVertexData (dir.file ("fit.vtk"));
  EXPECT_EQ (text.find ("COLOR_SCALARS") != std::string::npos, kept.colours) << text;
  EXPECT_EQ (text.find ("quality") != std::string::npos, kept.quality) << text;
  EXPECT_THROW (morphreg::savedVertexData (dir.file ("fit.stl")), morphreg::IoError);
}

TEST (MeshOutputTest, QualityNeedsOneValuePerVertex)
{
  const ColouredCube cube;
  EXPECT_THROW (morphreg::toPolygonMesh (cube.mesh, cube.colours, Eigen::VectorXd::Ones (3)),
                morphreg::InvalidInputError);
}

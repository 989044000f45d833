// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/common/cloud_matrix.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>

#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <sstream>

namespace morphreg
{
namespace
{
std::vector<pcl::Vertices>
toPolygons (const TriangleMesh::Triangles& triangles)
{
  std::vector<pcl::Vertices> polygons (triangles.cols ());
  for (Eigen::Index t = 0; t < triangles.cols (); ++t)
    polygons[t].vertices = {static_cast<pcl::index_t> (triangles (0, t)), static_cast<pcl::index_t> (triangles (1, t)),
                            static_cast<pcl::index_t> (triangles (2, t))};
  return polygons;
}

template <typename PointT>
void
setPositionAndNormal (PointT& p, const Eigen::Vector3d& position, const Eigen::Vector3d& normal)
{
  p.getVector3fMap () = position.cast<float> ();
  p.getNormalVector3fMap () = normal.cast<float> ();
  p.curvature = 0.0f;
}
/** PointXYZRGBNormal's curvature field, which nothing computes, renamed \a name (its values set by the caller) or,
 *  for an empty name, dropped from the field list (its bytes stay as padding, which PCL's writers skip). */
void
giveCurvatureTo (const std::string& name, pcl::PCLPointCloud2& cloud)
{
  const auto curvature = std::find_if (cloud.fields.begin (), cloud.fields.end (),
                                       [] (const pcl::PCLPointField& field) { return field.name == "curvature"; });
  if (curvature == cloud.fields.end ())
    return;
  if (name.empty ())
    cloud.fields.erase (curvature);
  else
    curvature->name = name;
}
} // namespace

TriangleMesh
fromPolygonMesh (const pcl::PolygonMesh& mesh, const std::string& name)
{
  bool has_xyz[3] = {false, false, false};
  for (const auto& field : mesh.cloud.fields)
    for (int k = 0; k < 3; ++k)
      has_xyz[k] = has_xyz[k] || field.name == std::string (1, "xyz"[k]);
  if (!(has_xyz[0] && has_xyz[1] && has_xyz[2]))
    throw InvalidInputError (name + ": the mesh's vertex cloud has no x/y/z fields");

  pcl::PointCloud<pcl::PointXYZ> cloud;
  pcl::fromPCLPointCloud2 (mesh.cloud, cloud);
  TriangleMesh result;
  result.vertices = pointsOf (cloud);
  result.triangles.resize (3, static_cast<Eigen::Index> (mesh.polygons.size ()));
  for (size_t t = 0; t < mesh.polygons.size (); ++t) {
    const auto& vertices = mesh.polygons[t].vertices;
    if (vertices.size () != 3) {
      std::ostringstream msg;
      msg << name << ": polygon " << t << " has " << vertices.size ()
          << " vertices; only triangle meshes are supported";
      throw InvalidInputError (msg.str ());
    }
    for (int c = 0; c < 3; ++c)
      result.triangles (c, t) = static_cast<int> (vertices[c]);
  }
  return result;
}

pcl::PolygonMesh
toPolygonMesh (const TriangleMesh& mesh)
{
  const Eigen::Matrix3Xd normals = vertexNormals (mesh);
  pcl::PointCloud<pcl::PointNormal> cloud;
  cloud.resize (mesh.numVertices ());
  for (Eigen::Index i = 0; i < mesh.numVertices (); ++i)
    setPositionAndNormal (cloud[i], mesh.vertices.col (i), normals.col (i));
  pcl::PolygonMesh result;
  pcl::toPCLPointCloud2 (cloud, result.cloud);
  result.polygons = toPolygons (mesh.triangles);
  return result;
}

pcl::PolygonMesh
toPolygonMesh (const TriangleMesh& mesh, const Eigen::Matrix<unsigned char, 3, Eigen::Dynamic>& colours)
{
  return toPolygonMesh (mesh, colours, Eigen::VectorXd ());
}

pcl::PolygonMesh
toPolygonMesh (const TriangleMesh& mesh, const Eigen::Matrix<unsigned char, 3, Eigen::Dynamic>& colours,
               const Eigen::VectorXd& quality)
{
  if (colours.cols () != mesh.numVertices ())
    throw InvalidInputError ("toPolygonMesh: one colour per vertex required, got " + std::to_string (colours.cols ()) +
                             " for " + std::to_string (mesh.numVertices ()) + " vertices");
  if (quality.size () != 0 && quality.size () != mesh.numVertices ())
    throw InvalidInputError ("toPolygonMesh: one quality value per vertex required, got " +
                             std::to_string (quality.size ()) + " for " + std::to_string (mesh.numVertices ()) +
                             " vertices");
  const Eigen::Matrix3Xd normals = vertexNormals (mesh);
  pcl::PointCloud<pcl::PointXYZRGBNormal> cloud;
  cloud.resize (mesh.numVertices ());
  for (Eigen::Index i = 0; i < mesh.numVertices (); ++i) {
    setPositionAndNormal (cloud[i], mesh.vertices.col (i), normals.col (i));
    cloud[i].r = colours (0, i);
    cloud[i].g = colours (1, i);
    cloud[i].b = colours (2, i);
    if (quality.size () != 0)
      cloud[i].curvature = static_cast<float> (quality[i]);
  }
  pcl::PolygonMesh result;
  pcl::toPCLPointCloud2 (cloud, result.cloud);
  giveCurvatureTo (quality.size () != 0 ? "quality" : "", result.cloud);
  result.polygons = toPolygons (mesh.triangles);
  return result;
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include "obj_content.h"
#include "polygon_file.h"

#include <morphreg/io/coloured_surface_io.h>
#include <morphreg/io/file_validation.h>
#include <morphreg/io/gltf_reader.h>
#include <morphreg/io/pcd_reader.h>

#include <pcl/PCLPointField.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>

namespace morphreg
{
namespace
{
bool
hasRgb (const pcl::PCLPointCloud2& cloud)
{
  for (const pcl::PCLPointField& field : cloud.fields)
    if (field.name == "rgb" || field.name == "rgba")
      return true;
  return false;
}

/** A PCL mesh (or a cloud: no polygons) as a surface: polygons cut into triangle fans, colours if it has rgb. */
ColouredSurface
surfaceOf (const pcl::PolygonMesh& mesh)
{
  pcl::PointCloud<pcl::PointXYZRGB> cloud;
  pcl::fromPCLPointCloud2 (mesh.cloud, cloud);
  ColouredSurface surface;
  surface.points.resize (3, static_cast<Eigen::Index> (cloud.size ()));
  if (hasRgb (mesh.cloud))
    surface.colours.resize (3, static_cast<Eigen::Index> (cloud.size ()));
  for (std::size_t i = 0; i < cloud.size (); ++i) {
    surface.points.col (i) = cloud[i].getVector3fMap ().cast<double> ();
    if (surface.colours.cols () > 0)
      surface.colours.col (i) << cloud[i].r, cloud[i].g, cloud[i].b;
  }
  std::vector<Eigen::Vector3i> triangles;
  for (const pcl::Vertices& polygon : mesh.polygons)
    for (std::size_t k = 1; k + 1 < polygon.vertices.size (); ++k)
      triangles.emplace_back (polygon.vertices[0], polygon.vertices[k], polygon.vertices[k + 1]);
  surface.triangles.resize (3, static_cast<Eigen::Index> (triangles.size ()));
  for (std::size_t t = 0; t < triangles.size (); ++t)
    surface.triangles.col (t) = triangles[t];
  return surface;
}

/** \a surface without its points that are not finite and the triangles at them. */
ColouredSurface
finitePart (ColouredSurface surface)
{
  const Eigen::Array<bool, 1, Eigen::Dynamic> finite = surface.points.array ().isFinite ().colwise ().all ();
  if (finite.all ())
    return surface;
  std::vector<int> kept, index (surface.points.cols (), -1);
  for (Eigen::Index p = 0; p < surface.points.cols (); ++p)
    if (finite[p])
      index[p] = static_cast<int> (kept.size ()), kept.push_back (static_cast<int> (p));
  ColouredSurface part = surface;
  part.points = surface.points (Eigen::all, kept);
  if (surface.colours.cols () > 0)
    part.colours = surface.colours (Eigen::all, kept);
  std::vector<int> triangles;
  for (Eigen::Index t = 0; t < surface.triangles.cols (); ++t)
    if (finite[surface.triangles (0, t)] && finite[surface.triangles (1, t)] && finite[surface.triangles (2, t)])
      triangles.push_back (static_cast<int> (t));
  part.triangles = surface.triangles (Eigen::all, triangles).unaryExpr ([&] (int p) { return index[p]; });
  if (surface.corner_uv.cols () > 0) {
    part.triangle_texture.clear ();
    part.corner_uv.resize (2, 3 * static_cast<Eigen::Index> (triangles.size ()));
    for (std::size_t t = 0; t < triangles.size (); ++t) {
      part.triangle_texture.push_back (surface.triangle_texture[triangles[t]]);
      part.corner_uv.middleCols<3> (3 * t) = surface.corner_uv.middleCols<3> (3 * triangles[t]);
    }
  }
  return part;
}
} // namespace

ColouredSurface
loadColouredSurface (const std::string& path)
{
  const FileFormat format = checkGeometryFile (path, ".pcd .ply .obj .stl .off .vtk .gltf .glb", "scan");
  if (format == FileFormat::Gltf || format == FileFormat::Glb)
    return readGltfFile (path).surface;
  if (format == FileFormat::Obj)
    return finitePart (readObjSurface (path));
  pcl::PolygonMesh mesh;
  if (format == FileFormat::Pcd)
    mesh.cloud = readPcdFile (path).cloud;
  else
    mesh = readPolygonFile (path, format);
  return finitePart (surfaceOf (mesh));
}
} // namespace morphreg

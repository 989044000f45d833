// SPDX-License-Identifier: BSD-3-Clause
#include "off_reader.h"
#include "ply_writer.h"
#include "polygon_file.h"
#include "vtk_reader.h"

#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>
#include <morphreg/io/field_precision.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/file_validation.h>
#include <morphreg/io/gltf_reader.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>

#include <pcl/conversions.h>
#include <pcl/io/ply_io.h>
#include <pcl/io/vtk_io.h>
#include <pcl/io/vtk_lib_io.h>

namespace morphreg
{
pcl::PolygonMesh
readPolygonFile (const std::string& path, FileFormat format)
{
  pcl::PolygonMesh mesh;
  const int status = callPclIo (path, [&] {
    if (format == FileFormat::Off)
      mesh = readOffMesh (path);
    else if (format == FileFormat::Ply)
      return pcl::io::loadPLYFile (path, mesh);
    else if (format == FileFormat::Obj)
      mesh = readObjFile (path);
    else if (format == FileFormat::VtkLegacy)
      mesh = readVtkFile (path);
    else if (format == FileFormat::Gltf || format == FileFormat::Glb)
      mesh = toPolygonMesh (readGltfFile (path));
    else
      return pcl::io::loadPolygonFile (path, mesh) > 0 ? 0 : -1;
    return 0;
  });
  if (status < 0)
    throw FormatError (path + ": not a readable " + fileExtension (path).substr (1) + " mesh");
  narrowDoubleFields (mesh.cloud, path); // "property double x" would otherwise load as zeros
  return mesh;
}

pcl::PolygonMesh
loadMeshFile (const std::string& path)
{
  pcl::PolygonMesh mesh = readPolygonFile (path, checkGeometryFile (path, kMeshExtensions, "mesh"));
  if (mesh.cloud.width * mesh.cloud.height == 0)
    throw FormatError (path + ": mesh has no vertices");
  return mesh;
}

pcl::PolygonMesh
loadPolygonMesh (const std::string& path)
{
  pcl::PolygonMesh mesh = loadMeshFile (path);
  if (mesh.polygons.empty ())
    throw FormatError (path + ": mesh has no polygons (is it a point cloud?)");
  return mesh;
}

SavedVertexData
savedVertexData (const std::string& path)
{
  requireExtension (path, ".ply .obj .vtk", "mesh");
  return {true, fileExtension (path) == ".ply"};
}

void
savePolygonMesh (const std::string& path, const pcl::PolygonMesh& mesh)
{
  requireExtension (path, ".ply .obj .vtk", "mesh");
  const std::string ext = fileExtension (path);
  if (ext == ".obj")
    return saveObjFile (path, mesh);
  if (ext == ".ply")
    return writeFileAtomically (path, plyMeshBytes (path, mesh));
  writeAtomically (path, [&] (const std::string& partial) {
    const int status = callPclIo (path, [&] { return pcl::io::saveVTKFile (partial, mesh); });
    if (status < 0)
      throw IoError (path + ": cannot write the mesh");
    requireCompletelyWritten (partial, path);
  });
}

TriangleMesh
loadTriangleMesh (const std::string& path)
{
  TriangleMesh mesh = fromPolygonMesh (loadPolygonMesh (path), path);
  validateMesh (mesh, path);
  return mesh;
}

void
saveTriangleMesh (const std::string& path, const TriangleMesh& mesh)
{
  savePolygonMesh (path, toPolygonMesh (mesh));
}

} // namespace morphreg

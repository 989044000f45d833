// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/field_precision.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/file_validation.h>
#include <morphreg/io/gltf_reader.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/pcd_reader.h>

#include <pcl/conversions.h>
#include <pcl/io/pcd_io.h>
#include <pcl/io/ply_io.h>

#include <sstream>

namespace morphreg
{
template <typename PointT>
typename pcl::PointCloud<PointT>::Ptr
loadCloud (const std::string& path)
{
  const FileFormat format = checkGeometryFile (path, ".pcd .ply .obj .stl .off .gltf .glb", "point cloud");
  typename pcl::PointCloud<PointT>::Ptr cloud (new pcl::PointCloud<PointT>);
  if (format == FileFormat::Obj) { // its vertices, faces or not
    pcl::fromPCLPointCloud2 (readObjFile (path).cloud, *cloud);
    return cloud;
  }
  if (format == FileFormat::StlAscii || format == FileFormat::StlBinary || format == FileFormat::Off) {
    // mesh formats: the mesh's vertices are the cloud (an OFF file of points alone too)
    pcl::fromPCLPointCloud2 (loadMeshFile (path).cloud, *cloud);
    return cloud;
  }
  if (format == FileFormat::Gltf || format == FileFormat::Glb) { // its triangles' and points' vertices, in mm
    pcl::fromPCLPointCloud2 (toPolygonMesh (readGltfFile (path)).cloud, *cloud);
    return cloud;
  }
  if (format == FileFormat::Pcd) { // morphreg's own reader: PCL's crashes on some malformed files
    const PcdCloud pcd = readPcdFile (path);
    pcl::fromPCLPointCloud2 (pcd.cloud, *cloud);
    cloud->sensor_origin_ = pcd.origin;
    cloud->sensor_orientation_ = pcd.orientation;
    return cloud;
  }
  pcl::PCLPointCloud2 blob;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  const int status = callPclIo (path, [&] { return pcl::io::loadPLYFile (path, blob, origin, orientation); });
  if (status < 0)
    throw FormatError (path + ": not a readable point cloud");
  narrowDoubleFields (blob, path); // "property double x" would otherwise load as zeros
  pcl::fromPCLPointCloud2 (blob, *cloud);
  cloud->sensor_origin_ = origin;
  cloud->sensor_orientation_ = orientation;
  if (cloud->empty ())
    throw FormatError (path + ": the cloud has no points");
  return cloud;
}

template <typename PointT>
void
saveCloud (const std::string& path, const pcl::PointCloud<PointT>& cloud)
{
  requireExtension (path, ".pcd .ply .obj", "point cloud");
  if (cloud.empty ())
    throw InvalidInputError (path + ": refusing to write an empty cloud");
  const std::string ext = fileExtension (path);
  if (ext == ".obj") {
    pcl::PolygonMesh vertices_only; // OBJ holds clouds as a mesh without faces
    pcl::toPCLPointCloud2 (cloud, vertices_only.cloud);
    return saveObjFile (path, vertices_only);
  }
  writeAtomically (path, [&] (const std::string& partial) {
    const int status = callPclIo (path, [&] {
      if (ext == ".pcd")
        return pcl::io::savePCDFileBinary (partial, cloud);
      return pcl::io::savePLYFileBinary (partial, cloud);
    });
    if (status < 0)
      throw IoError (path + ": cannot write the point cloud");
    requireCompletelyWritten (partial, path);
  });
}

} // namespace morphreg

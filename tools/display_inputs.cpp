// SPDX-License-Identifier: BSD-3-Clause
#include "display_inputs.h"

#include <morphreg/common/colour_map.h>
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/visualization/registration_visualizer.h>

#include <pcl/PCLPointField.h>
#include <pcl/common/io.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <vector>

namespace morphreg
{
namespace tools
{
std::optional<Eigen::VectorXd>
vertexQuality (const pcl::PolygonMesh& mesh, const std::string& path)
{
  const int index = pcl::getFieldIndex (mesh.cloud, "quality");
  if (index < 0)
    return std::nullopt;
  const pcl::PCLPointField& field = mesh.cloud.fields[index];
  if (field.datatype != pcl::PCLPointField::FLOAT32 || field.count != 1)
    return std::nullopt;
  const std::size_t count = static_cast<std::size_t> (mesh.cloud.width) * mesh.cloud.height;
  Eigen::VectorXd quality (static_cast<Eigen::Index> (count));
  for (std::size_t i = 0; i < count; ++i) {
    float value;
    std::memcpy (&value, &mesh.cloud.data[i * mesh.cloud.point_step + field.offset], sizeof (value));
    if (value < 0.0f || std::isinf (value)) {
      std::cerr << "morphreg: " << path << ": its vertex quality is not a distance (vertex " << i << ": " << value
                << "); drawn without residual colours\n";
      return std::nullopt;
    }
    quality[static_cast<Eigen::Index> (i)] = value;
  }
  return quality;
}
pcl::PointCloud<pcl::PointXYZ>::Ptr
addScanFile (RegistrationVisualizer& viewer, const std::string& path, bool over_mesh, int width, int height,
             const std::string& id)
{
  const pcl::PointCloud<pcl::PointXYZ>::Ptr cloud = loadCloud<pcl::PointXYZ> (path);
  try {
    if (over_mesh)
      viewer.addScanOverlay (*cloud, static_cast<std::size_t> (width) * static_cast<std::size_t> (height) / 60, id);
    else
      viewer.addTargetCloud (*cloud, id, 0, 2.0);
  }
  catch (const InvalidInputError& e) {
    throw InvalidInputError (path + ": " + e.what ());
  }
  return cloud;
}

std::pair<pcl::PolygonMesh, std::optional<Eigen::VectorXd>>
addMeshFile (RegistrationVisualizer& viewer, const std::string& path, double colour_max, double opacity,
             const std::string& id, int viewport)
{
  std::pair<pcl::PolygonMesh, std::optional<Eigen::VectorXd>> read{loadPolygonMesh (path), std::nullopt};
  read.second = vertexQuality (read.first, path);
  if (read.second)
    viewer.addResidualHeatMap (read.first, *read.second, residualColourScale (*read.second, colour_max), id, viewport);
  else
    viewer.addModelMesh (read.first, opacity, id, viewport);
  return read;
}
} // namespace tools
} // namespace morphreg

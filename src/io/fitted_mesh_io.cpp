// SPDX-License-Identifier: BSD-3-Clause
#include "../common/number_text.h"

#include <morphreg/io/fitted_mesh_io.h>
#include <morphreg/io/mesh_io.h>

#include <pcl/PCLPointField.h>
#include <pcl/common/io.h>

#include <cmath>
#include <cstring>

namespace morphreg
{
std::optional<Eigen::VectorXd>
vertexResiduals (const pcl::PolygonMesh& mesh, std::string& note)
{
  note.clear ();
  const int index = pcl::getFieldIndex (mesh.cloud, "quality");
  if (index < 0)
    return std::nullopt;
  const pcl::PCLPointField& field = mesh.cloud.fields[static_cast<std::size_t> (index)];
  if (field.datatype != pcl::PCLPointField::FLOAT32 || field.count != 1)
    return std::nullopt;
  const std::size_t count = static_cast<std::size_t> (mesh.cloud.width) * mesh.cloud.height;
  Eigen::VectorXd residuals (static_cast<Eigen::Index> (count));
  for (std::size_t i = 0; i < count; ++i) {
    float value;
    std::memcpy (&value, &mesh.cloud.data[i * mesh.cloud.point_step + field.offset], sizeof (value));
    if (value < 0.0f || std::isinf (value)) {
      note = "its vertex quality is not a distance (vertex " + std::to_string (i) + ": " +
             detail::numberText (value, 6) + "); drawn without residual colours";
      return std::nullopt;
    }
    residuals[static_cast<Eigen::Index> (i)] = value;
  }
  return residuals;
}

FittedMeshFile
loadFittedMesh (const std::string& path)
{
  FittedMeshFile file{loadPolygonMesh (path), std::nullopt, ""};
  file.residuals = vertexResiduals (file.mesh, file.note);
  if (!file.note.empty ())
    file.note = path + ": " + file.note;
  return file;
}
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/datasets/fsaverage_head.h>
#include <morphreg/io/mesh_io.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace morphreg
{
namespace
{
constexpr double kMetresToMillimetres = 1000.0;

/** JSON fiducial names and the project ids they are stored under. */
const std::vector<std::pair<std::string, std::string>> kFiducials = {
    {"nasion", "nasion"}, {"LPA", "left_tragus"}, {"RPA", "right_tragus"}};

LandmarkPositions
readFiducials (const std::string& path)
{
  requireReadableFile (path);
  std::ifstream stream (path);
  const nlohmann::json json = nlohmann::json::parse (stream, nullptr, false);
  if (json.is_discarded () || !json.is_object ())
    throw FormatError (path + ": not a JSON object");
  if (!json.contains ("units") || json["units"] != "metres")
    throw FormatError (path + ": \"units\" must be \"metres\"");
  const auto fiducials = json.find ("fiducials_xyz_m");
  if (fiducials == json.end () || !fiducials->is_object ())
    throw FormatError (path + ": no fiducials_xyz_m object");
  LandmarkPositions landmarks;
  for (const auto& [name, id] : kFiducials) {
    const auto entry = fiducials->find (name);
    if (entry == fiducials->end () || !entry->is_array () || entry->size () != 3)
      throw FormatError (path + ": fiducials_xyz_m/" + name + " must be an array of 3 numbers");
    Eigen::Vector3d position;
    for (int k = 0; k < 3; ++k) {
      if (!(*entry)[k].is_number ())
        throw FormatError (path + ": fiducials_xyz_m/" + name + " holds a non-number");
      position[k] = (*entry)[k].get<double> () * kMetresToMillimetres;
    }
    if (!position.allFinite ())
      throw FormatError (path + ": fiducials_xyz_m/" + name + " is not finite");
    landmarks[id] = position;
  }
  return landmarks;
}
} // namespace

FsaverageHead
loadFsaverageHead (const std::string& directory)
{
  const std::filesystem::path folder (directory);
  FsaverageHead head;
  head.mesh = loadTriangleMesh ((folder / "fsaverage_head.ply").string ());
  head.mesh.vertices *= kMetresToMillimetres;
  head.landmarks = readFiducials ((folder / "fsaverage_head_landmarks.json").string ());
  return head;
}

} // namespace morphreg

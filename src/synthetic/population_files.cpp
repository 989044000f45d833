// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_annotations.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/photo/photo_view_io.h>
#include <morphreg/synthetic/population_files.h>

#include <filesystem>
#include <iomanip>
#include <sstream>

namespace morphreg
{
namespace synthetic
{
namespace
{
std::string
headFileName (std::size_t index, const std::string& suffix)
{
  std::ostringstream name;
  name << "head_" << std::setw (3) << std::setfill ('0') << index << suffix;
  return name.str ();
}

LandmarkPositions
landmarkPositions (const LandmarkVertices& landmarks, const TriangleMesh& head)
{
  LandmarkPositions positions;
  for (const auto& [id, vertex] : landmarks)
    positions[id] = head.vertices.col (vertex);
  return positions;
}

nlohmann::json
parametersJson (const HeadParameters& parameters)
{
  nlohmann::json json;
  for (const auto& range : HeadParameters::ranges ())
    json[range.name] = parameters.*(range.member);
  return json;
}

/** The topology's annotations: regions.json and landmark_vertices.json (the model builder reads them), referenced from the
 *  manifest with the profile line. */
nlohmann::json
writeTopology (const std::string& directory, const HeadGenerator& generator)
{
  saveRegionLabels (directory + "/regions.json", generator.regions ());
  saveLandmarkVertices (directory + "/landmark_vertices.json", generator.landmarks ());
  return {{"num_vertices", generator.numVertices ()},
          {"region_labels", "regions.json"},
          {"landmark_vertices", "landmark_vertices.json"},
          {"profile_line", generator.profileLine ()}};
}

/** Creates \a directory (and parents); IoError naming it on failure. */
void
makeDirectory (const std::string& directory)
{
  std::error_code ec;
  std::filesystem::create_directories (directory, ec);
  if (ec)
    throw IoError (directory + ": cannot create the directory (" + ec.message () + ")");
}

/** Writes \a document to \a path with \a provenance as "morphreg" when it is not null. */
void
writeStamped (const std::string& path, nlohmann::json document, const nlohmann::json& provenance)
{
  if (!provenance.is_null ())
    document["morphreg"] = provenance;
  writeJsonFile (path, document);
}
} // namespace

nlohmann::json
writePopulationFiles (const std::string& directory, const HeadGenerator& generator,
                      const std::vector<SyntheticHead>& heads, std::uint64_t seed, const nlohmann::json& provenance,
                      const HeadWrittenCallback& head_written)
{
  makeDirectory (directory);
  nlohmann::json manifest = writeTopology (directory, generator);
  manifest["units"] = "mm";
  manifest["seed"] = seed;
  manifest["heads"] = nlohmann::json::array ();
  for (std::size_t i = 0; i < heads.size (); ++i) {
    const std::string file = headFileName (i, ".ply"), landmarks = headFileName (i, "_landmarks.json");
    saveTriangleMesh (directory + "/" + file, heads[i].mesh);
    saveLandmarks (directory + "/" + landmarks, landmarkPositions (generator.landmarks (), heads[i].mesh));
    manifest["heads"].push_back ({{"file", file},
                                  {"landmarks", landmarks},
                                  {"seed", seed + i},
                                  {"parameters", parametersJson (heads[i].parameters)}});
    if (head_written)
      head_written (i + 1);
  }
  writeStamped (directory + "/population.json", manifest, provenance);
  return manifest;
}

nlohmann::json
writeScanFiles (const std::string& directory, const std::string& name, const SimulatedScan& scan,
                const TriangleMesh& head, const LandmarkVertices& landmarks, const nlohmann::json& provenance)
{
  makeDirectory (directory);
  TriangleMesh posed = head;
  posed.vertices = scan.head_to_scan * head.vertices;
  saveTriangleMesh (directory + "/" + name + "_truth.ply", posed);
  saveLandmarks (directory + "/" + name + "_landmarks.json", landmarkPositions (landmarks, posed));
  saveCloud (directory + "/" + name + ".pcd", *scan.cloud);
  const Eigen::Matrix4d pose = scan.head_to_scan.matrix ();
  nlohmann::json truth = {{"units", "mm"},
                          {"head_to_scan", std::vector<double> (pose.data (), pose.data () + 16)},
                          {"head_to_scan_layout", "column-major 4x4"},
                          {"scale", scan.scale},
                          {"num_points", scan.cloud->size ()},
                          {"num_outliers", scan.num_outliers},
                          {"source_triangle", scan.source_triangle},
                          {"barycentric", std::vector<double> (scan.barycentric.data (),
                                                               scan.barycentric.data () + scan.barycentric.size ())}};
  writeStamped (directory + "/" + name + "_truth.json", truth, provenance);
  if (!scan.range_mesh.polygons.empty ())
    savePolygonMesh (directory + "/" + name + "_range.ply", scan.range_mesh);
  return {{"cloud", name + ".pcd"},
          {"truth", name + "_truth.json"},
          {"truth_mesh", name + "_truth.ply"},
          {"landmarks", name + "_landmarks.json"},
          {"num_points", scan.cloud->size ()},
          {"num_outliers", scan.num_outliers},
          {"scale", scan.scale}};
}

nlohmann::json
writePhotoFiles (const std::string& directory, const std::string& name, const SimulatedPhotos& photos,
                 std::size_t head_index, const nlohmann::json& provenance)
{
  makeDirectory (directory);
  saveProfileView (directory + "/" + name + "_profile.json", photos.profile);
  saveFrontalView (directory + "/" + name + "_frontal.json", photos.frontal);
  Eigen::Matrix4d pose = Eigen::Matrix4d::Identity ();
  pose.topLeftCorner<3, 3> () = photos.scale * photos.rotation;
  pose.topRightCorner<3, 1> () = photos.translation;
  const nlohmann::json truth = {{"head", headFileName (head_index, ".ply")},
                                {"units", "head in mm, photo frame normalised (pixels / longer image side)"},
                                {"head_to_photo", std::vector<double> (pose.data (), pose.data () + 16)},
                                {"head_to_photo_layout", "column-major 4x4"},
                                {"scale", photos.scale}};
  writeStamped (directory + "/" + name + "_truth.json", truth, provenance);
  return {{"profile", name + "_profile.json"}, {"frontal", name + "_frontal.json"}, {"truth", name + "_truth.json"}};
}

} // namespace synthetic
} // namespace morphreg

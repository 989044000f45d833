// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_annotations.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/photo/photo_view_io.h>
#include <morphreg/synthetic/population_files.h>

#include <cmath>
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

namespace
{
/** Profile and frontal photo annotations of the first settings.photos heads, each nodding by 5 degrees. */
void
writeHeadPhotos (const std::string& directory, const SyntheticStudySettings& settings, const HeadGenerator& generator,
                 const std::vector<SyntheticHead>& heads, const nlohmann::json& provenance)
{
  PhotoSimulator::Parameters camera;
  camera.rotation = Eigen::AngleAxisd (5.0 * M_PI / 180.0, Eigen::Vector3d::UnitX ()).toRotationMatrix ();
  const PhotoSimulator simulator (camera);
  const LandmarkVertices frontal = frontalLandmarks (generator.landmarks ());
  for (int i = 0; i < settings.photos; ++i) {
    const SyntheticHead& head = heads[static_cast<std::size_t> (i)];
    const std::uint64_t seed = settings.seed + static_cast<std::uint64_t> (i);
    writePhotoFiles (directory, "photo_" + std::to_string (i),
                     simulator.photograph (head.mesh.vertices, frontal, generator.profileLine (), seed),
                     static_cast<std::size_t> (i), provenance);
  }
}
} // namespace

void
writeSyntheticStudy (const std::string& directory, const SyntheticStudySettings& settings,
                     const nlohmann::json& provenance, const StudyProgress& progress)
{
  const ScanSimulator scanner (settings.scanner); // bad scanner settings fail before anything is written
  if (settings.scans > settings.count || settings.photos > settings.count)
    throw InvalidInputError ("synthetic study: " + std::to_string (settings.scans) + " scans and " +
                             std::to_string (settings.photos) + " photo pairs of " + std::to_string (settings.count) +
                             " heads; a head is scanned or photographed at most once");
  const StudyProgress told = progress ? progress : [] (const std::string&, int, int) {};
  const HeadGenerator generator (settings.resolution);
  const std::vector<SyntheticHead> heads = generator.population (settings.count, settings.seed);
  writePopulationFiles (directory, generator, heads, settings.seed, provenance,
                        [&] (std::size_t done) { told ("writing heads", static_cast<int> (done), settings.count); });
  for (int i = 0; i < settings.scans; ++i) {
    const TriangleMesh& head = heads[static_cast<std::size_t> (i)].mesh;
    writeScanFiles (directory, "scan_" + std::to_string (i), scanner.scan (head, settings.seed + i), head,
                    generator.landmarks (), provenance);
    told ("scanning heads", i + 1, settings.scans);
  }
  writeHeadPhotos (directory, settings, generator, heads, provenance);
}

} // namespace synthetic
} // namespace morphreg

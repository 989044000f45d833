// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/datasets/ict_facekit.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/npy_reader.h>
#include <morphreg/model/pca.h>

#include <nlohmann/json.hpp>

#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>

namespace morphreg
{
namespace
{
constexpr double kCentimetresToMillimetres = 10.0;
/** ICT-FaceKit's face [0, 9409) and head and neck [9409, 11248): the vertices the model keeps (eyes, mouth socket,
 *  teeth and eyelashes follow). */
constexpr Eigen::Index kHeadAndNeckVertices = 11248;

/** Project landmark ids (docs/landmarks.md) and their iBUG-68 numbers. */
const std::vector<std::pair<std::string, int>> kIbugLandmarks = {{"right_eyebrow", 19},
                                                                 {"right_eye_outer", 36},
                                                                 {"right_eye_inner", 39},
                                                                 {"left_eyebrow", 24},
                                                                 {"left_eye_outer", 45},
                                                                 {"left_eye_inner", 42},
                                                                 {"right_nose_wing", 31},
                                                                 {"nose_tip", 30},
                                                                 {"left_nose_wing", 35},
                                                                 {"right_mouth_corner", 48},
                                                                 {"left_mouth_corner", 54},
                                                                 {"upper_lip_center", 51},
                                                                 {"mouth_center", 62},
                                                                 {"lower_lip_center", 57},
                                                                 {"right_philtrum", 50},
                                                                 {"left_philtrum", 52},
                                                                 {"right_lower_lip", 58},
                                                                 {"left_lower_lip", 56},
                                                                 {"right_jaw", 3},
                                                                 {"right_jaw_middle", 5},
                                                                 {"right_chin", 7},
                                                                 {"left_jaw", 13},
                                                                 {"left_jaw_middle", 11},
                                                                 {"left_chin", 9},
                                                                 {"chin", 8}};

/** Landmarks ICT does not provide, picked on the mean mesh by geometry. */
const std::vector<std::pair<std::string, int>> kGeometricLandmarks = {
    {"left_tragus", 7321}, {"right_tragus", 8048}, {"nasion", 1358}};

std::string
join (const std::string& directory, const std::string& name)
{
  return directory.empty () || directory.back () == '/' ? directory + name : directory + "/" + name;
}

/** The model's landmarks from ICT's 68 iBUG vertices: "ibug68_NN", the project ids that map to iBUG points and the
 *  geometric ones ICT lacks. */
LandmarkVertices
landmarksFromIbug (const std::vector<int>& ibug)
{
  LandmarkVertices landmarks;
  for (size_t k = 0; k < ibug.size (); ++k)
    landmarks[ibug68LandmarkId (static_cast<int> (k))] = ibug[k];
  for (const auto& [id, number] : kIbugLandmarks)
    landmarks[id] = ibug[number];
  for (const auto& [id, vertex] : kGeometricLandmarks)
    landmarks[id] = vertex;
  return landmarks;
}

nlohmann::json
readJsonObject (const std::string& path)
{
  requireReadableFile (path, kMaxTextFileBytes);
  std::ifstream stream (path);
  const nlohmann::json json = nlohmann::json::parse (stream, nullptr, false);
  if (json.is_discarded () || !json.is_object ())
    throw FormatError (path + ": not a JSON object");
  return json;
}

/** The 68 iBUG vertex indices of \a list (entry \a name of \a path), each checked to be a vertex of the mean. */
std::vector<int>
ibugVertices (const nlohmann::json& list, const std::string& path, const std::string& name, Eigen::Index num_vertices)
{
  if (!list.is_array () || list.size () != 68)
    throw FormatError (path + ": " + name + " must be an array of 68 vertex indices");
  std::vector<int> ibug;
  for (const auto& value : list) {
    if (!value.is_number_integer () || value.get<long long> () < 0 || value.get<long long> () >= num_vertices)
      throw FormatError (path + ": " + name + " entry " + std::to_string (ibug.size ()) + " (" + value.dump () +
                         ") is not a vertex index in [0, " + std::to_string (num_vertices) + ")");
    ibug.push_back (value.get<int> ());
  }
  return ibug;
}

/** The converted layout's iBUG vertices: ict_head_model.json's landmarks/multipie68. */
std::vector<int>
readIbugVertices (const std::string& path, Eigen::Index num_vertices)
{
  const nlohmann::json json = readJsonObject (path);
  if (!json.contains ("num_vertices") || json["num_vertices"] != num_vertices)
    throw FormatError (path + ": num_vertices does not match the mean mesh (" + std::to_string (num_vertices) + ")");
  const nlohmann::json landmarks = json.value ("landmarks", nlohmann::json::object ());
  return ibugVertices (landmarks.value ("multipie68", nlohmann::json ()), path, "landmarks/multipie68", num_vertices);
}

/** Vertices on x = 0, from the front of the neck over the face and crown to the back of the neck. */
std::vector<int>
midSagittalProfile (const TriangleMesh& mesh)
{
  const double tolerance = 1e-6 * mesh.vertices.cwiseAbs ().maxCoeff ();
  std::vector<int> profile;
  Eigen::Vector2d centre = Eigen::Vector2d::Zero ();
  for (Eigen::Index i = 0; i < mesh.numVertices (); ++i)
    if (std::abs (mesh.vertices (0, i)) <= tolerance) {
      profile.push_back (static_cast<int> (i));
      centre += mesh.vertices.col (i).tail<2> ();
    }
  centre /= std::max<double> (1.0, static_cast<double> (profile.size ()));
  // Angle in the (z, y) plane, starting straight down (the neck) and turning towards the face.
  const auto key = [&] (int v) {
    const double angle = std::atan2 (mesh.vertices (1, v) - centre.y (), mesh.vertices (2, v) - centre.x ());
    return std::fmod (angle + 0.5 * M_PI + 2.0 * M_PI, 2.0 * M_PI);
  };
  std::sort (profile.begin (), profile.end (), [&] (int a, int b) { return key (a) < key (b); });
  return profile;
}
/** Landmarks (from ICT's 68 iBUG vertices), the profile line and the provenance of an ICT model with mean \a mean. */
void
describeIctModel (MorphableModel& model, const TriangleMesh& mean, const std::vector<int>& ibug,
                  const std::string& source)
{
  model.setLandmarks (landmarksFromIbug (ibug));
  model.setProfileLine (midSagittalProfile (mean));
  model.setMetadata ({{"source", source},
                      {"license", "MIT License, Copyright (c) 2020 USC Institute for Creative Technologies"},
                      {"original_units", "cm (converted to mm on import)"}});
}

/** The converted layout: ict_head_mean.ply, the orthonormal basis and eigenvalues as .npy, ict_head_model.json. */
MorphableModel::Ptr
loadConvertedLayout (const std::string& directory)
{
  const std::string mean_path = join (directory, "ict_head_mean.ply");
  TriangleMesh mean = loadTriangleMesh (mean_path);
  mean.vertices *= kCentimetresToMillimetres;
  const auto n = static_cast<std::size_t> (mean.numVertices ());

  const std::string eigen_path = join (directory, "ict_head_pca_eigenvalues.npy");
  const NpyArray eigenvalues = readNpyFloat32 (eigen_path);
  if (eigenvalues.shape.size () != 1 || eigenvalues.size () == 0)
    throw FormatError (eigen_path + ": expected a 1-d array of eigenvalues");
  const std::size_t k = eigenvalues.size ();
  const std::string basis_path = join (directory, "ict_head_pca_basis.npy");
  const NpyArray basis = readNpyFloat32 (basis_path);
  requireNpyShape (basis, {k, n, 3}, basis_path);

  Eigen::VectorXd variances =
      Eigen::Map<const Eigen::VectorXf> (eigenvalues.data.data (), static_cast<Eigen::Index> (k)).cast<double> () *
      (kCentimetresToMillimetres * kCentimetresToMillimetres);
  if (variances.minCoeff () < 0.0)
    throw FormatError (eigen_path + ": negative eigenvalue");
  // [k, N, 3] in C order: component c occupies 3N consecutive values, interleaved x, y, z.
  Eigen::MatrixXd columns = Eigen::Map<const Eigen::MatrixXf> (basis.data.data (), static_cast<Eigen::Index> (3 * n),
                                                               static_cast<Eigen::Index> (k))
                                .cast<double> ();
  for (Eigen::Index c = 0; c < columns.cols (); ++c)
    if (std::abs (columns.col (c).norm () - 1.0) > 1e-3)
      throw FormatError (basis_path + ": component " + std::to_string (c) + " has norm " +
                         std::to_string (columns.col (c).norm ()) + ", expected an orthonormal basis");

  const Eigen::VectorXd flat_mean = Eigen::Map<const Eigen::VectorXd> (mean.vertices.data (), mean.vertices.size ());
  auto model = MorphableModel::fromGlobalPca (mean.triangles, flat_mean, std::move (columns), std::move (variances));
  describeIctModel (*model, mean, readIbugVertices (join (directory, "ict_head_model.json"), mean.numVertices ()),
                    "ICT-FaceKit FaceXModel (ICT Face Model Light), head and neck vertices [0, 11248)");
  return model;
}

/** The vertices [0, 11248) (face, head and neck) of an ICT OBJ, x y z interleaved, in mm; FormatError naming \a path
 *  unless the file has \a expected vertices (the neutral mesh's count). */
Eigen::VectorXd
headVertices (const pcl::PolygonMesh& mesh, const std::string& path, std::size_t expected)
{
  pcl::PointCloud<pcl::PointXYZ> cloud;
  pcl::fromPCLPointCloud2 (mesh.cloud, cloud);
  if (cloud.size () != expected || cloud.size () < static_cast<std::size_t> (kHeadAndNeckVertices))
    throw FormatError (path + ": " + std::to_string (cloud.size ()) + " vertices, expected " +
                       std::to_string (expected) + " (ICT-FaceKit's mesh, its first " +
                       std::to_string (kHeadAndNeckVertices) + " the face, head and neck)");
  Eigen::VectorXd head (3 * kHeadAndNeckVertices);
  for (Eigen::Index i = 0; i < kHeadAndNeckVertices; ++i)
    head.segment<3> (3 * i) = cloud[i].getVector3fMap ().cast<double> () * kCentimetresToMillimetres;
  return head;
}

/** The polygons of the face, head and neck (every corner below 11248) as triangles, each split as a fan from its
 *  first corner (a quad into (0, 1, 2) and (0, 2, 3), as the converted files have it). */
TriangleMesh::Triangles
headTriangles (const pcl::PolygonMesh& mesh, const std::string& path)
{
  std::vector<Eigen::Vector3i> triangles;
  for (const pcl::Vertices& polygon : mesh.polygons) {
    const auto& corners = polygon.vertices;
    if (*std::max_element (corners.begin (), corners.end ()) >= kHeadAndNeckVertices)
      continue;
    for (std::size_t c = 1; c + 1 < corners.size (); ++c)
      triangles.emplace_back (corners[0], corners[c], corners[c + 1]);
  }
  if (triangles.empty ())
    throw FormatError (path + ": no polygon within the face, head and neck (vertices [0, " +
                       std::to_string (kHeadAndNeckVertices) + "))");
  TriangleMesh::Triangles result (3, static_cast<Eigen::Index> (triangles.size ()));
  for (std::size_t t = 0; t < triangles.size (); ++t)
    result.col (static_cast<Eigen::Index> (t)) = triangles[t];
  return result;
}

/** The identityNNN.obj files of \a folder, in their numbers' order. */
std::vector<std::string>
identityFiles (const std::string& folder)
{
  const std::regex name ("identity[0-9]+\\.obj");
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator (folder))
    if (std::regex_match (entry.path ().filename ().string (), name))
      files.push_back (entry.path ().string ());
  std::sort (files.begin (), files.end ());
  return files;
}

/** ICT-FaceKit's own layout (its FaceXModel folder): the model x = mean + sum_k c_k (identity_k - neutral), c_k ~ N(0,
 *  1), over the face, head and neck, as an orthonormal basis with variances (its PCA, with the modes' Gram matrix). */
MorphableModel::Ptr
loadUpstreamLayout (const std::string& folder)
{
  const std::string neutral_path = join (folder, "generic_neutral_mesh.obj");
  const pcl::PolygonMesh neutral = readObjFile (neutral_path);
  const std::size_t count = neutral.cloud.width * neutral.cloud.height;
  const Eigen::VectorXd mean = headVertices (neutral, neutral_path, count);
  const std::vector<std::string> identities = identityFiles (folder);
  if (identities.size () < 2)
    throw IoError (folder + ": " + std::to_string (identities.size ()) +
                   " identityNNN.obj file(s); ICT-FaceKit's identity model needs at least two");
  Eigen::MatrixXd modes (mean.size (), static_cast<Eigen::Index> (identities.size ()));
  for (std::size_t k = 0; k < identities.size (); ++k)
    modes.col (static_cast<Eigen::Index> (k)) = headVertices (readObjFile (identities[k]), identities[k], count) - mean;
  PcaBasis pca = computePca (modes, PcaMethod::gram);
  pca.variances *= static_cast<double> (modes.cols () - 1); // the modes are scaled directions, not samples

  const std::string indices_path = join (folder, "vertex_indices.json");
  const std::vector<int> ibug =
      ibugVertices (readJsonObject (indices_path).value ("idx_to_landmark_verts", nlohmann::json ()), indices_path,
                    "idx_to_landmark_verts", kHeadAndNeckVertices);
  const TriangleMesh mean_mesh{Eigen::Map<const Eigen::Matrix3Xd> (mean.data (), 3, kHeadAndNeckVertices),
                               headTriangles (neutral, neutral_path)};
  auto model =
      MorphableModel::fromGlobalPca (mean_mesh.triangles, mean, std::move (pca.basis), std::move (pca.variances));
  describeIctModel (*model, mean_mesh, ibug,
                    "ICT-FaceKit FaceXModel (ICT Face Model Light) as published: generic_neutral_mesh.obj and " +
                        std::to_string (identities.size ()) + " identity OBJs, head and neck vertices [0, 11248)");
  return model;
}

/** The FaceXModel folder of \a directory (the folder itself or its FaceXModel/), or "" if it has none. */
std::string
upstreamFolder (const std::string& directory)
{
  for (const std::string& folder : {join (directory, "FaceXModel"), directory})
    if (std::filesystem::exists (join (folder, "generic_neutral_mesh.obj")))
      return folder;
  return "";
}
} // namespace

MorphableModel::Ptr
loadIctFaceKit (const std::string& directory)
{
  if (std::filesystem::exists (join (directory, "ict_head_mean.ply")))
    return loadConvertedLayout (directory);
  const std::string folder = upstreamFolder (directory);
  if (!folder.empty ())
    return loadUpstreamLayout (folder);
  throw IoError (directory + ": no ICT-FaceKit model: neither ICT-FaceKit's own layout (FaceXModel/" +
                 "generic_neutral_mesh.obj, identityNNN.obj, vertex_indices.json) nor the converted one " +
                 "(ict_head_mean.ply, ict_head_pca_basis.npy, ict_head_pca_eigenvalues.npy, ict_head_model.json)");
}

} // namespace morphreg

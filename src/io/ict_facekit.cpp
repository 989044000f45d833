#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/ict_facekit.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/npy_reader.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <fstream>

namespace morphreg
{
namespace
{
constexpr double kCentimetresToMillimetres = 10.0;

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

LandmarkVertices
readLandmarks (const std::string& path, Eigen::Index num_vertices)
{
  requireReadableFile (path, kMaxTextFileBytes);
  std::ifstream stream (path);
  const nlohmann::json json = nlohmann::json::parse (stream, nullptr, false);
  if (json.is_discarded () || !json.is_object ())
    throw FormatError (path + ": not a JSON object");
  if (!json.contains ("num_vertices") || json["num_vertices"] != num_vertices)
    throw FormatError (path + ": num_vertices does not match the mean mesh (" + std::to_string (num_vertices) + ")");
  const auto entry = json.find ("landmarks");
  if (entry == json.end () || !entry->contains ("multipie68") || !(*entry)["multipie68"].is_array () ||
      (*entry)["multipie68"].size () != 68)
    throw FormatError (path + ": landmarks/multipie68 must be an array of 68 vertex indices");
  std::vector<int> ibug;
  for (const auto& value : (*entry)["multipie68"]) {
    if (!value.is_number_integer () || value.get<long long> () < 0 || value.get<long long> () >= num_vertices)
      throw FormatError (path + ": landmarks/multipie68 entry " + std::to_string (ibug.size ()) + " (" + value.dump () +
                         ") is not a vertex index in [0, " + std::to_string (num_vertices) + ")");
    ibug.push_back (value.get<int> ());
  }
  LandmarkVertices landmarks;
  for (size_t k = 0; k < ibug.size (); ++k)
    landmarks[ibug68LandmarkId (static_cast<int> (k))] = ibug[k];
  for (const auto& [id, number] : kIbugLandmarks)
    landmarks[id] = ibug[number];
  for (const auto& [id, vertex] : kGeometricLandmarks)
    landmarks[id] = vertex;
  return landmarks;
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
} // namespace

MorphableModel::Ptr
loadIctFaceKit (const std::string& directory)
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
  model->setLandmarks (readLandmarks (join (directory, "ict_head_model.json"), mean.numVertices ()));
  model->setProfileLine (midSagittalProfile (mean));
  model->setMetadata ({{"source", "ICT-FaceKit FaceXModel (ICT Face Model Light), head and neck vertices [0, 11248)"},
                       {"license", "MIT License, Copyright (c) 2020 USC Institute for Creative Technologies"},
                       {"original_units", "cm (converted to mm on import)"}});
  return model;
}

} // namespace morphreg

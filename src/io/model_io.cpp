// SPDX-License-Identifier: BSD-3-Clause
#include "hdf5_file.h"

#include <morphreg/common/length_unit.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/model_io.h>
#include <morphreg/model/model_consistency.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <ctime>

namespace morphreg
{
namespace
{
using RowMajorMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

/** The statismo part of a file: topology, mean and global PCA. */
struct StatismoPart
{
  TriangleMesh::Triangles triangles;
  Eigen::VectorXd mean;
  Eigen::VectorXd reference; ///< representer/points, interleaved like the mean
  Eigen::MatrixXd basis;
  Eigen::VectorXd variances;
  double noise_variance = 0.0;
};

std::string
joinPath (const std::string& prefix, const std::string& name)
{
  return prefix.empty () ? name : prefix + "/" + name;
}

Eigen::MatrixXd
toMatrix (const hdf5::Array<double>& array)
{
  return Eigen::Map<const RowMajorMatrix> (array.values.data (), static_cast<Eigen::Index> (array.dims[0]),
                                           static_cast<Eigen::Index> (array.dims[1]));
}

Eigen::VectorXd
toVector (const hdf5::Array<double>& array)
{
  return Eigen::Map<const Eigen::VectorXd> (array.values.data (), static_cast<Eigen::Index> (array.values.size ()));
}

/** Integer indices in [0, limit), checked. */
std::vector<int>
toIndices (const hdf5::Reader& file, const std::string& name, const hdf5::Array<long long>& array, Eigen::Index limit)
{
  std::vector<int> indices (array.values.size ());
  for (size_t i = 0; i < indices.size (); ++i) {
    if (array.values[i] < 0 || array.values[i] >= limit)
      file.fail (name, "index " + std::to_string (array.values[i]) + " at element " + std::to_string (i) +
                           " is out of range [0, " + std::to_string (limit) + ")");
    indices[i] = static_cast<int> (array.values[i]);
  }
  return indices;
}

void
requireDims (const hdf5::Reader& file, const std::string& name, const std::vector<hsize_t>& dims,
             const std::vector<hsize_t>& expected, const std::string& meaning)
{
  if (dims != expected) {
    std::string text;
    for (size_t i = 0; i < dims.size (); ++i)
      text += (i ? ", " : "") + std::to_string (dims[i]);
    file.fail (name, "has dimensions [" + text + "], expected " + meaning);
  }
}

int
minorVersion (const hdf5::Reader& file, const std::string& prefix)
{
  for (const std::string& group : {joinPath (prefix, "version"), std::string ("version")}) {
    if (!file.exists (group + "/minorVersion"))
      continue;
    const double major = file.readScalar (group + "/majorVersion");
    const double minor = file.readScalar (group + "/minorVersion");
    if (major != 0.0 || (minor != 8.0 && minor != 9.0))
      file.fail (group + "/minorVersion", "unsupported statismo version " + std::to_string (major) + "." +
                                              std::to_string (minor) + " (0.8 and 0.9 are supported)");
    return static_cast<int> (minor);
  }
  return 9;
}

StatismoPart
readStatismo (const hdf5::Reader& file, const std::string& prefix)
{
  StatismoPart part;
  const std::string points_name = joinPath (prefix, "representer/points");
  const auto points = file.readFloats (points_name, 2);
  if (points.dims[0] != 3 || points.dims[1] == 0)
    requireDims (file, points_name, points.dims, {3, std::max<hsize_t> (points.dims[1], 1)}, "[3, N] with N > 0");
  const hsize_t n = points.dims[1];
  part.reference = Eigen::Map<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> (
                       points.values.data (), 3, static_cast<Eigen::Index> (n))
                       .reshaped (); // column-major: x, y, z of each point in turn

  const std::string cells_name = joinPath (prefix, "representer/cells");
  const auto cells = file.readIntegers (cells_name, 2);
  if (cells.dims[0] != 3 || cells.dims[1] == 0)
    requireDims (file, cells_name, cells.dims, {3, std::max<hsize_t> (cells.dims[1], 1)},
                 "[3, M] triangles with M > 0");
  const std::vector<int> indices = toIndices (file, cells_name, cells, static_cast<Eigen::Index> (n));
  // [3, M] row-major: row r holds corner r of every triangle.
  part.triangles = Eigen::Map<const Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> (
      indices.data (), 3, static_cast<Eigen::Index> (cells.dims[1]));

  const std::string mean_name = joinPath (prefix, "model/mean");
  const auto mean = file.readFloats (mean_name, 1);
  requireDims (file, mean_name, mean.dims, {3 * n},
               "[3N] = [" + std::to_string (3 * n) + "] (N from representer/points)");
  part.mean = toVector (mean);

  const std::string variance_name = joinPath (prefix, "model/pcaVariance");
  const auto variances = file.readFloats (variance_name, 1);
  part.variances = toVector (variances);
  if (part.variances.size () && part.variances.minCoeff () < 0.0)
    file.fail (variance_name, "has a negative variance");

  const std::string basis_name = joinPath (prefix, "model/pcaBasis");
  const auto basis = file.readFloats (basis_name, 2);
  requireDims (file, basis_name, basis.dims, {3 * n, variances.dims[0]},
               "[3N, k] = [" + std::to_string (3 * n) + ", " + std::to_string (variances.dims[0]) + "]");
  part.basis = toMatrix (basis);

  const std::string noise_name = joinPath (prefix, "model/noiseVariance");
  part.noise_variance = file.exists (noise_name) ? file.readScalar (noise_name) : 0.0;
  if (part.noise_variance < 0.0)
    file.fail (noise_name, "is negative");

  if (minorVersion (file, prefix) == 8) {
    // statismo v0.8 stored U * diag(sqrt(variance)); v0.9 stores the orthonormal U.
    for (Eigen::Index k = 0; k < part.basis.cols (); ++k) {
      if (!(part.variances[k] > 0.0))
        file.fail (variance_name, "v0.8 basis column " + std::to_string (k) + " has zero variance, cannot normalise");
      part.basis.col (k) /= std::sqrt (part.variances[k]);
    }
  }
  for (Eigen::Index k = 0; k < part.basis.cols (); ++k)
    if (std::abs (part.basis.col (k).norm () - 1.0) > 1e-3)
      file.fail (basis_name, "column " + std::to_string (k) + " has norm " +
                                 std::to_string (part.basis.col (k).norm ()) +
                                 ", expected orthonormal columns (a v0.8 scaled basis labelled v0.9?)");
  return part;
}

ModelRegion
readRegion (const hdf5::Reader& file, const std::string& group, Eigen::Index num_vertices)
{
  ModelRegion region;
  region.name = file.readString (group + "/name");
  const auto vertices = file.readIntegers (group + "/vertices", 1);
  region.vertices = toIndices (file, group + "/vertices", vertices, num_vertices);
  const hsize_t b = vertices.dims[0];
  const auto weights = file.readFloats (group + "/weights", 1);
  requireDims (file, group + "/weights", weights.dims, {b}, "one weight per region vertex");
  region.weights = toVector (weights);
  const auto variances = file.readFloats (group + "/variances", 1);
  region.variances = toVector (variances);
  const auto basis = file.readFloats (group + "/basis", 2);
  requireDims (file, group + "/basis", basis.dims, {3 * b, variances.dims[0]}, "[3B, P] (vertices, variances)");
  region.basis = toMatrix (basis);
  return region;
}

nlohmann::json
readJson (const hdf5::Reader& file, const std::string& name)
{
  const nlohmann::json value = nlohmann::json::parse (file.readString (name), nullptr, false);
  if (value.is_discarded () || !value.is_object ())
    file.fail (name, "is not a JSON object");
  return value;
}

/** How a file's model is brought to mm: the factor on its coordinates and the metadata entry saying so. */
struct UnitConversion
{
  double to_mm = 1.0;
  std::string description; ///< the kFileUnitsKey entry, e.g. "cm (the file's units); converted to mm on loading"
};

UnitConversion
describeConversion (LengthUnit unit, const std::string& how)
{
  const double to_mm = millimetresPer (unit);
  return {to_mm, toString (unit) + " (" + how + ")" + (to_mm == 1.0 ? "" : "; converted to mm on loading")};
}

/** A morphreg file's units dataset; FormatError naming the file unless it is a length unit. */
UnitConversion
statedUnit (const hdf5::Reader& file)
{
  const std::string units = file.readString ("morphreg/units");
  try {
    return describeConversion (parseLengthUnit (units), "the file's units");
  }
  catch (const InvalidInputError&) {
    file.fail ("morphreg/units", "'" + units + "' is no length unit (mm, cm, dm, m or in)");
  }
  return {};
}

/** A statismo file's unit, which the layout does not state: guessed from the mean's size (guessModelUnit); a
 *  FormatError naming the file when the size fits no unit. */
UnitConversion
guessedUnit (const std::string& path, const Eigen::VectorXd& mean)
{
  LengthUnitGuess guess;
  try {
    guess = guessModelUnit (Eigen::Map<const Eigen::Matrix3Xd> (mean.data (), 3, mean.size () / 3));
  }
  catch (const InvalidInputError& e) {
    throw FormatError (path + ": " + e.detailedMessage ());
  }
  if (!guess.recognised)
    throw FormatError (path + ": not a head model in any unit: " + guess.reason +
                       "; convert it to mm (statismo files do not state their unit)");
  return describeConversion (guess.unit, "guessed from its size: " + guess.reason);
}

/** The statismo part brought to mm: coordinates times \a to_mm, variances (and the noise) times its square. */
void
scaleToMillimetres (StatismoPart& part, double to_mm)
{
  part.mean *= to_mm;
  part.variances *= to_mm * to_mm;
  part.noise_variance *= to_mm * to_mm;
}

MorphableModel::Ptr
readMorphreg (const hdf5::Reader& file)
{
  StatismoPart part = readStatismo (file, "");
  const Eigen::Index n = part.mean.size () / 3;
  const double version = file.readScalar ("morphreg/formatVersion");
  if (version != 1.0)
    file.fail ("morphreg/formatVersion", "unsupported morphreg format version " + std::to_string (version));
  const auto mean = file.readFloats ("morphreg/mean", 1);
  requireDims (file, "morphreg/mean", mean.dims, {static_cast<hsize_t> (3 * n)}, "[3N] like model/mean");
  // the copies compared as the file writes them, before the conversion to mm
  requireSameMean (toVector (mean), part.mean, file.path (), "the datasets morphreg/mean and model/mean");
  requireSameMean (toVector (mean), part.reference, file.path (), "the datasets morphreg/mean and representer/points");
  const UnitConversion unit = statedUnit (file);
  scaleToMillimetres (part, unit.to_mm);
  const double num_regions = file.readScalar ("morphreg/numRegions");
  if (num_regions < 1 || num_regions > 10000 || num_regions != std::floor (num_regions))
    file.fail ("morphreg/numRegions", "invalid region count " + std::to_string (num_regions));
  std::vector<ModelRegion> regions;
  for (int j = 0; j < static_cast<int> (num_regions); ++j) {
    regions.push_back (readRegion (file, "morphreg/regions/region_" + std::to_string (j), n));
    regions.back ().variances *= unit.to_mm * unit.to_mm;
  }

  try {
    auto model = std::make_shared<MorphableModel> (part.triangles, toVector (mean) * unit.to_mm, std::move (regions));
    model->setGlobalPca (part.basis, part.variances);
    model->setNoiseVariance (part.noise_variance);
    const auto profile = file.readIntegers ("morphreg/profileLine", 1);
    model->setProfileLine (toIndices (file, "morphreg/profileLine", profile, n));
    LandmarkVertices landmarks;
    const nlohmann::json landmark_json = readJson (file, "morphreg/landmarks");
    for (const auto& [name, index] : landmark_json.items ()) {
      requireKnownLandmarkId (name, file.path () + ": dataset 'morphreg/landmarks'");
      landmarks[name] = static_cast<int> (jsonWholeNumber (
          index, 0, n - 1, file.path () + ": dataset 'morphreg/landmarks': the vertex of landmark '" + name + "'"));
    }
    model->setLandmarks (landmarks);
    std::map<std::string, std::string> metadata;
    const nlohmann::json metadata_json = readJson (file, "morphreg/metadata");
    for (const auto& [key, value] : metadata_json.items ()) {
      if (!value.is_string ())
        file.fail ("morphreg/metadata", "entry '" + key + "' is not a string");
      metadata[key] = value.get<std::string> ();
    }
    metadata[kFileUnitsKey] = unit.description;
    model->setMetadata (metadata);
    requireConsistentModel (*model, file.path ());
    return model;
  }
  catch (const InvalidInputError& e) {
    throw FormatError (file.path () + ": /morphreg: " + e.detailedMessage ());
  }
}

/** The landmarks of a Basel Face Model 2017 file (metadata/landmarks/json, scalismo's layout, positions on the mean)
 *  as the nearest mean vertices; none if the file has no such dataset.
 */
LandmarkVertices
readBfmLandmarks (const hdf5::Reader& file, const Eigen::VectorXd& mean)
{
  const std::string name = "metadata/landmarks/json";
  if (!file.exists (name))
    return {};
  const LandmarkPositions positions =
      parseScalismoLandmarks (file.readString (name), file.path () + ": dataset '" + name + "'");
  const Eigen::Map<const Eigen::Matrix3Xd> vertices (mean.data (), 3, mean.size () / 3);
  LandmarkVertices landmarks;
  for (const auto& [id, position] : positions) {
    Eigen::Index nearest = 0;
    (vertices.colwise () - position).colwise ().squaredNorm ().minCoeff (&nearest);
    landmarks[id] = static_cast<int> (nearest);
  }
  return landmarks;
}

std::vector<double>
rowMajor (const Eigen::MatrixXd& matrix)
{
  std::vector<double> values (matrix.size ());
  Eigen::Map<RowMajorMatrix> (values.data (), matrix.rows (), matrix.cols ()) = matrix;
  return values;
}

void
writeStatismo (hdf5::Writer& file, const MorphableModel& model)
{
  const auto n = static_cast<hsize_t> (model.numVertices ());
  const auto k = static_cast<hsize_t> (model.globalVariances ().size ());
  file.group ("model");
  file.floats ("model/mean", {3 * n}, model.mean ().data (), false);
  file.floats ("model/pcaBasis", {3 * n, k}, rowMajor (model.globalBasis ()).data (), false);
  file.floats ("model/pcaVariance", {k}, model.globalVariances ().data (), false);
  file.scalarFloat ("model/noiseVariance", model.noiseVariance ());

  file.group ("representer");
  file.attribute ("representer", "name", "vtkStandardMeshRepresenter");
  file.attribute ("representer", "datasetType", "POLYGON_MESH");
  const Eigen::Map<const Eigen::Matrix3Xd> points (model.mean ().data (), 3, model.numVertices ());
  file.floats ("representer/points", {3, n}, rowMajor (points).data (), false);
  std::vector<int> cells (model.triangles ().size ());
  Eigen::Map<Eigen::Matrix<int, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> (
      cells.data (), 3, model.triangles ().cols ()) = model.triangles ();
  file.integers ("representer/cells", {3, static_cast<hsize_t> (model.triangles ().cols ())}, cells.data ());

  file.group ("version");
  file.scalarInt ("version/majorVersion", 0);
  file.scalarInt ("version/minorVersion", 9);
  file.group ("modelinfo");
  const std::time_t now = std::time (nullptr);
  char stamp[32];
  std::strftime (stamp, sizeof (stamp), "%Y-%m-%dT%H:%M:%SZ", std::gmtime (&now));
  file.string ("modelinfo/build-time", stamp);
  file.floats ("modelinfo/scores", {k, 0}, nullptr, false);
  file.group ("modelinfo/builderInfo");
}

void
writeMorphreg (hdf5::Writer& file, const MorphableModel& model)
{
  file.group ("morphreg");
  file.scalarInt ("morphreg/formatVersion", 1);
  file.floats ("morphreg/mean", {static_cast<hsize_t> (model.mean ().size ())}, model.mean ().data (), true);
  file.string ("morphreg/units", model.units ());
  file.string ("morphreg/landmarks", nlohmann::json (model.landmarks ()).dump ());
  file.string ("morphreg/metadata", nlohmann::json (model.metadata ()).dump ());
  file.integers ("morphreg/profileLine", {model.profileLine ().size ()}, model.profileLine ().data ());
  file.scalarInt ("morphreg/numRegions", model.numRegions ());
  file.group ("morphreg/regions");
  for (int j = 0; j < model.numRegions (); ++j) {
    const ModelRegion& region = model.region (j);
    const std::string group = "morphreg/regions/region_" + std::to_string (j);
    const auto b = static_cast<hsize_t> (region.vertices.size ());
    const auto p = static_cast<hsize_t> (region.variances.size ());
    file.group (group);
    file.string (group + "/name", region.name);
    file.integers (group + "/vertices", {b}, region.vertices.data ());
    file.floats (group + "/weights", {b}, region.weights.data (), true);
    file.floats (group + "/basis", {3 * b, p}, rowMajor (region.basis).data (), true);
    file.floats (group + "/variances", {p}, region.variances.data (), true);
  }
}
} // namespace

void
saveModel (const std::string& path, const MorphableModel& model)
{
  hdf5::Writer file (path);
  writeStatismo (file, model);
  writeMorphreg (file, model);
  file.close ();
}

MorphableModel::Ptr
loadModel (const std::string& path)
{
  const hdf5::Reader file (path);
  if (file.exists ("morphreg"))
    return readMorphreg (file);
  if (file.exists ("model/mean") || !file.exists ("shape/model/mean"))
    return loadStatismoModel (path, "");
  return loadStatismoModel (path, "shape");
}

MorphableModel::Ptr
loadStatismoModel (const std::string& path, const std::string& prefix)
{
  const hdf5::Reader file (path);
  StatismoPart part = readStatismo (file, prefix);
  const UnitConversion unit = guessedUnit (path, part.mean);
  const LandmarkVertices landmarks = readBfmLandmarks (file, part.mean);
  scaleToMillimetres (part, unit.to_mm);
  try {
    auto model = MorphableModel::fromGlobalPca (std::move (part.triangles), std::move (part.mean),
                                                std::move (part.basis), std::move (part.variances));
    model->setNoiseVariance (part.noise_variance);
    model->setLandmarks (landmarks);
    model->setMetadata ({{"source", path}, {"format", "statismo"}, {kFileUnitsKey, unit.description}});
    requireConsistentModel (*model, path);
    return model;
  }
  catch (const InvalidInputError& e) {
    throw FormatError (path + ": " + e.detailedMessage ());
  }
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/model/impl/morphable_model.hpp>

#include <Eigen/Cholesky>

#include <cmath>
#include <limits>

namespace morphreg
{
namespace
{
/** Tolerance for blending weights summing to 1 (float32 files round them). */
constexpr double kWeightSumTolerance = 1e-5;

std::string
regionLabel (const ModelRegion& region, int index)
{
  return "region " + std::to_string (index) + (region.name.empty () ? "" : " (" + region.name + ")");
}
} // namespace

MorphableModel::MorphableModel (TriangleMesh::Triangles triangles, Eigen::VectorXd mean,
                                std::vector<ModelRegion> regions)
  : triangles_ (std::move (triangles)), mean_ (std::move (mean)), regions_ (std::move (regions))
{
  if (mean_.size () == 0 || mean_.size () % 3 != 0)
    throw InvalidInputError ("MorphableModel: mean has " + std::to_string (mean_.size ()) + " values, expected 3N > 0");
  if (!mean_.allFinite ())
    throw InvalidInputError ("MorphableModel: mean has non-finite values");
  TriangleMesh mesh;
  mesh.vertices = Eigen::Map<const Eigen::Matrix3Xd> (mean_.data (), 3, numVertices ());
  mesh.triangles = triangles_;
  validateMesh (mesh, "MorphableModel mean mesh");
  if (regions_.empty ())
    throw InvalidInputError ("MorphableModel: at least one region is needed");
  for (int j = 0; j < numRegions (); ++j)
    validateRegion (regions_[j], j);
  buildVertexIndex ();
}

MorphableModel::Ptr
MorphableModel::fromGlobalPca (TriangleMesh::Triangles triangles, Eigen::VectorXd mean, Eigen::MatrixXd basis,
                               Eigen::VectorXd variances)
{
  ModelRegion region;
  region.name = "global";
  const Eigen::Index n = mean.size () / 3;
  region.vertices.resize (n);
  for (Eigen::Index i = 0; i < n; ++i)
    region.vertices[i] = static_cast<int> (i);
  region.weights = Eigen::VectorXd::Ones (n);
  region.basis = basis;
  region.variances = variances;
  auto model = std::make_shared<MorphableModel> (std::move (triangles), std::move (mean),
                                                 std::vector<ModelRegion>{std::move (region)});
  model->setGlobalPca (std::move (basis), std::move (variances));
  return model;
}

void
MorphableModel::validateRegion (const ModelRegion& region, int index) const
{
  const std::string label = "MorphableModel: " + regionLabel (region, index);
  const auto b = static_cast<Eigen::Index> (region.vertices.size ());
  if (b == 0)
    throw InvalidInputError (label + " has no vertices");
  for (Eigen::Index r = 0; r < b; ++r) {
    const int v = region.vertices[r];
    if (v < 0 || v >= numVertices ())
      throw InvalidInputError (label + ": vertex " + std::to_string (v) + " is out of range [0, " +
                               std::to_string (numVertices ()) + ")");
    if (r > 0 && v <= region.vertices[r - 1])
      throw InvalidInputError (label + ": vertex indices are not strictly increasing at position " +
                               std::to_string (r));
  }
  if (region.weights.size () != b)
    throw InvalidInputError (label + " has " + std::to_string (region.weights.size ()) + " weights for " +
                             std::to_string (b) + " vertices");
  if (!region.weights.allFinite () || region.weights.minCoeff () < 0.0 || region.weights.maxCoeff () > 1.0)
    throw InvalidInputError (label + ": blending weights must be finite and in [0, 1]");
  if (region.basis.rows () != 3 * b || region.basis.cols () != region.variances.size ())
    throw InvalidInputError (label + ": basis is " + std::to_string (region.basis.rows ()) + " x " +
                             std::to_string (region.basis.cols ()) + ", expected " + std::to_string (3 * b) + " x " +
                             std::to_string (region.variances.size ()) + " (3 x vertices, variances)");
  if (!region.basis.allFinite ())
    throw InvalidInputError (label + ": basis has non-finite values");
  if (!region.variances.allFinite () || (region.variances.size () > 0 && region.variances.minCoeff () < 0.0))
    throw InvalidInputError (label + ": variances must be finite and non-negative");
}

void
MorphableModel::buildVertexIndex ()
{
  const Eigen::Index n = numVertices ();
  std::vector<std::vector<RegionEntry>> per_vertex (n);
  for (int j = 0; j < numRegions (); ++j)
    for (size_t r = 0; r < regions_[j].vertices.size (); ++r)
      per_vertex[regions_[j].vertices[r]].push_back ({j, static_cast<int> (r), regions_[j].weights[r]});

  entry_offsets_.assign (1, 0);
  entries_.clear ();
  gamma_pairs_.clear ();
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto& list = per_vertex[i];
    double sum = 0.0;
    for (const RegionEntry& e : list)
      sum += e.weight;
    if (list.empty () || std::abs (sum - 1.0) > kWeightSumTolerance)
      throw InvalidInputError (
          "MorphableModel: vertex " + std::to_string (i) +
          (list.empty () ? " is in no region" : "'s blending weights sum to " + std::to_string (sum) + ", not 1"));
    if (list.size () == 2)
      gamma_pairs_.push_back ({static_cast<int> (i), list[0].region, list[0].row, list[1].region, list[1].row});
    entries_.insert (entries_.end (), list.begin (), list.end ());
    entry_offsets_.push_back (static_cast<int> (entries_.size ()));
  }
}

TriangleMesh
MorphableModel::meanMesh () const
{
  return generateMesh (Eigen::VectorXd::Zero (0), ComponentSelection (std::vector<int> (numRegions (), 0)));
}

int
MorphableModel::findRegion (const std::string& name) const
{
  for (int j = 0; j < numRegions (); ++j)
    if (regions_[j].name == name)
      return j;
  return -1;
}

ComponentSelection
MorphableModel::allComponents () const
{
  std::vector<int> counts;
  for (const ModelRegion& region : regions_)
    counts.push_back (static_cast<int> (region.basis.cols ()));
  return ComponentSelection (counts);
}

ComponentSelection
MorphableModel::firstComponents (int k) const
{
  return firstComponents (std::vector<int> (numRegions (), k));
}

ComponentSelection
MorphableModel::firstComponents (const std::vector<int>& k) const
{
  if (static_cast<int> (k.size ()) != numRegions ())
    throw InvalidInputError ("MorphableModel::firstComponents: " + std::to_string (k.size ()) +
                             " counts for a model with " + std::to_string (numRegions ()) + " regions");
  std::vector<int> counts;
  for (int j = 0; j < numRegions (); ++j) {
    if (k[j] < 0)
      throw InvalidInputError ("MorphableModel::firstComponents: negative count for region " + std::to_string (j));
    counts.push_back (std::min (k[j], static_cast<int> (regions_[j].basis.cols ())));
  }
  return ComponentSelection (counts);
}

void
MorphableModel::requireCompatible (const ComponentSelection& selection, const Eigen::VectorXd* coefficients,
                                   const std::string& what) const
{
  if (selection.numRegions () != numRegions ())
    throw InvalidInputError (what + ": component selection has " + std::to_string (selection.numRegions ()) +
                             " regions, the model " + std::to_string (numRegions ()));
  for (int j = 0; j < numRegions (); ++j)
    if (selection.count (j) > regions_[j].basis.cols ())
      throw InvalidInputError (what + ": selects " + std::to_string (selection.count (j)) + " components of " +
                               regionLabel (regions_[j], j) + ", which has " +
                               std::to_string (regions_[j].basis.cols ()));
  if (coefficients && coefficients->size () != selection.total ())
    throw InvalidInputError (what + ": " + std::to_string (coefficients->size ()) + " coefficients, expected " +
                             std::to_string (selection.total ()));
  if (coefficients && !coefficients->allFinite ())
    throw InvalidInputError (what + ": coefficients are not finite");
}

Eigen::Matrix3Xd
MorphableModel::shapeRows (int vertex, const ComponentSelection& selection) const
{
  Eigen::Matrix3Xd rows = Eigen::Matrix3Xd::Zero (3, selection.total ());
  for (const RegionEntry& e : vertexEntries (vertex)) {
    const int count = selection.count (e.region);
    rows.middleCols (selection.offset (e.region), count) = e.weight * regionRows (e.region, e.row, count);
  }
  return rows;
}

MorphableModel::RowMatrix
MorphableModel::shapeMatrix (const ComponentSelection& selection) const
{
  requireCompatible (selection, nullptr, "MorphableModel::shapeMatrix");
  RowMatrix h = RowMatrix::Zero (3 * numVertices (), selection.total ());
  for (Eigen::Index i = 0; i < numVertices (); ++i)
    for (const RegionEntry& e : vertexEntries (static_cast<int> (i))) {
      const int count = selection.count (e.region);
      h.block (3 * i, selection.offset (e.region), 3, count) = e.weight * regionRows (e.region, e.row, count);
    }
  return h;
}

Eigen::Vector3d
MorphableModel::vertex (int vertex, const Eigen::VectorXd& coefficients, const ComponentSelection& selection) const
{
  Eigen::Vector3d p = meanVertex (vertex);
  for (const RegionEntry& e : vertexEntries (vertex)) {
    const int count = selection.count (e.region);
    p += e.weight * regionRows (e.region, e.row, count) * coefficients.segment (selection.offset (e.region), count);
  }
  return p;
}

MorphableModel::RowMatrix
MorphableModel::gammaMatrix (const ComponentSelection& selection) const
{
  requireCompatible (selection, nullptr, "MorphableModel::gammaMatrix");
  RowMatrix gamma = RowMatrix::Zero (3 * static_cast<Eigen::Index> (gamma_pairs_.size ()), selection.total ());
  for (size_t l = 0; l < gamma_pairs_.size (); ++l) {
    const GammaPair& g = gamma_pairs_[l];
    const Eigen::Index row = 3 * static_cast<Eigen::Index> (l);
    gamma.block (row, selection.offset (g.region_a), 3, selection.count (g.region_a)) =
        regionRows (g.region_a, g.row_a, selection.count (g.region_a));
    gamma.block (row, selection.offset (g.region_b), 3, selection.count (g.region_b)) =
        -regionRows (g.region_b, g.row_b, selection.count (g.region_b));
  }
  return gamma;
}

Eigen::Matrix3Xd
MorphableModel::gammaResiduals (const Eigen::VectorXd& coefficients, const ComponentSelection& selection) const
{
  requireCompatible (selection, &coefficients, "MorphableModel::gammaResiduals");
  Eigen::Matrix3Xd residuals (3, gamma_pairs_.size ());
  for (size_t l = 0; l < gamma_pairs_.size (); ++l) {
    const GammaPair& g = gamma_pairs_[l];
    const int ca = selection.count (g.region_a);
    const int cb = selection.count (g.region_b);
    residuals.col (l) =
        regionRows (g.region_a, g.row_a, ca) * coefficients.segment (selection.offset (g.region_a), ca) -
        regionRows (g.region_b, g.row_b, cb) * coefficients.segment (selection.offset (g.region_b), cb);
  }
  return residuals;
}

Eigen::VectorXd
MorphableModel::variances (const ComponentSelection& selection) const
{
  requireCompatible (selection, nullptr, "MorphableModel::variances");
  Eigen::VectorXd stacked (selection.total ());
  for (int j = 0; j < numRegions (); ++j)
    stacked.segment (selection.offset (j), selection.count (j)) = regions_[j].variances.head (selection.count (j));
  return stacked;
}

Eigen::VectorXd
MorphableModel::lambdaDiagonal (const ComponentSelection& selection, ShapePrior prior) const
{
  const Eigen::VectorXd var = variances (selection);
  if (prior == ShapePrior::identity || var.size () == 0)
    return Eigen::VectorXd::Ones (var.size ());
  const double floor = std::max (1e-12 * var.maxCoeff (), std::numeric_limits<double>::min ());
  return var.cwiseMax (floor).cwiseSqrt ().cwiseInverse ();
}

Eigen::Matrix3Xd
MorphableModel::displacements (const Eigen::VectorXd& coefficients, const ComponentSelection& selection) const
{
  // Region by region: one dense product per region, then scattered with the blending weights.
  Eigen::Matrix3Xd offsets = Eigen::Matrix3Xd::Zero (3, numVertices ());
  for (int j = 0; j < numRegions (); ++j) {
    const int count = selection.count (j);
    if (count == 0)
      continue;
    const ModelRegion& region = regions_[j];
    const Eigen::VectorXd local = region.basis.leftCols (count) * coefficients.segment (selection.offset (j), count);
    for (size_t r = 0; r < region.vertices.size (); ++r)
      offsets.col (region.vertices[r]) += region.weights[r] * local.segment<3> (3 * r);
  }
  return offsets;
}

Eigen::Matrix3Xd
MorphableModel::generate (const Eigen::VectorXd& coefficients, const ComponentSelection& selection) const
{
  requireCompatible (selection, &coefficients, "MorphableModel::generate");
  return Eigen::Map<const Eigen::Matrix3Xd> (mean_.data (), 3, numVertices ()) +
         displacements (coefficients, selection);
}

TriangleMesh
MorphableModel::generateMesh (const Eigen::VectorXd& coefficients, const ComponentSelection& selection) const
{
  TriangleMesh mesh;
  mesh.vertices = generate (coefficients, selection);
  mesh.triangles = triangles_;
  return mesh;
}

pcl::PolygonMesh
MorphableModel::generatePolygonMesh (const Eigen::VectorXd& coefficients, const ComponentSelection& selection) const
{
  return toPolygonMesh (generateMesh (coefficients, selection));
}

Eigen::VectorXd
MorphableModel::sampleCoefficients (std::mt19937_64& rng, const ComponentSelection& selection) const
{
  const Eigen::VectorXd std_devs = variances (selection).cwiseSqrt ();
  std::normal_distribution<double> normal;
  Eigen::VectorXd coefficients (std_devs.size ());
  for (Eigen::Index c = 0; c < std_devs.size (); ++c)
    coefficients[c] = std_devs[c] * normal (rng);
  return coefficients;
}

MorphableModel::Projection
MorphableModel::project (const Eigen::Matrix3Xd& shape, const ComponentSelection& selection, double regularization,
                         ShapePrior prior) const
{
  requireCompatible (selection, nullptr, "MorphableModel::project");
  if (shape.cols () != numVertices ())
    throw InvalidInputError ("MorphableModel::project: shape has " + std::to_string (shape.cols ()) +
                             " vertices, the model " + std::to_string (numVertices ()));
  if (!shape.allFinite ())
    throw InvalidInputError ("MorphableModel::project: shape has non-finite vertices");
  if (!std::isfinite (regularization) || regularization < 0.0)
    throw InvalidInputError ("MorphableModel::project: regularization must be finite and >= 0");

  const RowMatrix h = shapeMatrix (selection);
  const Eigen::Map<const Eigen::VectorXd> target (shape.data (), shape.size ());
  const Eigen::VectorXd lambda = lambdaDiagonal (selection, prior);
  Eigen::MatrixXd normal = h.transpose () * h;
  normal.diagonal () += regularization * lambda.cwiseAbs2 ();
  const Eigen::LDLT<Eigen::MatrixXd> solver (normal);
  const double scale = normal.size () ? normal.diagonal ().cwiseAbs ().maxCoeff () : 0.0;
  if (solver.info () != Eigen::Success || (normal.size () && solver.vectorD ().minCoeff () <= 1e-12 * scale))
    throw NumericalError ("MorphableModel::project: the normal equations are singular (a selected component has "
                          "no support); add regularization or select fewer components");

  Projection result;
  result.coefficients = solver.solve (h.transpose () * (target - mean_));
  result.reconstruction = generate (result.coefficients, selection);
  const Eigen::VectorXd distances = (result.reconstruction - shape).colwise ().norm ();
  result.rms_error = std::sqrt (distances.squaredNorm () / static_cast<double> (distances.size ()));
  result.max_error = distances.maxCoeff ();
  return result;
}

MorphableModel::Projection
MorphableModel::project (const TriangleMesh& mesh, const ComponentSelection& selection, double regularization,
                         ShapePrior prior) const
{
  TriangleMesh reference;
  reference.vertices = Eigen::Map<const Eigen::Matrix3Xd> (mean_.data (), 3, numVertices ());
  reference.triangles = triangles_;
  requireSameTopology (reference, mesh, "MorphableModel::project mesh");
  return project (mesh.vertices, selection, regularization, prior);
}

void
MorphableModel::setGlobalPca (Eigen::MatrixXd basis, Eigen::VectorXd variances)
{
  if (basis.rows () != mean_.size () || basis.cols () != variances.size ())
    throw InvalidInputError ("MorphableModel::setGlobalPca: basis is " + std::to_string (basis.rows ()) + " x " +
                             std::to_string (basis.cols ()) + ", expected " + std::to_string (mean_.size ()) + " x " +
                             std::to_string (variances.size ()));
  if (!basis.allFinite () || !variances.allFinite () || (variances.size () && variances.minCoeff () < 0.0))
    throw InvalidInputError ("MorphableModel::setGlobalPca: non-finite basis or negative/non-finite variances");
  global_basis_ = std::move (basis);
  global_variances_ = std::move (variances);
}

void
MorphableModel::setNoiseVariance (double variance)
{
  if (!std::isfinite (variance) || variance < 0.0)
    throw InvalidInputError ("MorphableModel::setNoiseVariance: must be finite and >= 0, got " +
                             std::to_string (variance));
  noise_variance_ = variance;
}

void
MorphableModel::setLandmarks (LandmarkVertices landmarks)
{
  for (const auto& [name, index] : landmarks) {
    if (name.empty ())
      throw InvalidInputError ("MorphableModel::setLandmarks: empty landmark name");
    if (index < 0 || index >= numVertices ())
      throw InvalidInputError ("MorphableModel::setLandmarks: landmark '" + name + "' has vertex " +
                               std::to_string (index) + ", out of range [0, " + std::to_string (numVertices ()) + ")");
  }
  landmarks_ = std::move (landmarks);
}

int
MorphableModel::landmarkVertex (const std::string& name) const
{
  const auto it = landmarks_.find (name);
  if (it != landmarks_.end ())
    return it->second;
  std::string known;
  for (const auto& entry : landmarks_)
    known += (known.empty () ? "" : ", ") + entry.first;
  throw InvalidInputError ("MorphableModel: no landmark '" + name +
                           "'; the model has: " + (known.empty () ? std::string ("none") : known));
}

void
MorphableModel::setProfileLine (std::vector<int> vertices)
{
  for (const int v : vertices)
    if (v < 0 || v >= numVertices ())
      throw InvalidInputError ("MorphableModel::setProfileLine: vertex " + std::to_string (v) + " out of range [0, " +
                               std::to_string (numVertices ()) + ")");
  profile_line_ = std::move (vertices);
}

void
MorphableModel::setUnits (std::string units)
{
  if (units.empty ())
    throw InvalidInputError ("MorphableModel::setUnits: empty unit name");
  units_ = std::move (units);
}

void
MorphableModel::setMetadata (std::map<std::string, std::string> metadata)
{
  metadata_ = std::move (metadata);
}

} // namespace morphreg

#define MORPHREG_INSTANTIATE_MORPHABLE_MODEL(T)                                                                        \
  template pcl::PointCloud<T>::Ptr morphreg::MorphableModel::generateCloud<T> (                                        \
      const Eigen::VectorXd&, const morphreg::ComponentSelection&) const;
MORPHREG_INSTANTIATE_MORPHABLE_MODEL (pcl::PointXYZ)
MORPHREG_INSTANTIATE_MORPHABLE_MODEL (pcl::PointNormal)
MORPHREG_INSTANTIATE_MORPHABLE_MODEL (pcl::PointXYZRGBNormal)
#undef MORPHREG_INSTANTIATE_MORPHABLE_MODEL

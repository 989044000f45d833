#pragma once

#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/registration/cached_correspondence_estimation.h>
#include <morphreg/registration/global_alignment.h>
#include <morphreg/registration/initial_alignment.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/registration/similarity_shape_step.h>

#include <pcl/conversions.h>
#include <pcl/registration/correspondence_estimation.h>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>

namespace morphreg
{
/** The unknowns of the fit. The model instance v = mu + H m is cached with m. */
template <typename PointTarget, typename Scalar>
struct MorphableICP<PointTarget, Scalar>::State
{
  double log_scale = 0.0;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity ();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero ();
  ComponentSelection selection; ///< the components \a coefficients stacks
  Eigen::VectorXd coefficients;
  Eigen::Matrix3Xd model_vertices;

  Eigen::Matrix3Xd
  transformed () const
  {
    return (std::exp (log_scale) * rotation * model_vertices).colwise () + translation;
  }

  Eigen::Matrix4d
  similarity () const
  {
    Eigen::Matrix4d m = Eigen::Matrix4d::Identity ();
    m.topLeftCorner<3, 3> () = std::exp (log_scale) * rotation;
    m.topRightCorner<3, 1> () = translation;
    return m;
  }
};

/** Accepted correspondences of one iteration, with their IRLS weights and the mean squared distance. */
template <typename PointTarget, typename Scalar>
struct MorphableICP<PointTarget, Scalar>::Evaluation
{
  Eigen::Matrix3Xd transformed;
  typename pcl::PointCloud<PointTarget>::Ptr cloud;
  pcl::Correspondences kept;
  std::vector<double> distances;
  std::vector<double> weights;
  int found = 0;
  double error = 0.0;
};

/** Fixed parts of the normal equations of one stage: the shape prior block and the landmark rows. */
template <typename PointTarget, typename Scalar>
struct MorphableICP<PointTarget, Scalar>::Problem
{
  bool shape = false;
  ComponentSelection selection;     ///< the components fitted (shape stage)
  Eigen::VectorXd sigma;            ///< their prior standard deviations
  Eigen::MatrixXd prior;            ///< lambda_1^2 Gamma^T Gamma + lambda_2^2 Lambda^2 (P x P)
  std::vector<int> landmark_vertices;
  Eigen::Matrix3Xd landmark_points;
};

namespace detail
{
inline double
medianOf (std::vector<double> values)
{
  if (values.empty ())
    return 0.0;
  const auto mid = values.begin () + static_cast<long> (values.size () / 2);
  std::nth_element (values.begin (), mid, values.end ());
  return *mid;
}

/** \a weight if it is finite and >= 0; else InvalidInputError naming \a what. */
inline double
requireWeight (double weight, const std::string& what)
{
  if (!(weight >= 0.0) || !std::isfinite (weight))
    throw InvalidInputError (what + " must be finite and >= 0, got " + std::to_string (weight));
  return weight;
}

/** \a coefficients of \a from restacked for \a to: shared leading components kept, new ones zero. */
inline Eigen::VectorXd
restack (const Eigen::VectorXd& coefficients, const ComponentSelection& from, const ComponentSelection& to)
{
  Eigen::VectorXd result = Eigen::VectorXd::Zero (to.total ());
  for (int r = 0; r < to.numRegions () && r < from.numRegions (); ++r) {
    const int shared = std::min (from.count (r), to.count (r));
    result.segment (to.offset (r), shared) = coefficients.segment (from.offset (r), shared);
  }
  return result;
}

/** IRLS weight of a residual distance \a d for kernel width \a c. */
inline double
robustWeight (RobustLoss loss, double d, double c)
{
  switch (loss) {
  case RobustLoss::huber:
    return d <= c ? 1.0 : c / d;
  case RobustLoss::tukey: {
    if (d >= c)
      return 0.0;
    const double u = 1.0 - (d / c) * (d / c);
    return u * u;
  }
  case RobustLoss::none:
    break;
  }
  return 1.0;
}

/** Unit normal of \a neighbours' least-squares plane and whether the largest angular gap between them around
 *  \a centre, in that plane, exceeds 90 degrees (a boundary point).
 */
inline bool
isBoundaryPoint (const Eigen::Vector3d& centre, const Eigen::Vector3d& normal, const Eigen::Matrix3Xd& neighbours)
{
  const Eigen::Vector3d u = normal.unitOrthogonal ();
  const Eigen::Vector3d v = normal.cross (u);
  std::vector<double> angles;
  for (Eigen::Index k = 0; k < neighbours.cols (); ++k) {
    const Eigen::Vector3d d = neighbours.col (k) - centre;
    if (d.squaredNorm () > 0.0)
      angles.push_back (std::atan2 (d.dot (v), d.dot (u)));
  }
  if (angles.size () < 3)
    return true;
  std::sort (angles.begin (), angles.end ());
  double gap = angles.front () + 2.0 * M_PI - angles.back ();
  for (size_t k = 1; k < angles.size (); ++k)
    gap = std::max (gap, angles[k] - angles[k - 1]);
  return gap > 0.5 * M_PI;
}
} // namespace detail

template <typename PointTarget, typename Scalar>
MorphableICP<PointTarget, Scalar>::MorphableICP ()
{
  this->reg_name_ = "MorphableICP";
  this->max_iterations_ = 50;
  this->correspondence_estimation_.reset (new CachedCorrespondenceEstimation<PointTarget, PointTarget, Scalar>);
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setModel (const MorphableModel::ConstPtr& model)
{
  if (!model)
    throw InvalidInputError ("MorphableICP::setModel: the model is null");
  for (const auto& landmark : landmarks_)
    model->landmarkVertex (landmark.first);
  model_ = model;
  selection_ = model_->firstComponents (10);
  const TriangleMesh mean{Eigen::Map<const Eigen::Matrix3Xd> (model_->mean ().data (), 3, model_->numVertices ()),
                          model_->triangles ()};
  const Eigen::VectorXd areas = triangleAreas (mean);
  vertex_area_weights_ = Eigen::VectorXd::Zero (model_->numVertices ());
  for (Eigen::Index t = 0; t < mean.triangles.cols (); ++t)
    for (int corner = 0; corner < 3; ++corner)
      vertex_area_weights_[mean.triangles (corner, t)] += areas[t] / 3.0;
  vertex_area_weights_ /= std::max (vertex_area_weights_.mean (), std::numeric_limits<double>::min ());
  Base::setInputSource (model_->generateCloud<PointTarget> (Eigen::VectorXd::Zero (selection_.total ()),
                                                              selection_));
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setComponentSelection (const ComponentSelection& selection)
{
  if (!model_)
    throw InvalidInputError ("MorphableICP::setComponentSelection: set a model first");
  model_->requireCompatible (selection, nullptr, "MorphableICP::setComponentSelection");
  selection_ = selection;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setSmoothnessWeight (double lambda1)
{
  lambda1_ = detail::requireWeight (lambda1, "MorphableICP::setSmoothnessWeight: lambda_1");
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setRefinementSmoothnessWeight (double lambda1)
{
  refinement_lambda1_ = detail::requireWeight (lambda1, "MorphableICP::setRefinementSmoothnessWeight: lambda_1");
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setShapeSchedule (std::vector<ShapePhase> phases)
{
  for (size_t k = 0; k < phases.size (); ++k)
    detail::requireWeight (phases[k].smoothness_weight,
                           "MorphableICP::setShapeSchedule: lambda_1 of phase " + std::to_string (k));
  schedule_ = std::move (phases);
}

template <typename PointTarget, typename Scalar>
std::vector<ShapePhase>
MorphableICP<PointTarget, Scalar>::effectiveShapeSchedule () const
{
  if (!schedule_.empty ())
    return schedule_;
  return {{selection_, lambda1_}, {selection_, refinement_lambda1_}};
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setShapePriorWeight (double lambda2, ShapePrior prior)
{
  lambda2_ = detail::requireWeight (lambda2, "MorphableICP::setShapePriorWeight: lambda_2");
  prior_ = prior;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setSimilarityIterations (int iterations)
{
  if (iterations < 1)
    throw InvalidInputError ("MorphableICP::setSimilarityIterations: at least 1 iteration is needed");
  similarity_iterations_ = iterations;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setPointToPlane (bool enabled, double tangential_weight)
{
  if (!(tangential_weight >= 0.0 && tangential_weight <= 1.0))
    throw InvalidInputError ("MorphableICP::setPointToPlane: the tangential weight must be in [0, 1]");
  point_to_plane_ = enabled;
  tangential_weight_ = tangential_weight;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setRobustLoss (RobustLoss loss, double scale)
{
  if (!std::isfinite (scale))
    throw InvalidInputError ("MorphableICP::setRobustLoss: the kernel width must be finite");
  robust_loss_ = loss;
  robust_scale_ = scale;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setRejectTargetBoundary (bool enabled, int neighbours)
{
  if (neighbours < 4)
    throw InvalidInputError ("MorphableICP::setRejectTargetBoundary: at least 4 neighbours are needed");
  reject_boundary_ = enabled;
  if (neighbours != boundary_neighbours_)
    target_prepared_ = false;
  boundary_neighbours_ = neighbours;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setTargetSmoothing (bool enabled)
{
  if (enabled != smooth_target_)
    target_prepared_ = false;
  smooth_target_ = enabled;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setDivergenceGuard (double max_sigma, int rising_iterations)
{
  if (!std::isfinite (max_sigma) || rising_iterations < 1)
    throw InvalidInputError ("MorphableICP::setDivergenceGuard: need a finite limit and >= 1 rising iteration");
  max_sigma_ = max_sigma;
  rising_iterations_ = rising_iterations;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setTargetLandmarks (const LandmarkPositions& landmarks, double weight)
{
  detail::requireWeight (weight, "MorphableICP::setTargetLandmarks: the landmark weight");
  for (const auto& landmark : landmarks) {
    if (!landmark.second.allFinite ())
      throw InvalidInputError ("MorphableICP::setTargetLandmarks: landmark '" + landmark.first +
                               "' is not finite");
    if (model_)
      model_->landmarkVertex (landmark.first);
  }
  landmarks_ = landmarks;
  landmark_weight_ = weight;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setInputTarget (const PointCloudTargetConstPtr& cloud)
{
  Base::setInputTarget (cloud);
  target_prepared_ = false;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::validateInputs () const
{
  if (!model_)
    throw InvalidInputError ("MorphableICP: no model (call setModel)");
  if (!this->input_ || static_cast<Eigen::Index> (this->input_->size ()) != model_->numVertices ())
    throw InvalidInputError ("MorphableICP: the source cloud must be the model instance of setModel (" +
                             std::to_string (model_->numVertices ()) + " points)");
  if (!this->target_)
    throw InvalidInputError ("MorphableICP: no target cloud (call setInputTarget)");
  requireFiniteNonEmpty (*this->target_, "MorphableICP target");
  for (const auto& landmark : landmarks_)
    model_->landmarkVertex (landmark.first);
  for (size_t k = 0; k < schedule_.size (); ++k) {
    const ComponentSelection& phase = schedule_[k].components;
    model_->requireCompatible (phase, nullptr, "MorphableICP shape schedule");
    for (int r = 0; r < phase.numRegions (); ++r)
      if (phase.count (r) > selection_.count (r))
        throw InvalidInputError ("MorphableICP: shape phase " + std::to_string (k) + " fits " +
                                 std::to_string (phase.count (r)) + " components of region " + std::to_string (r) +
                                 ", more than the component selection's " + std::to_string (selection_.count (r)));
  }
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::align (PointCloudSource& output)
{
  align (output, Matrix4::Identity ());
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::align (PointCloudSource& output, const Matrix4& guess)
{
  validateInputs ();
  const LengthUnitGuess unit = resolveTargetUnit ();
  const double to_mm = millimetresPer (unit.unit);
  if (to_mm == 1.0)
    Base::align (output, guess);
  else
    alignInMillimetres (output, guess, to_mm);
  report_.target_unit = toString (unit.unit);
  report_.target_unit_reason = unit.reason;
}

template <typename PointTarget, typename Scalar>
LengthUnitGuess
MorphableICP<PointTarget, Scalar>::resolveTargetUnit () const
{
  if (target_unit_)
    return {*target_unit_, 0.0, "given"};
  const Eigen::Map<const Eigen::Matrix3Xd> mean (model_->mean ().data (), 3, model_->numVertices ());
  const Eigen::Vector3d centroid = mean.rowwise ().mean ();
  const double model_radius = std::sqrt ((mean.colwise () - centroid).colwise ().squaredNorm ().mean ());
  Eigen::Matrix3Xd target (3, this->target_->size ());
  for (size_t i = 0; i < this->target_->size (); ++i)
    target.col (i) = (*this->target_)[i].getVector3fMap ().template cast<double> ();
  return guessLengthUnit (target, model_radius);
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::alignInMillimetres (PointCloudSource& output, const Matrix4& guess, double to_mm)
{
  const PointCloudTargetConstPtr user_target = this->target_;
  const LandmarkPositions user_landmarks = landmarks_;
  typename PointCloudTarget::Ptr scaled (new PointCloudTarget (*user_target));
  for (auto& point : *scaled)
    point.getVector3fMap () *= static_cast<float> (to_mm);
  for (auto& landmark : landmarks_)
    landmark.second *= to_mm;
  Matrix4 scaled_guess = guess;
  if (!guess.isIdentity ()) // the identity means "no guess" (see IcpInitialisation::automatic)
    scaled_guess.template topRows<3> () *= static_cast<Scalar> (to_mm);
  const auto restore = [&] () {
    landmarks_ = user_landmarks;
    setInputTarget (user_target);
  };
  setInputTarget (scaled);
  try {
    Base::align (output, scaled_guess);
  }
  catch (...) {
    restore ();
    throw;
  }
  restore ();
  for (auto& point : output)
    point.getVector3fMap () /= static_cast<float> (to_mm);
  fitted_vertices_ /= to_mm;
  this->final_transformation_.template topRows<3> () /= static_cast<Scalar> (to_mm);
  this->transformation_ = this->final_transformation_;
  report_.initial_transformation.template topRows<3> () /= to_mm;
}

template <typename PointTarget, typename Scalar>
Eigen::Matrix4d
MorphableICP<PointTarget, Scalar>::initialTransformation (const Matrix4& guess)
{
  const Eigen::Matrix4d given = guess.template cast<double> ();
  IcpInitialisation mode = initialisation_;
  if (mode == IcpInitialisation::automatic)
    mode = !given.isIdentity () ? IcpInitialisation::guess
           : landmarks_.size () >= 3 ? IcpInitialisation::landmarks
                                     : IcpInitialisation::global;
  report_.initialisation = mode == IcpInitialisation::guess       ? "guess"
                           : mode == IcpInitialisation::landmarks ? "landmarks"
                           : mode == IcpInitialisation::coarse    ? "coarse"
                                                                  : "global";
  if (mode == IcpInitialisation::guess)
    return given;
  if (mode == IcpInitialisation::landmarks) {
    if (landmarks_.size () < 3)
      throw InvalidInputError ("MorphableICP: the landmark initialisation needs >= 3 target landmarks, got " +
                               std::to_string (landmarks_.size ()));
    Eigen::Matrix3Xd from (3, landmarks_.size ()), to (3, landmarks_.size ());
    int k = 0;
    for (const auto& landmark : landmarks_) {
      from.col (k) = model_->meanVertex (model_->landmarkVertex (landmark.first));
      to.col (k++) = landmark.second;
    }
    return similarityFromLandmarks (from, to);
  }
  Eigen::Matrix3Xd target (3, this->target_->size ());
  for (size_t i = 0; i < this->target_->size (); ++i)
    target.col (i) = (*this->target_)[i].getVector3fMap ().template cast<double> ();
  const Eigen::Map<const Eigen::Matrix3Xd> mean (model_->mean ().data (), 3, model_->numVertices ());
  if (mode == IcpInitialisation::global) {
    Eigen::Matrix3Xd normals;
    if constexpr (pcl::traits::has_normal_v<PointTarget>) {
      normals.resize (3, this->target_->size ());
      for (size_t i = 0; i < this->target_->size (); ++i)
        normals.col (i) = (*this->target_)[i].getNormalVector3fMap ().template cast<double> ();
    }
    const GlobalAlignment found = alignHeadGlobally (TriangleMesh{mean, model_->triangles ()}, target, normals);
    report_.initialisation_detail = found.method;
    report_.initialisation_confidence = found.confidence;
    report_.head_points = static_cast<int> (found.head_indices.size ());
    return found.similarity;
  }
  // align() has built the target's k-d tree: the coarse start takes its neighbourhoods from it.
  const auto& tree = *this->tree_;
  const PointCloudTarget& cloud = *this->target_;
  const auto neighbours = [&tree, &cloud] (Eigen::Index i, int k, pcl::Indices& indices, std::vector<float>& squared) {
    tree.nearestKSearch (cloud[i], k, indices, squared);
  };
  return robustCoarseSimilarity (mean, target, neighbours);
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::prepareTarget ()
{
  const auto n = static_cast<Eigen::Index> (this->target_->size ());
  target_normals_.setZero (3, n);
  target_points_.resize (3, n);
  target_has_normal_.assign (n, false);
  target_boundary_.assign (n, false);
  target_point_ready_.assign (n, false);
  target_prepared_ = true;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::prepareTargetPoints (const pcl::Correspondences& correspondences)
{
  std::vector<Eigen::Index> pending;
  for (const pcl::Correspondence& c : correspondences)
    if (!target_point_ready_[c.index_match]) {
      target_point_ready_[c.index_match] = true;
      pending.push_back (c.index_match);
    }
  const PointCloudTarget& target = *this->target_;
  const int k = std::min<int> (boundary_neighbours_, static_cast<int> (target.size ()));
  const auto& tree = this->tree_;
  const auto count = static_cast<long> (pending.size ());
  // After the first iterations only a few points are new: not worth waking the other threads for.
#pragma omp parallel for schedule(dynamic, 64) if (count > 256)
  for (long c = 0; c < count; ++c) {
    const Eigen::Index i = pending[c];
    pcl::Indices neighbours;
    std::vector<float> distances;
    tree->nearestKSearch (target[i], k, neighbours, distances);
    Eigen::Matrix3Xd points (3, neighbours.size ());
    for (size_t j = 0; j < neighbours.size (); ++j)
      points.col (j) = target[neighbours[j]].getVector3fMap ().template cast<double> ();
    const PointPlane plane = fitPlane (points);
    const Eigen::Vector3d point = target[i].getVector3fMap ().template cast<double> ();
    target_points_.col (i) = smooth_target_ && plane.normal.allFinite ()
                                 ? Eigen::Vector3d (point - plane.normal * plane.normal.dot (point - plane.centroid))
                                 : point;
    Eigen::Vector3d normal = Eigen::Vector3d::Zero ();
    if constexpr (pcl::traits::has_normal_v<PointTarget>)
      normal = target[i].getNormalVector3fMap ().template cast<double> ();
    if (!normal.allFinite () || normal.norm () < 1e-6)
      normal = plane.normal;
    normal.normalize ();
    target_normals_.col (i) = normal;
    const bool has_normal = normal.allFinite ();
    target_boundary_[i] = !has_normal || detail::isBoundaryPoint (point, normal, points);
    target_has_normal_[i] = has_normal;
  }
}

template <typename PointTarget, typename Scalar>
typename MorphableICP<PointTarget, Scalar>::Evaluation
MorphableICP<PointTarget, Scalar>::evaluate (const State& state, RobustLoss loss)
{
  Evaluation ev;
  ev.transformed = state.transformed ();
  const Eigen::Index n = ev.transformed.cols ();
  ev.cloud.reset (new pcl::PointCloud<PointTarget>);
  ev.cloud->resize (n);
  for (Eigen::Index i = 0; i < n; ++i)
    (*ev.cloud)[i].getVector3fMap () = ev.transformed.col (i).template cast<float> ();

  auto& estimation = *this->correspondence_estimation_;
  pcl::PCLPointCloud2::Ptr source_blob;
  auto sourceBlob = [&] () {
    if (!source_blob) {
      const TriangleMesh mesh{ev.transformed, model_->triangles ()};
      const Eigen::Matrix3Xd normals = vertexNormals (mesh);
      pcl::PointCloud<pcl::PointNormal> cloud;
      cloud.resize (n);
      for (Eigen::Index i = 0; i < n; ++i) {
        cloud[i].getVector3fMap () = ev.transformed.col (i).template cast<float> ();
        cloud[i].getNormalVector3fMap () = normals.col (i).template cast<float> ();
      }
      source_blob.reset (new pcl::PCLPointCloud2);
      pcl::toPCLPointCloud2 (cloud, *source_blob);
    }
    return source_blob;
  };
  estimation.setInputSource (ev.cloud);
  if (estimation.requiresSourceNormals ())
    estimation.setSourceNormals (sourceBlob ());
  pcl::CorrespondencesPtr current (new pcl::Correspondences);
  estimation.determineCorrespondences (*current, this->corr_dist_threshold_);
  ev.found = static_cast<int> (current->size ());
  prepareTargetPoints (*current);

  if (reject_boundary_) {
    pcl::CorrespondencesPtr inside (new pcl::Correspondences);
    for (const pcl::Correspondence& c : *current)
      if (!target_boundary_[c.index_match])
        inside->push_back (c);
    current = inside;
  }
  for (const auto& rejector : this->correspondence_rejectors_) {
    if (rejector->requiresSourcePoints ())
      rejector->setSourcePoints (sourceBlob ());
    if (rejector->requiresSourceNormals ())
      rejector->setSourceNormals (sourceBlob ());
    rejector->setInputCorrespondences (current);
    pcl::CorrespondencesPtr remaining (new pcl::Correspondences);
    rejector->getCorrespondences (*remaining);
    current = remaining;
  }
  ev.kept = *current;

  const size_t kept = ev.kept.size ();
  ev.distances.resize (kept);
  double sum = 0.0;
  for (size_t c = 0; c < kept; ++c) {
    const Eigen::Vector3d q = target_points_.col (ev.kept[c].index_match);
    ev.distances[c] = (q - ev.transformed.col (ev.kept[c].index_query)).norm ();
    sum += ev.distances[c] * ev.distances[c];
  }
  ev.error = kept > 0 ? sum / static_cast<double> (kept) : std::numeric_limits<double>::infinity ();

  double width = robust_scale_;
  if (loss != RobustLoss::none && width <= 0.0) {
    const double sigma = 1.4826 * detail::medianOf (ev.distances);
    width = (loss == RobustLoss::huber ? 1.345 : 4.685) * std::max (sigma, 1e-6);
  }
  ev.weights.resize (kept);
  for (size_t c = 0; c < kept; ++c)
    ev.weights[c] = detail::robustWeight (loss, ev.distances[c], width) *
                    (area_weighting_ ? vertex_area_weights_[ev.kept[c].index_query] : 1.0);
  return ev;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::row (long c, const Evaluation& ev, const Problem& problem, int& vertex,
                                        Eigen::Vector3d& q, Eigen::Matrix3d& metric) const
{
  const auto kept = static_cast<long> (ev.kept.size ());
  if (c < kept) {
    const pcl::Correspondence& corr = ev.kept[c];
    vertex = corr.index_query;
    q = target_points_.col (corr.index_match);
    metric = Eigen::Matrix3d::Identity ();
    if (point_to_plane_ && target_has_normal_[corr.index_match]) {
      const Eigen::Vector3d normal = target_normals_.col (corr.index_match);
      const Eigen::Matrix3d nn = normal * normal.transpose ();
      metric = nn + tangential_weight_ * (Eigen::Matrix3d::Identity () - nn);
    }
    metric *= ev.weights[c];
  }
  else {
    vertex = problem.landmark_vertices[c - kept];
    q = problem.landmark_points.col (c - kept);
    metric = landmark_weight_ * Eigen::Matrix3d::Identity ();
  }
}

template <typename PointTarget, typename Scalar>
double
MorphableICP<PointTarget, Scalar>::objective (const State& state, const Evaluation& ev, const Problem& problem) const
{
  const auto rows = static_cast<long> (ev.kept.size () + problem.landmark_vertices.size ());
  const Eigen::Matrix3d sr = std::exp (state.log_scale) * state.rotation;
  double sum = 0.0;
  // Serial: a few microseconds per thousand rows, less than an OpenMP fork-join costs on a busy machine.
  for (long c = 0; c < rows; ++c) {
    int vertex;
    Eigen::Vector3d q;
    Eigen::Matrix3d metric;
    row (c, ev, problem, vertex, q, metric);
    const Eigen::Vector3d r = q - sr * state.model_vertices.col (vertex) - state.translation;
    sum += r.dot (metric * r);
  }
  if (problem.shape)
    sum += state.coefficients.dot (problem.prior * state.coefficients);
  return sum;
}

template <typename PointTarget, typename Scalar>
bool
MorphableICP<PointTarget, Scalar>::step (State& state, const Evaluation& ev, const Problem& problem,
                                         double current) const
{
  const ComponentSelection& selection = problem.selection;
  const int p = problem.shape ? selection.total () : 0;
  const int dim = 7 + p;
  const double s = std::exp (state.log_scale);
  const Eigen::Matrix3d sr = s * state.rotation;
  const auto kept = static_cast<long> (ev.kept.size ());
  const auto landmarks = static_cast<long> (problem.landmark_vertices.size ());
  int max_columns = 7;
  for (int j = 0; j < selection.numRegions (); ++j)
    max_columns += problem.shape ? selection.count (j) : 0;

  Eigen::MatrixXd hessian = Eigen::MatrixXd::Zero (dim, dim);
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero (dim);
  // The similarity stage's 7 x 7 system is too small to be worth an OpenMP fork-join.
#pragma omp parallel if (problem.shape)
  {
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero (dim, dim);
    Eigen::VectorXd g = Eigen::VectorXd::Zero (dim);
    Eigen::Matrix<double, 3, Eigen::Dynamic> jacobian (3, max_columns);
    Eigen::Matrix<double, 3, Eigen::Dynamic> weighted (3, max_columns);
    Eigen::MatrixXd block (max_columns, max_columns);
    Eigen::VectorXd rhs (max_columns);
    // Column ranges of one row's Jacobian: {first local column, first unknown, count}; the similarity first.
    std::vector<std::array<int, 3>> ranges;
#pragma omp for schedule(static) nowait
    for (long c = 0; c < kept + landmarks; ++c) {
      int vertex;
      Eigen::Vector3d q;
      Eigen::Matrix3d metric;
      row (c, ev, problem, vertex, q, metric);
      const Eigen::Vector3d rotated = sr * state.model_vertices.col (vertex);
      const Eigen::Vector3d residual = q - rotated - state.translation;
      jacobian.template leftCols<7> () = detail::similarityJacobian (rotated);
      ranges.assign (1, {0, 0, 7});
      int k = 7;
      if (problem.shape)
        for (const RegionEntry& e : model_->vertexEntries (vertex)) {
          const int count = selection.count (e.region);
          if (count == 0)
            continue;
          jacobian.middleCols (k, count).noalias () = (e.weight * sr) * model_->regionRows (e.region, e.row, count);
          ranges.push_back ({k, 7 + selection.offset (e.region), count});
          k += count;
        }
      // J^T W J and J^T W r, coefficient-wise (no GEMM dispatch for these small sizes), added block by block.
      weighted.leftCols (k).noalias () = metric * jacobian.leftCols (k);
      block.topLeftCorner (k, k).noalias () = weighted.leftCols (k).transpose ().lazyProduct (jacobian.leftCols (k));
      rhs.head (k).noalias () = weighted.leftCols (k).transpose () * residual;
      for (const auto& a : ranges) {
        g.segment (a[1], a[2]) += rhs.segment (a[0], a[2]);
        for (const auto& b : ranges)
          h.block (a[1], b[1], a[2], b[2]) += block.block (a[0], b[0], a[2], b[2]);
      }
    }
#pragma omp critical
    {
      hessian += h;
      gradient += g;
    }
  }
  if (problem.shape) {
    hessian.bottomRightCorner (p, p) += problem.prior;
    gradient.tail (p) -= problem.prior * state.coefficients;
  }
  if (!estimate_scale_) {
    hessian.row (0).setZero ();
    hessian.col (0).setZero ();
    hessian (0, 0) = 1.0;
    gradient[0] = 0.0;
  }
  hessian.diagonal ().array () += 1e-12 * std::max (1.0, hessian.diagonal ().maxCoeff ());
  const Eigen::LDLT<Eigen::MatrixXd> solver (hessian);
  Eigen::VectorXd delta = solver.solve (gradient);
  if (solver.info () != Eigen::Success || !delta.allFinite ())
    return false;
  // Trust region: no coefficient moves more than kMaxShapeStep prior standard deviations in one update, so a step
  // taken on the first, still sliding correspondences cannot throw the shape far outside the prior.
  if (problem.shape)
    detail::limitShapeStep (delta, problem.sigma);

  // Backtracking: halve the step until the objective (with these correspondences) decreases below \a current.
  for (double alpha = 1.0; alpha > 1e-2; alpha *= 0.5) {
    State candidate = state;
    const Eigen::VectorXd d = alpha * delta;
    detail::updateSimilarity (d.head<7> (), candidate.log_scale, candidate.rotation, candidate.translation);
    if (problem.shape) {
      candidate.coefficients += d.tail (p);
      candidate.model_vertices = model_->generate (candidate.coefficients, selection);
    }
    if (objective (candidate, ev, problem) <= current) {
      state = std::move (candidate);
      break;
    }
  }
  return true;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::dampReversal (State& state, const Eigen::VectorXd& before, const Problem& problem,
                                                 Eigen::VectorXd& previous_change) const
{
  Eigen::VectorXd change = (state.coefficients - before).cwiseQuotient (problem.sigma);
  if (previous_change.size () == change.size () && change.dot (previous_change) < 0.0) {
    change *= 0.5;
    state.coefficients = before + change.cwiseProduct (problem.sigma);
    state.model_vertices = model_->generate (state.coefficients, state.selection);
  }
  previous_change = change;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::computeTransformation (PointCloudSource& output, const Matrix4& guess)
{
  validateInputs ();
  if (!target_prepared_)
    prepareTarget ();
  report_ = IcpReport ();
  auto& estimation = *this->correspondence_estimation_;
  estimation.setInputTarget (this->target_);
  estimation.setSearchMethodTarget (this->tree_, true);
  if (estimation.requiresTargetNormals ())
    throw InvalidInputError ("MorphableICP: correspondence estimations that need target normals are not supported");
  pcl::PCLPointCloud2::Ptr target_blob;
  for (const auto& rejector : this->correspondence_rejectors_) {
    if (rejector->requiresTargetNormals () && !pcl::traits::has_normal_v<PointTarget>)
      throw InvalidInputError ("MorphableICP: rejector " + rejector->getClassName () +
                               " needs target normals, but the target point type has none");
    if (!target_blob && (rejector->requiresTargetPoints () || rejector->requiresTargetNormals ())) {
      target_blob.reset (new pcl::PCLPointCloud2);
      pcl::toPCLPointCloud2 (*this->target_, *target_blob);
    }
    if (rejector->requiresTargetPoints ())
      rejector->setTargetPoints (target_blob);
    if (rejector->requiresTargetNormals ())
      rejector->setTargetNormals (target_blob);
  }

  // Starting state from the initial similarity.
  const Eigen::Matrix4d initial = initialTransformation (guess);
  const Eigen::Matrix3d a = initial.topLeftCorner<3, 3> ();
  if (!initial.allFinite () || a.determinant () <= 0.0)
    throw InvalidInputError ("MorphableICP: the initial guess is not a proper similarity");
  report_.initial_transformation = initial;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd (a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  State state;
  state.log_scale = estimate_scale_ ? std::log (std::cbrt (a.determinant ())) : 0.0;
  state.rotation = svd.matrixU () * svd.matrixV ().transpose ();
  state.translation = initial.topRightCorner<3, 1> ();
  const bool with_shape = shape_stage_ && selection_.total () > 0;
  const std::vector<ShapePhase> phases = with_shape ? effectiveShapeSchedule () : std::vector<ShapePhase> ();
  state.selection = phases.empty () ? selection_ : phases.front ().components;
  state.coefficients = Eigen::VectorXd::Zero (state.selection.total ());
  state.model_vertices = model_->generate (state.coefficients, state.selection);

  Problem problem;
  for (const auto& landmark : landmarks_)
    problem.landmark_vertices.push_back (model_->landmarkVertex (landmark.first));
  problem.landmark_points.resize (3, landmarks_.size ());
  int column = 0;
  for (const auto& landmark : landmarks_)
    problem.landmark_points.col (column++) = landmark.second;
  const double motion_epsilon = this->transformation_epsilon_ > 0.0 ? this->transformation_epsilon_ : 1e-4;
  const double fitness_epsilon = this->euclidean_fitness_epsilon_;
  State best = state;
  double best_cost = std::numeric_limits<double>::infinity ();
  this->nr_iterations_ = 0;
  bool diverged = false;

  // The similarity stage, then each shape phase to convergence; a phase's budget is its share of what is left.
  const int runs = 1 + static_cast<int> (phases.size ());
  for (int run = 0; run < runs; ++run) {
    problem.shape = run > 0;
    const RobustLoss loss = graduated_loss_ && robust_loss_ == RobustLoss::tukey && run + 1 < runs
                                ? RobustLoss::huber
                                : robust_loss_;
    const IcpStage stage = problem.shape ? IcpStage::shape : IcpStage::similarity;
    if (problem.shape) {
      const ShapePhase& phase = phases[run - 1];
      state.coefficients = detail::restack (state.coefficients, state.selection, phase.components);
      state.selection = phase.components;
      state.model_vertices = model_->generate (state.coefficients, state.selection);
      problem.selection = phase.components;
      problem.prior = detail::shapePriorMatrix (*model_, phase.components, phase.smoothness_weight, lambda2_, prior_);
      problem.sigma = model_->variances (phase.components).cwiseSqrt ();
    }
    const int remaining = this->max_iterations_ - this->nr_iterations_;
    if (remaining <= 0)
      break;
    const int budget = !problem.shape ? (with_shape ? std::min (similarity_iterations_,
                                                                std::max (1, this->max_iterations_ / 2))
                                                    : remaining)
                                      : std::max (1, remaining / (runs - run));
    const int p = problem.shape ? problem.selection.total () : 0;
    const int unknowns = (estimate_scale_ ? 7 : 6) + p;
    double previous_error = std::numeric_limits<double>::infinity ();
    Eigen::VectorXd previous_change; // the last update of the coefficients, in prior standard deviations
    int rising = 0;
    best = state;
    best_cost = std::numeric_limits<double>::infinity ();
    report_.termination = IcpTermination::max_iterations;
    for (int it = 0; it < budget; ++it) {
      const auto start = std::chrono::steady_clock::now ();
      const Evaluation ev = evaluate (state, loss);
      const int rows = static_cast<int> (ev.kept.size () + problem.landmark_vertices.size ());
      if (rows < unknowns)
        throw TooFewCorrespondencesError ("MorphableICP: " + std::to_string (ev.kept.size ()) + " correspondences (of " +
                                 std::to_string (ev.found) + " found) and " +
                                 std::to_string (problem.landmark_vertices.size ()) + " landmarks for " +
                                 std::to_string (unknowns) + " unknowns; check the max correspondence distance, "
                                 "the rejectors and the initial alignment");
      if (this->update_visualizer_) {
        pcl::Indices source_indices, target_indices;
        for (const pcl::Correspondence& c : ev.kept) {
          source_indices.push_back (c.index_query);
          target_indices.push_back (c.index_match);
        }
        this->update_visualizer_ (*ev.cloud, source_indices, *this->target_, target_indices);
      }
      const double total_cost = objective (state, ev, problem);
      const double cost = total_cost / rows;
      if (cost < best_cost) {
        best = state;
        best_cost = cost;
        rising = 0;
      }
      else if (problem.shape && cost > 1.05 * best_cost && ++rising >= rising_iterations_) {
        diverged = true;
        report_.divergence = IcpDivergence::cost_rose;
        report_.message = "the cost rose " + std::to_string (rising) + " times in a row above the best";
      }
      if (diverged)
        break;
      const Eigen::Matrix3Xd before = ev.transformed;
      const Eigen::VectorXd before_coefficients = state.coefficients;
      if (!step (state, ev, problem, total_cost)) {
        diverged = true;
        report_.divergence = IcpDivergence::unsolvable;
        report_.message = "the normal equations could not be solved";
        break;
      }
      if (problem.shape && p > 0)
        dampReversal (state, before_coefficients, problem, previous_change);
      const double motion = (state.transformed () - before).colwise ().squaredNorm ().mean ();
      const double seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
      report_.history.push_back ({stage, ev.error, ev.found, static_cast<int> (ev.kept.size ()), seconds});
      ++this->nr_iterations_;
      (problem.shape ? report_.shape_iterations : report_.similarity_iterations) += 1;
      if (problem.shape && max_sigma_ > 0.0 && p > 0 &&
          (state.coefficients.cwiseAbs ().array () > max_sigma_ * problem.sigma.array () + 1e-9).any ()) {
        diverged = true;
        report_.divergence = IcpDivergence::prior_exceeded;
        report_.message = "a shape coefficient left the prior (more than " + std::to_string (max_sigma_) +
                          " standard deviations)";
        break;
      }
      if (motion < motion_epsilon) {
        report_.termination = IcpTermination::transformation_converged;
        break;
      }
      if (fitness_epsilon > 0.0 && std::abs (previous_error - cost) < fitness_epsilon) {
        report_.termination = IcpTermination::fitness_converged;
        break;
      }
      previous_error = cost;
    }
    if (diverged)
      break;
  }
  if (diverged)
    report_.termination = IcpTermination::diverged;

  Evaluation final_ev = evaluate (state, robust_loss_);
  const double final_rows = static_cast<double> (final_ev.kept.size () + problem.landmark_vertices.size ());
  if (objective (state, final_ev, problem) / final_rows > best_cost) {
    state = best;
    final_ev = evaluate (state, robust_loss_);
  }
  finish (state, output);
  vertex_residuals_ = Eigen::VectorXd::Constant (model_->numVertices (), std::numeric_limits<double>::quiet_NaN ());
  for (size_t c = 0; c < final_ev.kept.size (); ++c)
    vertex_residuals_[final_ev.kept[c].index_query] = final_ev.distances[c];
  report_.correspondences = static_cast<int> (final_ev.kept.size ());
  if (!final_ev.distances.empty ()) {
    const Eigen::Map<const Eigen::VectorXd> d (final_ev.distances.data (), final_ev.distances.size ());
    report_.fitness_mean = d.mean ();
    report_.fitness_rms = std::sqrt (d.squaredNorm () / static_cast<double> (d.size ()));
    report_.fitness_median = detail::medianOf (final_ev.distances);
  }
  this->converged_ = !diverged;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::finish (const State& state, PointCloudSource& output)
{
  coefficients_ = detail::restack (state.coefficients, state.selection, selection_);
  fitted_vertices_ = state.transformed ();
  const Eigen::Matrix3Xd normals = vertexNormals (TriangleMesh{fitted_vertices_, model_->triangles ()});
  output.resize (fitted_vertices_.cols ());
  for (Eigen::Index i = 0; i < fitted_vertices_.cols (); ++i) {
    output[i].getVector3fMap () = fitted_vertices_.col (i).template cast<float> ();
    if constexpr (pcl::traits::has_normal_v<PointTarget>)
      output[i].getNormalVector3fMap () = normals.col (i).template cast<float> ();
  }
  this->final_transformation_ = state.similarity ().template cast<Scalar> ();
  this->transformation_ = this->final_transformation_;
}

template <typename PointTarget, typename Scalar>
pcl::PolygonMesh
MorphableICP<PointTarget, Scalar>::getFittedMesh () const
{
  if (!model_ || fitted_vertices_.cols () != model_->numVertices ())
    throw InvalidInputError ("MorphableICP::getFittedMesh: align() has not run");
  return toPolygonMesh (TriangleMesh{fitted_vertices_, model_->triangles ()});
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <morphreg/common/cloud_matrix.h>
#include <morphreg/common/error.h>
#include <morphreg/common/order_statistics.h>
#include <morphreg/common/cloud_checks.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/model/coefficient_units.h>
#include <morphreg/registration/cached_correspondence_estimation.h>
#include <morphreg/registration/global_alignment.h>
#include <morphreg/registration/initial_alignment.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/common/length_unit.h>
#include <morphreg/model/model_radius.h>

#include <pcl/common/transforms.h>
#include <pcl/conversions.h>
#include <pcl/point_representation.h>
#include <pcl/registration/correspondence_estimation.h>

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace morphreg
{
/** Accepted correspondences of one iteration, with their IRLS weights and the mean squared distance. */
template <typename PointTarget, typename Scalar>
struct MorphableICP<PointTarget, Scalar>::Evaluation
{
  Eigen::Matrix3Xd transformed;
  typename pcl::PointCloud<PointTarget>::Ptr cloud;
  pcl::PCLPointCloud2::Ptr source_blob; ///< the posed model with normals, built on first use
  pcl::Correspondences kept;
  std::vector<double> distances;
  std::vector<double> weights;
  int found = 0;
  double error = 0.0;
};

namespace detail
{
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
} // namespace detail

template <typename PointTarget, typename Scalar>
MorphableICP<PointTarget, Scalar>::MorphableICP ()
{
  this->reg_name_ = "MorphableICP";
  this->max_iterations_ = MorphableIcpDefaults::iterations;
  this->correspondence_estimation_.reset (
      new CachedCorrespondenceEstimation<PointTarget, PointTarget, typename Base::Matrix4::Scalar>);
  own_source_tree_ = this->tree_reciprocal_;
  this->input_.reset (new PointCloudSource);
  typename PointCloudTarget::Ptr placeholder (new PointCloudTarget);
  placeholder->push_back (PointTarget ()); // one point: PCL's k-d tree refuses an empty cloud with a message
  no_target_ = placeholder;
  this->target_ = no_target_;
  target_surface_ = std::make_shared<TargetSurface> ();
  boundary_rejector_ = std::make_shared<CorrespondenceRejectorTargetBoundary> (target_surface_);
  normal_rejector_ = std::make_shared<CorrespondenceRejectorNormalCompatibility> (target_surface_);
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
  selection_ = model_->firstComponents (MorphableIcpDefaults::components_per_region);
  const TriangleMesh mean{Eigen::Map<const Eigen::Matrix3Xd> (model_->mean ().data (), 3, model_->numVertices ()),
                          model_->triangles ()};
  const Eigen::VectorXd areas = triangleAreas (mean);
  vertex_area_weights_ = Eigen::VectorXd::Zero (model_->numVertices ());
  for (Eigen::Index t = 0; t < mean.triangles.cols (); ++t)
    for (int corner = 0; corner < 3; ++corner)
      vertex_area_weights_[mean.triangles (corner, t)] += areas[t] / 3.0;
  vertex_area_weights_ /= std::max (vertex_area_weights_.mean (), std::numeric_limits<double>::min ());
  Base::setInputSource (model_->generateCloud<PointTarget> (Eigen::VectorXd::Zero (selection_.total ()), selection_));
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
  lambda1_ = requirePriorWeight (lambda1, "MorphableICP::setSmoothnessWeight: lambda_1");
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setRefinementSmoothnessWeight (double lambda1)
{
  refinement_lambda1_ = requirePriorWeight (lambda1, "MorphableICP::setRefinementSmoothnessWeight: lambda_1");
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setShapeSchedule (std::vector<ShapePhase> phases)
{
  for (size_t k = 0; k < phases.size (); ++k) {
    const std::string phase = " of phase " + std::to_string (k);
    requirePriorWeight (phases[k].smoothness_weight, "MorphableICP::setShapeSchedule: lambda_1" + phase);
    if (phases[k].prior_weight)
      requirePriorWeight (*phases[k].prior_weight, "MorphableICP::setShapeSchedule: lambda_2" + phase);
  }
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
  lambda2_ = requirePriorWeight (lambda2, "MorphableICP::setShapePriorWeight: lambda_2");
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
MorphableICP<PointTarget, Scalar>::setRobustKernel (const RobustKernel::ConstPtr& kernel)
{
  if (!kernel)
    throw InvalidInputError ("MorphableICP::setRobustKernel: no kernel (a null pointer); plain least squares is "
                             "makeRobustKernel (\"none\")");
  if (!std::isfinite (kernel->getScale ()))
    throw InvalidInputError ("MorphableICP::setRobustKernel: the kernel width must be finite");
  robust_kernel_ = kernel;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setRejectTargetBoundary (bool enabled, int neighbours)
{
  target_surface_->setNeighbours (neighbours);
  reject_boundary_ = enabled;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setRejectIncompatibleNormals (bool enabled, double max_angle_deg)
{
  normal_rejector_->setMaximumAngle (max_angle_deg);
  reject_incompatible_normals_ = enabled;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setTargetSmoothing (TargetSmoothing smoothing)
{
  target_surface_->setSmoothing (smoothing);
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
  requirePriorWeight (weight, "MorphableICP::setTargetLandmarks: the landmark weight");
  for (const auto& landmark : landmarks) {
    if (!landmark.second.allFinite ())
      throw InvalidInputError ("MorphableICP::setTargetLandmarks: landmark '" + landmark.first + "' is not finite");
    if (model_)
      model_->landmarkVertex (landmark.first);
  }
  landmarks_ = landmarks;
  landmark_weight_ = weight;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setInputSource (const PointCloudSourceConstPtr&)
{
  throw InvalidInputError ("MorphableICP::setInputSource: the source is the model; set it with setModel (a "
                           "MorphableModel), and the scan with setInputTarget");
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setInputTarget (const PointCloudTargetConstPtr& cloud)
{
  if (!cloud || cloud->empty ())
    throw InvalidInputError (std::string ("MorphableICP::setInputTarget: the target cloud is ") +
                             (cloud ? "empty" : "null"));
  Base::setInputTarget (cloud);
  target_prepared_ = false;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::validateInputs () const
{
  if (!model_)
    throw InvalidInputError ("MorphableICP: no model (call setModel)");
  if (this->target_ == no_target_)
    throw InvalidInputError ("MorphableICP: no target cloud (call setInputTarget)");
  requireFiniteNonEmpty (*this->target_, "MorphableICP target");
  requireNoUnusedSettings ();
  requireMillimetreTarget ();
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
MorphableICP<PointTarget, Scalar>::requireNoUnusedSettings () const
{
  // pcl::Registration's setters are not virtual: what they set is checked here, on every path to align().
  const auto refuse = [] (const std::string& setter, const std::string& why) {
    throw InvalidInputError ("MorphableICP: " + setter + " was called, but MorphableICP does not use it: " + why);
  };
  if (this->transformation_estimation_)
    refuse ("setTransformationEstimation", "pose and shape come from one Gauss-Newton step (PoseShapeLeastSquares); "
                                           "setPointToPlane chooses point-to-plane or point-to-point rows");
  if (this->ransac_iterations_ != 0)
    refuse ("setRANSACIterations", "it has no RANSAC stage; the rejector chain and the robust loss handle outliers");
  if (this->inlier_threshold_ != 0.05) // pcl::Registration's default
    refuse ("setRANSACOutlierRejectionThreshold", "it has no RANSAC stage; see setRobustKernel");
  if (this->transformation_rotation_epsilon_ != 0.0)
    refuse ("setTransformationRotationEpsilon",
            "convergence is measured by the vertices' motion (setTransformationEpsilon, mm^2)");
  if (this->tree_reciprocal_ != own_source_tree_)
    refuse ("setSearchMethodSource", "the source moves with the shape every iteration; no source tree is searched");
  if (!this->fake_indices_)
    refuse ("setIndices", "every model vertex takes part in the fit");
  // pcl::Registration::align hands a point representation to the target's k-d tree; the fit's distances are in x, y, z.
  const auto representation = this->tree_->getPointRepresentation ();
  if (representation && !dynamic_cast<const pcl::DefaultPointRepresentation<PointTarget>*> (representation.get ()))
    refuse ("setPointRepresentation", "its correspondences, rejectors and residuals measure distances in x, y, z");
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::requireMillimetreTarget () const
{
  const bool one_view = this->target_->isOrganized () || viewpoint_.has_value ();
  const LengthUnitGuess unit = guessLengthUnit (pointsOf (*this->target_), modelRadius (*model_), one_view);
  if (unit.recognised && unit.unit != LengthUnit::millimetre)
    throw InvalidInputError ("MorphableICP: the target seems to be in " + toString (unit.unit) + ", not mm (" +
                             unit.reason +
                             "); MorphableICP fits in mm: convert the scan to mm first, e.g. with "
                             "morphreg::convertScanToMillimetres (pipeline/scan_units.h)");
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::setInitialAlignment (InitialAlignmentStrategy::ConstPtr start)
{
  if (!start)
    throw InvalidInputError ("MorphableICP::setInitialAlignment: no start (a null pointer); the default is "
                             "makeInitialAlignment (\"auto\")");
  initial_alignment_ = std::move (start);
}

template <typename PointTarget, typename Scalar>
Eigen::Matrix4d
MorphableICP<PointTarget, Scalar>::initialTransformation (const Matrix4& guess)
{
  StartInputs inputs;
  inputs.guess = guess.template cast<double> ();
  inputs.model_mean = {Eigen::Map<const Eigen::Matrix3Xd> (model_->mean ().data (), 3, model_->numVertices ()),
                       model_->triangles ()};
  inputs.model_landmarks.resize (3, static_cast<Eigen::Index> (landmarks_.size ()));
  inputs.target_landmarks.resize (3, static_cast<Eigen::Index> (landmarks_.size ()));
  Eigen::Index k = 0;
  for (const auto& [name, position] : landmarks_) {
    inputs.model_landmarks.col (k) = model_->meanVertex (model_->landmarkVertex (name));
    inputs.target_landmarks.col (k++) = position;
  }
  inputs.target = pointsOf (*this->target_);
  inputs.target_normals = normalsIfAny (*this->target_);
  inputs.viewpoint = target_viewpoint_;
  // align() has built the target's k-d tree: starts take their neighbourhoods from it.
  const auto& tree = *this->tree_;
  const PointCloudTarget& cloud = *this->target_;
  inputs.target_neighbours = [&tree, &cloud] (Eigen::Index i, int n, pcl::Indices& indices,
                                              std::vector<float>& squared) {
    tree.nearestKSearch (cloud[i], n, indices, squared);
  };
  const StartEstimate start = initial_alignment_->estimate (inputs);
  report_.initialisation = start.method;
  report_.initialisation_detail = start.detail;
  report_.initialisation_confidence = start.confidence;
  report_.head_points = start.head_points;
  return start.similarity;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::prepareEstimators ()
{
  auto& estimation = *this->correspondence_estimation_;
  estimation.setInputTarget (this->target_);
  estimation.setSearchMethodTarget (this->tree_, true);
  if (estimation.requiresTargetNormals ())
    throw InvalidInputError ("MorphableICP: correspondence estimations that need target normals are not supported");
  if (!target_prepared_) {
    const auto tree = this->tree_;
    const PointCloudTargetConstPtr cloud = this->target_;
    target_surface_->setInputTarget (
        pointsOf (*cloud), normalsIfAny (*cloud),
        [tree, cloud] (pcl::index_t i, int k, pcl::Indices& indices, std::vector<float>& squared) {
          tree->nearestKSearch ((*cloud)[i], k, indices, squared);
        });
    // An organised cloud is one sensor's view: its estimated normals face that sensor.
    const bool one_view = cloud->isOrganized () && !viewpoint_;
    target_viewpoint_ =
        one_view ? std::optional<Eigen::Vector3d> (cloud->sensor_origin_.template head<3> ().template cast<double> ())
                 : viewpoint_;
    target_surface_->setViewpoint (target_viewpoint_);
    target_prepared_ = true;
  }
  chain_ = this->correspondence_rejectors_;
  if (chain_.empty () && reject_boundary_)
    chain_.push_back (boundary_rejector_);
  if (this->correspondence_rejectors_.empty () && reject_incompatible_normals_)
    chain_.push_back (normal_rejector_);
  pcl::PCLPointCloud2::Ptr target_blob;
  for (const auto& rejector : chain_) {
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
  landmark_rows_.clear ();
  for (const auto& landmark : landmarks_)
    landmark_rows_.push_back (
        {model_->landmarkVertex (landmark.first), landmark.second, landmark_weight_ * Eigen::Matrix3d::Identity ()});
}

template <typename PointTarget, typename Scalar>
PoseShapeState
MorphableICP<PointTarget, Scalar>::initialState (const Matrix4& guess)
{
  const Eigen::Matrix4d initial = initialTransformation (guess);
  const Eigen::Matrix3d a = initial.topLeftCorner<3, 3> ();
  if (!initial.allFinite () || a.determinant () <= 0.0)
    throw InvalidInputError ("MorphableICP: the initial guess is not a proper similarity");
  report_.initial_transformation = initial;
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd (a, Eigen::ComputeFullU | Eigen::ComputeFullV);
  PoseShapeState state;
  state.log_scale = estimate_scale_ ? std::log (std::cbrt (a.determinant ())) : 0.0;
  state.rotation = svd.matrixU () * svd.matrixV ().transpose ();
  state.translation = initial.topRightCorner<3, 1> ();
  const std::vector<ShapePhase> schedule = effectiveShapeSchedule ();
  state.selection = shape_stage_ && selection_.total () > 0 ? schedule.front ().components : selection_;
  state.coefficients = Eigen::VectorXd::Zero (state.selection.total ());
  state.vertices = model_->generate (state.coefficients, state.selection);
  return state;
}

template <typename PointTarget, typename Scalar>
std::vector<typename MorphableICP<PointTarget, Scalar>::Phase>
MorphableICP<PointTarget, Scalar>::phases () const
{
  std::vector<Phase> phases (1);
  if (shape_stage_ && selection_.total () > 0)
    for (const ShapePhase& shape : effectiveShapeSchedule ())
      phases.push_back ({true, shape, robust_kernel_});
  // Graduated: the kernel's start (Huber for a redescending one) until the last phase (see setGraduatedRobustLoss).
  const RobustKernel::ConstPtr start = graduated_loss_ ? robust_kernel_->graduatedStart () : nullptr;
  for (size_t k = 0; k < phases.size (); ++k)
    phases[k].kernel = start && k + 1 < phases.size () ? start : robust_kernel_;
  return phases;
}

template <typename PointTarget, typename Scalar>
PoseShapeLeastSquares
MorphableICP<PointTarget, Scalar>::solver (const Phase& phase) const
{
  PoseShapeSettings settings;
  if (phase.shape)
    settings.components = phase.settings.components;
  settings.smoothness_weight = phase.settings.smoothness_weight;
  settings.prior_weight = phase.settings.prior_weight.value_or (lambda2_);
  settings.prior = prior_;
  settings.estimate_scale = estimate_scale_;
  settings.damp_reversals = true;
  return PoseShapeLeastSquares (*model_, {}, settings);
}

template <typename PointTarget, typename Scalar>
bool
MorphableICP<PointTarget, Scalar>::startPhase (const Phase& phase, const PoseShapeLeastSquares& solver, int phases_left,
                                               PoseShapeState& state, MorphableConvergence& convergence)
{
  if (phase.shape) {
    const ComponentSelection& components = phase.settings.components;
    state.coefficients = detail::restack (state.coefficients, state.selection, components);
    state.selection = components;
    state.vertices = model_->generate (state.coefficients, state.selection);
    state.last_step.resize (0);
  }
  const int remaining = convergence.remaining ();
  if (remaining <= 0)
    return false;
  // The similarity stage gets at most half the iterations when shape phases follow; a shape phase its share of
  // what is left.
  const int budget = phase.shape       ? std::max (1, remaining / phases_left)
                     : phases_left > 1 ? std::min (similarity_iterations_, std::max (1, this->max_iterations_ / 2))
                                       : remaining;
  convergence.startPhase (budget, phase.shape, solver.sigma ());
  return true;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::runPhase (const Phase& phase, const PoseShapeLeastSquares& solver,
                                             PoseShapeState& state, PoseShapeState& best,
                                             MorphableConvergence& convergence)
{
  const size_t unknowns = (estimate_scale_ ? 7 : 6) + static_cast<size_t> (solver.sigma ().size ());
  best = state;
  while (!convergence.hasConverged ()) {
    const auto start = std::chrono::steady_clock::now ();
    Evaluation ev = evaluate (state, *phase.kernel);
    const std::vector<PoseShapeRow> rows = this->rows (ev);
    requireEnoughRows (rows.size (), unknowns, "MorphableICP",
                       std::to_string (ev.kept.size ()) + " correspondences (of " + std::to_string (ev.found) +
                           " found) and " + std::to_string (landmark_rows_.size ()) + " landmarks",
                       "the max correspondence distance, the rejectors and the initial alignment");
    visualize (ev);
    if (!convergence.checkCost (solver.cost (state, rows) / static_cast<double> (rows.size ())))
      break;
    if (convergence.improved ())
      best = state;
    const bool solved = solver.step (state, rows);
    const double motion = (state.posed () - ev.transformed).colwise ().squaredNorm ().mean ();
    convergence.update (solved, motion, phase.shape ? state.coefficients : Eigen::VectorXd ());
    if (!solved)
      break;
    const double seconds = std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
    const IcpStage stage = phase.shape ? IcpStage::shape : IcpStage::similarity;
    report_.history.push_back ({stage, ev.error, ev.found, static_cast<int> (ev.kept.size ()), seconds});
    (phase.shape ? report_.shape_iterations : report_.similarity_iterations) += 1;
  }
}

template <typename PointTarget, typename Scalar>
typename MorphableICP<PointTarget, Scalar>::Evaluation
MorphableICP<PointTarget, Scalar>::evaluate (const PoseShapeState& state, const RobustKernel& kernel)
{
  Evaluation ev;
  ev.transformed = state.posed ();
  ev.cloud.reset (new pcl::PointCloud<PointTarget>);
  ev.cloud->resize (ev.transformed.cols ());
  for (Eigen::Index i = 0; i < ev.transformed.cols (); ++i)
    (*ev.cloud)[i].getVector3fMap () = ev.transformed.col (i).template cast<float> ();
  pcl::CorrespondencesPtr correspondences = findCorrespondences (ev);
  ev.kept = *reject (correspondences, ev);
  weigh (ev, kernel);
  return ev;
}

template <typename PointTarget, typename Scalar>
pcl::CorrespondencesPtr
MorphableICP<PointTarget, Scalar>::findCorrespondences (Evaluation& ev)
{
  auto& estimation = *this->correspondence_estimation_;
  estimation.setInputSource (ev.cloud);
  if (estimation.requiresSourceNormals ())
    estimation.setSourceNormals (sourceBlob (ev));
  pcl::CorrespondencesPtr found (new pcl::Correspondences);
  estimation.determineCorrespondences (*found, this->corr_dist_threshold_);
  ev.found = static_cast<int> (found->size ());
  target_surface_->compute (*found, ev.transformed);
  return found;
}

template <typename PointTarget, typename Scalar>
pcl::CorrespondencesPtr
MorphableICP<PointTarget, Scalar>::reject (pcl::CorrespondencesPtr correspondences, Evaluation& ev)
{
  for (const auto& rejector : chain_) {
    if (rejector->requiresSourcePoints ())
      rejector->setSourcePoints (sourceBlob (ev));
    if (rejector->requiresSourceNormals ())
      rejector->setSourceNormals (sourceBlob (ev));
    rejector->setInputCorrespondences (correspondences);
    pcl::CorrespondencesPtr remaining (new pcl::Correspondences);
    rejector->getCorrespondences (*remaining);
    correspondences = remaining;
  }
  return correspondences;
}

template <typename PointTarget, typename Scalar>
pcl::PCLPointCloud2::Ptr
MorphableICP<PointTarget, Scalar>::sourceBlob (Evaluation& ev) const
{
  if (!ev.source_blob) {
    const Eigen::Matrix3Xd normals = vertexNormals (TriangleMesh{ev.transformed, model_->triangles ()});
    pcl::PointCloud<pcl::PointNormal> cloud;
    cloud.resize (ev.transformed.cols ());
    for (Eigen::Index i = 0; i < ev.transformed.cols (); ++i) {
      cloud[i].getVector3fMap () = ev.transformed.col (i).template cast<float> ();
      cloud[i].getNormalVector3fMap () = normals.col (i).template cast<float> ();
    }
    ev.source_blob.reset (new pcl::PCLPointCloud2);
    pcl::toPCLPointCloud2 (cloud, *ev.source_blob);
  }
  return ev.source_blob;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::weigh (Evaluation& ev, const RobustKernel& kernel) const
{
  const size_t kept = ev.kept.size ();
  ev.distances.resize (kept);
  double sum = 0.0;
  for (size_t c = 0; c < kept; ++c) {
    const pcl::Correspondence& corr = ev.kept[c];
    ev.distances[c] = (target_surface_->point (corr.index_match) - ev.transformed.col (corr.index_query)).norm ();
    sum += ev.distances[c] * ev.distances[c];
  }
  ev.error = kept > 0 ? sum / static_cast<double> (kept) : std::numeric_limits<double>::infinity ();
  const double width = kernel.width (ev.distances);
  ev.weights.resize (kept);
  for (size_t c = 0; c < kept; ++c)
    ev.weights[c] =
        kernel.weight (ev.distances[c], width) * (area_weighting_ ? vertex_area_weights_[ev.kept[c].index_query] : 1.0);
}

template <typename PointTarget, typename Scalar>
std::vector<PoseShapeRow>
MorphableICP<PointTarget, Scalar>::rows (const Evaluation& ev) const
{
  std::vector<PoseShapeRow> rows;
  rows.reserve (ev.kept.size () + landmark_rows_.size ());
  for (size_t c = 0; c < ev.kept.size (); ++c) {
    const pcl::Correspondence& corr = ev.kept[c];
    Eigen::Matrix3d metric = Eigen::Matrix3d::Identity ();
    if (point_to_plane_ && target_surface_->hasNormal (corr.index_match)) {
      const Eigen::Vector3d normal = target_surface_->normal (corr.index_match);
      const Eigen::Matrix3d nn = normal * normal.transpose ();
      metric = nn + tangential_weight_ * (Eigen::Matrix3d::Identity () - nn);
    }
    rows.push_back ({corr.index_query, target_surface_->point (corr.index_match), ev.weights[c] * metric});
  }
  rows.insert (rows.end (), landmark_rows_.begin (), landmark_rows_.end ());
  return rows;
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::visualize (const Evaluation& ev) const
{
  if (!this->update_visualizer_)
    return;
  pcl::Indices source_indices, target_indices;
  for (const pcl::Correspondence& c : ev.kept) {
    source_indices.push_back (c.index_query);
    target_indices.push_back (c.index_match);
  }
  this->update_visualizer_ (*ev.cloud, source_indices, *this->target_, target_indices);
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::computeTransformation (PointCloudSource& output, const Matrix4& guess)
{
  validateInputs ();
  report_ = IcpReport ();
  prepareEstimators ();
  PoseShapeState state = initialState (guess);
  const double motion_epsilon = this->transformation_epsilon_ > 0.0 ? this->transformation_epsilon_ : 1e-4;
  MorphableConvergence convergence (this->max_iterations_, motion_epsilon, this->euclidean_fitness_epsilon_, max_sigma_,
                                    rising_iterations_);
  const std::vector<Phase> phases = this->phases ();
  PoseShapeLeastSquares solver = this->solver (phases.front ());
  PoseShapeState best = state;
  for (size_t k = 0; k < phases.size () && !convergence.hasDiverged (); ++k) {
    if (k > 0)
      solver = this->solver (phases[k]);
    if (!startPhase (phases[k], solver, static_cast<int> (phases.size () - k), state, convergence))
      break;
    runPhase (phases[k], solver, state, best, convergence);
  }
  this->nr_iterations_ = convergence.iterations ();
  finish (state, best, solver, convergence, output);
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::finish (PoseShapeState state, const PoseShapeState& best,
                                           const PoseShapeLeastSquares& solver, const MorphableConvergence& convergence,
                                           PointCloudSource& output)
{
  report_.termination = convergence.termination ();
  report_.divergence = convergence.divergence ();
  report_.message = convergence.message ();
  Evaluation final_ev = evaluate (state, *robust_kernel_);
  const std::vector<PoseShapeRow> final_rows = rows (final_ev);
  if (solver.cost (state, final_rows) / static_cast<double> (final_rows.size ()) > convergence.bestCost ()) {
    state = best;
    final_ev = evaluate (state, *robust_kernel_);
  }
  store (state, output);
  vertex_residuals_ = Eigen::VectorXd::Constant (model_->numVertices (), std::numeric_limits<double>::quiet_NaN ());
  for (size_t c = 0; c < final_ev.kept.size (); ++c)
    vertex_residuals_[final_ev.kept[c].index_query] = final_ev.distances[c];
  report_.target_smoothing = target_surface_->getSmoothing ();
  report_.target_noise_ratio = target_surface_->getNoiseRatio ();
  storeFitness (final_ev, state);
  this->converged_ = !convergence.hasDiverged ();
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::storeFitness (const Evaluation& ev, const PoseShapeState& state)
{
  // The source becomes the fitted shape's vertices with a correspondence (model frame), and the distances are
  // measured as pcl::Registration::getFitnessScore measures them: through the final transformation, in the same
  // float arithmetic, to the nearest point of the target's k-d tree.
  typename PointCloudSource::Ptr source (new PointCloudSource);
  source->resize (ev.kept.size ());
  for (size_t c = 0; c < ev.kept.size (); ++c)
    (*source)[c].getVector3fMap () = state.vertices.col (ev.kept[c].index_query).template cast<float> ();
  PointCloudSource posed;
  pcl::transformPointCloud (*source, posed, this->final_transformation_);
  std::vector<double> distances (posed.size ());
  pcl::Indices nearest (1);
  std::vector<float> squared (1);
  for (size_t c = 0; c < posed.size (); ++c) {
    this->tree_->nearestKSearch (posed[c], 1, nearest, squared);
    distances[c] = std::sqrt (static_cast<double> (squared[0]));
  }
  this->input_ = source;
  report_.correspondences = static_cast<int> (distances.size ());
  if (distances.empty ())
    return;
  const Eigen::Map<const Eigen::VectorXd> d (distances.data (), distances.size ());
  report_.fitness_mean = d.mean ();
  report_.fitness_rms = std::sqrt (d.squaredNorm () / static_cast<double> (d.size ()));
  report_.fitness_median = median (distances);
}

template <typename PointTarget, typename Scalar>
void
MorphableICP<PointTarget, Scalar>::store (const PoseShapeState& state, PointCloudSource& output)
{
  coefficients_ = detail::restack (state.coefficients, state.selection, selection_);
  coefficients_sd_ = coefficientsInStandardDeviations (*model_, coefficients_, selection_);
  fitted_vertices_ = state.posed ();
  const Eigen::Matrix3Xd normals = vertexNormals (TriangleMesh{fitted_vertices_, model_->triangles ()});
  output.resize (fitted_vertices_.cols ());
  for (Eigen::Index i = 0; i < fitted_vertices_.cols (); ++i) {
    output[i].getVector3fMap () = fitted_vertices_.col (i).template cast<float> ();
    if constexpr (pcl::traits::has_normal_v<PointTarget>)
      output[i].getNormalVector3fMap () = normals.col (i).template cast<float> ();
  }
  this->final_transformation_ = state.similarity ().template cast<typename Matrix4::Scalar> ();
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

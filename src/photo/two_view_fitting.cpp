// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/common/landmarks.h>
#include <morphreg/model/coefficient_units.h>
#include <morphreg/photo/polyline_2d.h>
#include <morphreg/photo/two_view_fitting.h>
#include <morphreg/warp/thin_plate_spline.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>
#include <map>
#include <numeric>

namespace morphreg
{
namespace
{
/** Model mm: a profile-line vertex farther than this beyond either end of the silhouette has no correspondence (the
 *  silhouette may show part of the profile: the end says nothing about where the outline goes on). */
constexpr double kEndSlack = 5.0;

/** At most this many rounds of TPS warp and 3D-3D fit in fitTpsIcp. */
constexpr int kTpsIcpRounds = 10;

/** Mean squared motion (model mm^2) of the fitted vertices below which an iteration loop has converged. */
constexpr double kMotionEpsilon = 1e-6;

/** Mean squared motion (model mm^2) of the vertices between \a before (posed) and \a state. */
double
motion (const Eigen::Matrix3Xd& before, const PoseShapeState& state)
{
  return (state.posed () - before).colwise ().squaredNorm ().mean () / (state.scale () * state.scale ());
}

/** A row of per-axis weights \a weight. */
PoseShapeRow
weightedRow (Eigen::Index slot, const Eigen::Vector3d& target, const Eigen::Vector3d& weight)
{
  return {static_cast<int> (slot), target, Eigen::Matrix3d (weight.asDiagonal ())};
}

/** The frontal landmarks used: model vertices, normalised (X, Y) positions and row weights; and the contour landmarks
 *  left out (weight 0). */
struct FrontalTargets
{
  std::vector<int> vertices;
  std::vector<Eigen::Vector2d> points;
  std::vector<double> weights;
  std::vector<std::string> ignored;

  double
  totalWeight () const
  {
    return std::accumulate (weights.begin (), weights.end (), 0.0);
  }
};

/** The rows of a two-view fit: the profile-line vertices (the first profile_count of shape.vertices), then the
 *  frontal landmark vertices, with their weights.
 */
struct TwoViewProblem
{
  PoseShapeLeastSquares shape; ///< the shape stage's solver
  PoseShapeLeastSquares pose;  ///< the similarity stage's (no shape unknowns)
  Eigen::Matrix3Xd mean;       ///< the mean shape's vertices of the slots
  Eigen::Index profile_count;
  std::vector<Eigen::Vector2d> landmarks; ///< normalised (X, Y) of slot profile_count + k
  std::vector<double> landmark_weights;   ///< the row weight of each landmark
  double sagittal_weight;
  double max_distance;
};

/** Throws InvalidInputError if the normalised frontal landmarks coincide or lie on one line. */
void
requireSpreadLandmarks (const std::vector<Eigen::Vector2d>& points)
{
  Eigen::Matrix2Xd centred (2, points.size ());
  for (size_t k = 0; k < points.size (); ++k)
    centred.col (static_cast<Eigen::Index> (k)) = points[k];
  centred.colwise () -= centred.rowwise ().mean ();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen (centred * centred.transpose ());
  const Eigen::Vector2d spread = eigen.eigenvalues ().cwiseMax (0.0).cwiseSqrt ();
  if (spread[1] < 1e-9)
    throw InvalidInputError ("TwoViewFitting: the frontal landmarks coincide");
  if (spread[0] < 1e-3 * spread[1])
    throw InvalidInputError ("TwoViewFitting: the frontal landmarks are collinear (they fix no pose)");
}

/** The frontal landmarks, validated against \a model: every id a model landmark; weighted \a weight, or
 *  \a contour_weight for outline points (isFrontalContourLandmarkId; left out when it is 0); at least 3 used, spread
 *  out. */
FrontalTargets
frontalTargets (const MorphableModel& model, const FrontalView& frontal, double weight, double contour_weight)
{
  FrontalTargets targets;
  for (const auto& landmark : frontal.normalisedLandmarks ()) {
    if (!model.landmarks ().count (landmark.first))
      throw InvalidInputError ("TwoViewFitting: frontal landmark '" + landmark.first + "' is not a model landmark");
    const bool contour = isFrontalContourLandmarkId (landmark.first);
    if (contour && contour_weight == 0.0) {
      targets.ignored.push_back (landmark.first);
      continue;
    }
    targets.vertices.push_back (model.landmarkVertex (landmark.first));
    targets.points.push_back (landmark.second);
    targets.weights.push_back (contour ? contour_weight : weight);
  }
  if (targets.points.size () < 3)
    throw InvalidInputError ("TwoViewFitting: " + std::to_string (targets.points.size ()) +
                             " frontal landmarks used; at least 3 are needed" +
                             (targets.ignored.empty () ? std::string ()
                                                       : " (outline landmarks such as '" + targets.ignored.front () +
                                                             "' are left out: setContourLandmarkWeight)"));
  requireSpreadLandmarks (targets.points);
  return targets;
}

/** The vertices of a two-view fit: the model's profile line, then the frontal landmark vertices of \a targets. */
std::vector<int>
twoViewVertices (const MorphableModel& model, const FrontalTargets& targets)
{
  std::vector<int> vertices = model.profileLine ();
  vertices.insert (vertices.end (), targets.vertices.begin (), targets.vertices.end ());
  return vertices;
}

/** The two-view problem over twoViewVertices with \a settings and \a targets' landmarks. */
TwoViewProblem
twoViewProblem (const MorphableModel& model, const PoseShapeSettings& settings, const FrontalTargets& targets,
                double sagittal_weight, double max_distance)
{
  PoseShapeSettings pose = settings;
  pose.components = ComponentSelection ();
  PoseShapeLeastSquares shape (model, twoViewVertices (model, targets), settings);
  Eigen::Matrix3Xd mean = shape.vertices (Eigen::VectorXd::Zero (shape.sigma ().size ()));
  return {std::move (shape), PoseShapeLeastSquares (model, twoViewVertices (model, targets), pose),
          std::move (mean),  static_cast<Eigen::Index> (model.profileLine ().size ()),
          targets.points,    targets.weights,
          sagittal_weight,   max_distance};
}

/** What a silhouette that the model's profile cannot follow should be checked for. */
const char* const kSilhouetteHint =
    "that the silhouette traces this face's profile (forehead, nose, lips, chin) in the photo's pixel coordinates";

/** Throws InvalidInputError when, after a fit, fewer than a quarter of the model's \a profile_count profile-line
 *  vertices lie on the silhouette (\a matched): the silhouette does not show this face's profile, and a fit to a few
 *  of its points would look converged but be meaningless.
 */
void
requireSilhouetteMatch (int matched, Eigen::Index profile_count)
{
  if (4 * static_cast<Eigen::Index> (matched) < profile_count)
    throw InvalidInputError ("the profile photo's silhouette does not match the model's profile: after the fit only " +
                             std::to_string (matched) + " of the model's " + std::to_string (profile_count) +
                             " profile-line vertices lie on it (at least a quarter must); check " + kSilhouetteHint);
}

/** \a state with the constrained vertices of \a problem. */
PoseShapeState
onProblem (PoseShapeState state, const PoseShapeLeastSquares& problem)
{
  state.vertices = problem.vertices (state.coefficients);
  return state;
}

/** Whether the projected profile-line vertex \a k (columns of \a profile) is hidden from its silhouette point
 *  \a closest by the profile line itself: another vertex of the line lies clearly nearer to that point (within 3/4 of
 *  its distance; on an outline the vertex nearest to its silhouette point is itself). The silhouette shows only the
 *  outline, so vertices inside a notch (the lips' inner edges, the mouth's cleft) or behind another part of the line
 *  have no silhouette point.
 */
bool
hiddenFromSilhouette (const Eigen::Matrix2Xd& profile, Eigen::Index k, const Eigen::Vector2d& closest)
{
  const double limit = 0.5625 * (profile.col (k) - closest).squaredNorm ();
  for (Eigen::Index j = 0; j < profile.cols (); ++j)
    if (j != k && (profile.col (j) - closest).squaredNorm () < limit)
      return true;
  return false;
}

/** The rows at \a state: profile correspondences (closest silhouette point within the distance), then the frontal
 *  landmarks; fills \a residuals with their in-image RMS distances in model mm.
 */
std::vector<PoseShapeRow>
currentRows (const TwoViewProblem& problem, const Polyline2d& silhouette, const PoseShapeState& state,
             TwoViewIteration& residuals)
{
  const Eigen::Matrix3Xd posed = state.posed ();
  const double mm = 1.0 / state.scale ();
  Eigen::Matrix2Xd profile (2, problem.profile_count);
  profile.row (0) = posed.row (2).head (problem.profile_count);
  profile.row (1) = posed.row (1).head (problem.profile_count);
  std::vector<PoseShapeRow> rows;
  double profile_sum = 0.0;
  for (Eigen::Index k = 0; k < problem.profile_count; ++k) {
    const Eigen::Vector2d projected = profile.col (k);
    const Eigen::Vector2d closest = silhouette.closestPoint (projected);
    const double distance = (closest - projected).norm () * mm;
    if (!(distance <= problem.max_distance) || (distance > kEndSlack && silhouette.isEnd (closest)) ||
        hiddenFromSilhouette (profile, k, closest))
      continue; // too far, beyond the end of a silhouette that shows part of the profile, or not on the outline
    rows.push_back (weightedRow (k, Eigen::Vector3d (0.0, closest.y (), closest.x ()),
                                 Eigen::Vector3d (problem.sagittal_weight, 1.0, 1.0)));
    profile_sum += distance * distance;
  }
  residuals.profile_correspondences = static_cast<int> (rows.size ());
  residuals.profile_rms = rows.empty () ? 0.0 : std::sqrt (profile_sum / static_cast<double> (rows.size ()));
  double landmark_sum = 0.0;
  for (size_t l = 0; l < problem.landmarks.size (); ++l) {
    const Eigen::Index slot = problem.profile_count + static_cast<Eigen::Index> (l);
    const Eigen::Vector2d& marked = problem.landmarks[l];
    const double weight = problem.landmark_weights[l];
    rows.push_back (
        weightedRow (slot, Eigen::Vector3d (marked.x (), marked.y (), 0.0), Eigen::Vector3d (weight, weight, 0.0)));
    landmark_sum += (marked - posed.col (slot).head<2> ()).squaredNorm () * mm * mm;
  }
  residuals.landmark_rms =
      problem.landmarks.empty () ? 0.0 : std::sqrt (landmark_sum / static_cast<double> (problem.landmarks.size ()));
  return rows;
}

/** The joint fit's data cost per row (model mm^2) of \a residuals: profile squares and the landmark squares with
 *  their total weight \a landmark_weight. */
double
jointCost (const TwoViewIteration& residuals, double landmark_weight)
{
  const double profile = residuals.profile_correspondences, marked = landmark_weight;
  return (residuals.profile_rms * residuals.profile_rms * profile +
          residuals.landmark_rms * residuals.landmark_rms * marked) /
         (profile + marked);
}

/** The rows of one TPS-ICP round, for every model vertex (\a state holds them all): the posed model warped by a 3D
 *  thin plate spline (in mm) that moves each frontal landmark vertex to its mark (X, Y) at its current depth (the mean
 *  mark of landmarks sharing a vertex) and each other profile-line vertex with a correspondence in \a image_rows to
 *  its silhouette point (Z, Y) at its current X. The warped vertices guide the parts the photos do not show and share
 *  the image rows' total weight; the landmark targets and the profile rows themselves keep their weights, so the fit
 *  stays on the silhouette where the warp's smooth interpolation cannot follow it.
 */
std::vector<PoseShapeRow>
tpsTargetRows (const TwoViewProblem& two_view, const std::vector<PoseShapeRow>& image_rows, const PoseShapeState& state)
{
  const double s = state.scale ();
  const Eigen::Matrix3Xd posed = state.posed ();
  std::map<int, Eigen::Vector3d> marked;  // landmark vertex -> sum of its marks (X, Y) and their count
  std::map<int, Eigen::Vector3d> anchors; // vertex -> its target
  std::map<int, double> weights;          // landmark vertex -> its row weight
  for (const PoseShapeRow& row : image_rows) {
    const int vertex = two_view.shape.slots ()[static_cast<size_t> (row.slot)];
    if (row.slot >= two_view.profile_count) {
      marked.emplace (vertex, Eigen::Vector3d::Zero ()).first->second +=
          Eigen::Vector3d (row.target.x (), row.target.y (), 1.0);
      weights[vertex] = std::max (weights[vertex], row.metric (0, 0));
    }
    else
      anchors[vertex] = Eigen::Vector3d (posed (0, vertex), row.target.y (), row.target.z ());
  }
  for (const auto& [vertex, sum] : marked)
    anchors[vertex] = Eigen::Vector3d (sum.x () / sum.z (), sum.y () / sum.z (), posed (2, vertex));
  Eigen::Matrix3Xd source (3, anchors.size ()), target (3, anchors.size ());
  Eigen::Index column = 0;
  for (const auto& [vertex, point] : anchors) {
    source.col (column) = posed.col (vertex) / s;
    target.col (column++) = point / s;
  }
  ThinPlateSpline<double, 3> tps;
  tps.fit (source, target);
  Eigen::Matrix3Xd warped = posed / s;
  tps.transformPositions (warped);
  warped *= s;
  // The warped vertices share the weight of the image rows they come from, so the priors weigh as in the joint fit
  // (at weight 1 each the mesh would outweigh them a hundredfold and the fit would follow the warp's extrapolation).
  const Eigen::Vector3d share =
      Eigen::Vector3d::Constant (static_cast<double> (image_rows.size ()) / static_cast<double> (warped.cols ()));
  std::vector<PoseShapeRow> rows;
  for (Eigen::Index i = 0; i < warped.cols (); ++i)
    rows.push_back (weightedRow (i, warped.col (i), share));
  for (const auto& entry : marked)
    rows.push_back (
        weightedRow (entry.first, anchors.at (entry.first), Eigen::Vector3d::Constant (weights.at (entry.first))));
  for (const PoseShapeRow& row : image_rows)
    if (row.slot < two_view.profile_count)
      rows.push_back ({two_view.shape.slots ()[static_cast<size_t> (row.slot)], row.target, row.metric});
  return rows;
}

/** The initial scale from the frontal landmarks: the least-squares ratio of their spread in the photo (normalised)
 *  to the model's mean landmarks' in (X, Y). */
double
landmarkScale (const TwoViewProblem& problem)
{
  const auto count = static_cast<Eigen::Index> (problem.landmarks.size ());
  Eigen::Matrix2Xd image (2, count), model (2, count);
  for (Eigen::Index k = 0; k < count; ++k) {
    image.col (k) = problem.landmarks[static_cast<size_t> (k)];
    model.col (k) = problem.mean.col (problem.profile_count + k).head<2> ();
  }
  const Eigen::Vector2d image_centre = image.rowwise ().mean (), model_centre = model.rowwise ().mean ();
  image.colwise () -= image_centre;
  model.colwise () -= model_centre;
  return (image.array () * model.array ()).sum () / model.squaredNorm ();
}

/** The initial scale from the silhouette alone: among scales from 0.5 to 2 times the one that gives the profile
 *  line the silhouette's height, the one at which the profile-line vertices (nose tip on the photo's) lie closest to
 *  the silhouette, each distance (model mm) truncated at the max correspondence distance; a silhouette that shows
 *  part of the profile (the face, not the back of the head) then still finds its size. */
double
silhouetteScale (const TwoViewProblem& problem, const Eigen::Vector3d& nose, const Polyline2d& silhouette)
{
  const Eigen::Matrix3Xd profile = problem.mean.leftCols (problem.profile_count);
  const double model_height = profile.row (1).maxCoeff () - profile.row (1).minCoeff ();
  const double image_height = silhouette.points ().row (1).maxCoeff () - silhouette.points ().row (1).minCoeff ();
  if (!(model_height > 0.0) || !(image_height > 0.0))
    throw InvalidInputError ("TwoViewFitting: the model's profile line or the silhouette has no height");
  double best_scale = image_height / model_height, best_score = std::numeric_limits<double>::infinity ();
  constexpr int kCandidates = 25;
  for (int k = 0; k < kCandidates; ++k) {
    const double scale = image_height / model_height * std::pow (2.0, (k - kCandidates / 2) / 12.0);
    double score = 0.0;
    for (Eigen::Index i = 0; i < profile.cols (); ++i) {
      const Eigen::Vector2d projected (scale * (profile (2, i) - nose.z ()), scale * (profile (1, i) - nose.y ()));
      score += std::min ((silhouette.closestPoint (projected) - projected).norm () / scale, problem.max_distance);
    }
    if (score < best_score) {
      best_score = score;
      best_scale = scale;
    }
  }
  return best_scale;
}

/** The initial pose: no rotation, the model's nose tip at the origin (the nose tip centres both photos), and the
 *  scale from the frontal landmarks when there are some (a partial silhouette says little about the head's size),
 *  else from the silhouette (silhouetteScale). */
PoseShapeState
initialState (const MorphableModel& model, const TwoViewProblem& problem, const Polyline2d& silhouette)
{
  const Eigen::Vector3d nose = model.meanVertex (model.landmarkVertex ("nose_tip"));
  PoseShapeState state;
  state.log_scale =
      std::log (problem.landmarks.size () >= 2 ? landmarkScale (problem) : silhouetteScale (problem, nose, silhouette));
  state.translation = -state.scale () * nose;
  state.coefficients = Eigen::VectorXd::Zero (problem.shape.sigma ().size ());
  state.vertices = problem.mean;
  return state;
}

/** Stores \a state's similarity, coefficients (of \a fit.selection) and meshes in \a fit. */
void
storeState (const MorphableModel& model, const PoseShapeState& state, TwoViewFit& fit)
{
  fit.coefficients_mm = state.coefficients;
  fit.coefficients = coefficientsInStandardDeviations (model, state.coefficients, fit.selection);
  fit.scale = state.scale ();
  fit.rotation = state.rotation;
  fit.translation = state.translation;
  fit.model_mesh = model.generateMesh (state.coefficients, fit.selection);
  fit.image_mesh = fit.model_mesh;
  fit.image_mesh.vertices = (fit.scale * fit.rotation * fit.model_mesh.vertices).colwise () + fit.translation;
}

/** \a value if it is finite and > 0 (>= 0 with \a zero_allowed); else InvalidInputError naming \a what. */
double
checkedSetting (double value, bool zero_allowed, const std::string& what)
{
  if (!std::isfinite (value) || value < 0.0 || (value == 0.0 && !zero_allowed))
    throw InvalidInputError ("TwoViewFitting: " + what + " must be finite and " + (zero_allowed ? ">= 0" : "> 0") +
                             ", got " + std::to_string (value));
  return value;
}
} // namespace

TwoViewFitting::TwoViewFitting (MorphableModel::ConstPtr model) : model_ (std::move (model))
{
  if (!model_)
    throw InvalidInputError ("TwoViewFitting: the model is null");
  if (model_->profileLine ().size () < 2)
    throw InvalidInputError ("TwoViewFitting: the model has no profile line (MorphableModel::setProfileLine)");
  if (!model_->landmarks ().count ("nose_tip"))
    throw InvalidInputError ("TwoViewFitting: the model has no nose_tip landmark (it centres the photos)");
  settings_.components = model_->firstComponents (kDefaultComponents);
  settings_.smoothness_weight = kDefaultSmoothnessWeight;
  settings_.prior_weight = kDefaultShapePriorWeight;
  settings_.coefficient_limit = kDefaultCoefficientLimit;
  settings_.model_units = true;
}

void
TwoViewFitting::setComponentSelection (const ComponentSelection& selection)
{
  model_->requireCompatible (selection, nullptr, "TwoViewFitting::setComponentSelection");
  settings_.components = selection;
}

void
TwoViewFitting::setSmoothnessWeight (double lambda1)
{
  settings_.smoothness_weight =
      checkedSetting (lambda1, false, "lambda_1 (the smoothness weight; regions without data need it)");
}

void
TwoViewFitting::setShapePriorWeight (double lambda2, ShapePrior prior)
{
  settings_.prior_weight = requirePriorWeight (lambda2, "TwoViewFitting: lambda_2");
  settings_.prior = prior;
}

void
TwoViewFitting::setCoefficientLimit (double sigmas)
{
  if (!(sigmas > 0.0)) // NaN included; infinity is no limit
    throw InvalidInputError ("TwoViewFitting: the coefficient limit must be > 0 standard deviations (infinity for "
                             "none), got " +
                             std::to_string (sigmas));
  settings_.coefficient_limit = sigmas;
}

void
TwoViewFitting::setFrontalWeight (double weight)
{
  frontal_weight_ = checkedSetting (weight, false, "the frontal weight");
}

void
TwoViewFitting::setContourLandmarkWeight (double weight)
{
  contour_weight_ = checkedSetting (weight, true, "the contour landmark weight");
}

void
TwoViewFitting::setSagittalWeight (double weight)
{
  sagittal_weight_ = checkedSetting (weight, true, "the sagittal weight");
}

void
TwoViewFitting::setMaxCorrespondenceDistance (double millimetres)
{
  max_distance_ = checkedSetting (millimetres, false, "the max correspondence distance");
}

void
TwoViewFitting::setIterations (int similarity, int shape)
{
  if (similarity < 0 || shape < 0)
    throw InvalidInputError ("TwoViewFitting: iteration budgets must be >= 0, got " + std::to_string (similarity) +
                             " and " + std::to_string (shape));
  similarity_iterations_ = similarity;
  shape_iterations_ = shape;
}

TwoViewFit
TwoViewFitting::fitProfile (const ProfileView& profile) const
{
  if (sagittal_weight_ <= 0.0)
    throw InvalidInputError ("TwoViewFitting::fitProfile: the sagittal weight is 0, so nothing fixes X");
  return fit (profile, nullptr);
}

TwoViewFit
TwoViewFitting::fitJoint (const ProfileView& profile, const FrontalView& frontal) const
{
  return fit (profile, &frontal);
}

TwoViewFit
TwoViewFitting::fitTpsIcp (const ProfileView& profile, const FrontalView& frontal) const
{
  const FrontalTargets targets = frontalTargets (*model_, frontal, frontal_weight_, contour_weight_);
  TwoViewFit result = fitProfile (profile);
  result.ignored_landmarks = targets.ignored;
  // The error that decides when to stop: the image residuals of the joint fit's rows.
  const TwoViewProblem two_view = twoViewProblem (*model_, settings_, targets, sagittal_weight_, max_distance_);
  const PoseShapeLeastSquares whole (*model_, {}, settings_);
  const Polyline2d silhouette (profile.normalisedSilhouette ());

  PoseShapeState state;
  state.log_scale = std::log (result.scale);
  state.rotation = result.rotation;
  state.translation = result.translation;
  state.coefficients = result.coefficients_mm;
  state.vertices = whole.vertices (state.coefficients);
  PoseShapeState best = state;
  double best_error = std::numeric_limits<double>::infinity ();
  for (int round = 0;; ++round) {
    TwoViewIteration iteration;
    iteration.stage = TwoViewStage::tps_icp;
    const std::vector<PoseShapeRow> image_rows =
        currentRows (two_view, silhouette, onProblem (state, two_view.shape), iteration);
    const double error = jointCost (iteration, targets.totalWeight ());
    if (!(error < best_error) || !isPlausibleShape (state.coefficients.cwiseQuotient (whole.sigma ())))
      break; // no better in the photos, or a head the model's population does not hold
    best = state;
    best_error = error;
    result.tps_rounds = round;
    result.history.push_back (iteration);
    if (round == kTpsIcpRounds)
      break;
    const std::vector<PoseShapeRow> rows = tpsTargetRows (two_view, image_rows, state);
    for (int it = 0; it < shape_iterations_; ++it) {
      const Eigen::Matrix3Xd before = state.posed ();
      if (!whole.step (state, rows))
        throw NumericalError ("TwoViewFitting::fitTpsIcp: the normal equations could not be solved");
      if (motion (before, state) < kMotionEpsilon)
        break;
    }
  }
  result.final_residuals.stage = TwoViewStage::tps_icp;
  result.returned = result.tps_rounds > 0 ? "tps_icp" : "profile";
  currentRows (two_view, silhouette, onProblem (best, two_view.shape), result.final_residuals);
  storeState (*model_, best, result);
  return result;
}

TwoViewFit
TwoViewFitting::fit (const ProfileView& profile, const FrontalView* frontal) const
{
  const FrontalTargets targets =
      frontal ? frontalTargets (*model_, *frontal, frontal_weight_, contour_weight_) : FrontalTargets ();
  const TwoViewProblem problem = twoViewProblem (*model_, settings_, targets, sagittal_weight_, max_distance_);
  const Eigen::Matrix2Xd silhouette_points = profile.normalisedSilhouette ();
  const Polyline2d silhouette (silhouette_points);
  PoseShapeState state = initialState (*model_, problem, silhouette);
  TwoViewFit result;
  for (const TwoViewStage stage : {TwoViewStage::similarity, TwoViewStage::shape}) {
    const PoseShapeLeastSquares& solver = stage == TwoViewStage::shape ? problem.shape : problem.pose;
    const int budget = stage == TwoViewStage::similarity ? similarity_iterations_ : shape_iterations_;
    for (int it = 0; it < budget; ++it) {
      TwoViewIteration iteration;
      iteration.stage = stage;
      const std::vector<PoseShapeRow> rows = currentRows (problem, silhouette, state, iteration);
      requireEnoughRows (static_cast<size_t> (iteration.profile_correspondences), 3, "the profile photo",
                         "profile-line vertices of the model lie within " + std::to_string (max_distance_) +
                             " mm of the silhouette",
                         kSilhouetteHint);
      result.history.push_back (iteration);
      const Eigen::Matrix3Xd before = state.posed ();
      if (!solver.step (state, rows))
        throw NumericalError ("TwoViewFitting: the normal equations could not be solved");
      if (motion (before, state) < kMotionEpsilon)
        break;
    }
  }
  result.final_residuals.stage = result.history.empty () ? TwoViewStage::similarity : result.history.back ().stage;
  currentRows (problem, silhouette, state, result.final_residuals);
  requireSilhouetteMatch (result.final_residuals.profile_correspondences, problem.profile_count);
  result.selection = settings_.components;
  result.returned = frontal ? "joint" : "profile";
  result.ignored_landmarks = targets.ignored;
  storeState (*model_, state, result);
  return result;
}
} // namespace morphreg

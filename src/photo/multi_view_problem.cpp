// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/model/coefficient_units.h>
#include <morphreg/common/error.h>
#include <morphreg/common/landmarks.h>
#include <morphreg/photo/multi_view_problem.h>

#include <Eigen/Eigenvalues>

#include <cmath>
#include <limits>

namespace morphreg
{
namespace
{
/** Mean squared motion (model mm^2) of the fitted vertices below which an iteration loop has converged. */
constexpr double kMotionEpsilon = 1e-6;

/** What a traced outline that the model's outline cannot follow should be checked for. */
const char* const kOutlineHint =
    "that the outline traces this face's profile (forehead, nose, lips, chin) in the photo's pixel coordinates";

/** The mean position of those of \a ids the model has (their mean shape), or none. */
std::optional<Eigen::Vector3d>
meanLandmark (const MorphableModel& model, std::initializer_list<const char*> ids)
{
  Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
  int count = 0;
  for (const char* id : ids)
    if (model.landmarks ().count (id)) {
      sum += model.meanVertex (model.landmarkVertex (id));
      ++count;
    }
  return count > 0 ? std::optional<Eigen::Vector3d> (sum / count) : std::nullopt;
}

/** Throws InvalidInputError naming \a source if the pixels coincide or lie on one line. */
void
requireSpread (const std::vector<Eigen::Vector2d>& points, const std::string& source)
{
  Eigen::Matrix2Xd centred (2, points.size ());
  for (size_t k = 0; k < points.size (); ++k)
    centred.col (static_cast<Eigen::Index> (k)) = points[k];
  centred.colwise () -= centred.rowwise ().mean ();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen (centred * centred.transpose ());
  const Eigen::Vector2d spread = eigen.eigenvalues ().cwiseMax (0.0).cwiseSqrt ();
  if (spread[1] < 1e-9)
    throw InvalidInputError ("PhotoFitting: " + source + ": the landmarks coincide");
  if (spread[0] < 1e-3 * spread[1])
    throw InvalidInputError ("PhotoFitting: " + source + ": the landmarks are collinear (they fix no pose)");
}
} // namespace

MultiViewProblem::MultiViewProblem (MorphableModel::ConstPtr model, std::vector<PhotoView> views,
                                    const PhotoFitSettings& settings)
  : model_ (std::move (model)), settings_ (settings),
    topology_ (requireFittable (model_).triangles (), model_->numVertices ())
{
  if (views.empty ())
    throw InvalidInputError ("PhotoFitting: no photo to fit");
  settings_.shape.model_units = false; // the rows carry 1 / (pixels per model mm)^2 themselves
  computeFaceZone ();
  for (PhotoView& view : views)
    addView (std::move (view));
  setPriorWeight (settings_.shape.prior_weight);
  PoseShapeSettings pose = settings_.shape;
  pose.components = ComponentSelection ();
  pose_solver_ = std::make_unique<PoseShapeLeastSquares> (*model_, std::vector<int> (), pose);
}

MultiViewProblem::~MultiViewProblem () = default;

const MorphableModel&
MultiViewProblem::requireFittable (const MorphableModel::ConstPtr& model)
{
  if (!model)
    throw InvalidInputError ("PhotoFitting: the model is null");
  if (model->profileLine ().size () < 2)
    throw InvalidInputError ("PhotoFitting: the model has no profile line (MorphableModel::setProfileLine)");
  if (!model->landmarks ().count ("nose_tip"))
    throw InvalidInputError ("PhotoFitting: the model has no nose_tip landmark (it centres the photos)");
  return *model;
}

void
MultiViewProblem::setPriorWeight (double weight)
{
  settings_.shape.prior_weight = requirePriorWeight (weight, "PhotoFitting: lambda_2");
  shape_solver_ = std::make_unique<PoseShapeLeastSquares> (*model_, std::vector<int> (), settings_.shape);
}

void
MultiViewProblem::computeFaceZone ()
{
  const MorphableModel& model = *model_;
  auto brows = meanLandmark (model, {"right_eyebrow", "left_eyebrow"});
  if (!brows)
    brows = meanLandmark (model, {"ibug68_19", "ibug68_24"});
  const auto ears = meanLandmark (model, {"right_tragus", "left_tragus"});
  face_zone_.assign (static_cast<size_t> (model.numVertices ()), 1);
  if (!brows)
    return; // nothing says where the face is: every outline point is the face's
  const double front = ears ? ears->z () + 10.0 : -std::numeric_limits<double>::infinity ();
  for (int v = 0; v < model.numVertices (); ++v) {
    const Eigen::Vector3d p = model.meanVertex (v);
    face_zone_[static_cast<size_t> (v)] = p.y () <= brows->y () && p.z () >= front;
  }
}

void
MultiViewProblem::addView (PhotoView view)
{
  const MorphableModel& model = *model_;
  ViewData data (std::move (view));
  data.camera = data.view.camera ();
  const size_t index = views_.size ();
  for (const auto& [id, pixel] : data.view.landmarks ()) {
    if (!model.landmarks ().count (id))
      throw InvalidInputError ("PhotoFitting: " + data.view.source () + ": landmark '" + id +
                               "' is not a model landmark");
    const int vertex = model.landmarkVertex (id);
    const bool outline = isOutlineLandmarkId (id);
    if (outline && settings_.outline_landmarks == OutlineLandmarkMode::ignored)
      ignored_.push_back (id);
    else if (outline && settings_.outline_landmarks == OutlineLandmarkMode::outline)
      data.outline_landmarks.push_back (
          {vertex, pixel, nearbyVertices (vertex), face_zone_[static_cast<size_t> (vertex)] != 0});
    else {
      landmarks_.push_back (
          {index, vertex, pixel, outline ? settings_.outline_landmark_weight : settings_.landmark_weight});
      ++data.landmarks;
    }
  }
  if (!data.view.outline ().empty ())
    addOutline (data);
  views_.push_back (std::move (data));
}

void
MultiViewProblem::addOutline (ViewData& data)
{
  const std::vector<Eigen::Vector2d>& points = data.view.outline ();
  Eigen::Matrix2Xd matrix (2, points.size ());
  for (size_t k = 0; k < points.size (); ++k)
    matrix.col (static_cast<Eigen::Index> (k)) = points[k];
  data.outline.emplace (matrix);
  data.two_sided.assign (points.size (), 1);
  if (data.view.hairline ()) {
    Eigen::Index nearest = 0;
    (matrix.colwise () - *data.view.hairline ()).colwise ().squaredNorm ().minCoeff (&nearest);
    data.hairline = nearest;
  }
}

std::vector<int>
MultiViewProblem::nearbyVertices (int vertex) const
{
  const Eigen::Vector3d centre = model_->meanVertex (vertex);
  std::vector<int> nearby;
  for (int v = 0; v < model_->numVertices (); ++v)
    if ((model_->meanVertex (v) - centre).norm () <= kOutlineLandmarkRadius)
      nearby.push_back (v);
  return nearby;
}

PoseShapeState
MultiViewProblem::meanState () const
{
  return shape_solver_->state (Eigen::Matrix4d::Identity (), Eigen::VectorXd::Zero (shape_solver_->sigma ().size ()));
}

int
MultiViewProblem::numLandmarks () const
{
  return static_cast<int> (landmarks_.size ());
}

bool
MultiViewProblem::hasOutline () const
{
  for (const ViewData& view : views_)
    if (view.outline)
      return true;
  return false;
}

void
MultiViewProblem::requireLandmarks () const
{
  std::string outline = ignored_.empty () ? std::string () : ignored_.front ();
  for (const ViewData& data : views_)
    for (const auto& [id, pixel] : data.view.landmarks ())
      outline = outline.empty () && isOutlineLandmarkId (id) ? id : outline;
  if (landmarks_.size () < 3)
    throw InvalidInputError (
        "PhotoFitting: " + std::to_string (landmarks_.size ()) +
        " landmarks fix model vertices; at least 3 are needed" +
        (outline.empty () ? std::string () : " (outline landmarks such as '" + outline + "' fix no vertex)"));
  for (size_t v = 0; v < views_.size (); ++v) {
    std::vector<Eigen::Vector2d> pixels;
    for (const Landmark& landmark : landmarks_)
      if (landmark.view == v)
        pixels.push_back (landmark.pixel);
    if (pixels.size () >= 3)
      requireSpread (pixels, views_[v].view.source ());
  }
}

double
MultiViewProblem::millimetresPerPixel (size_t view, const PoseShapeState& state) const
{
  const Eigen::Vector3d nose =
      state.scale () * state.rotation * state.vertices.col (model_->landmarkVertex ("nose_tip")) + state.translation;
  return 1.0 / (views_[view].camera->pixelsPerUnit (nose) * state.scale ());
}

void
MultiViewProblem::fitStages (PoseShapeState& state, PhotoRows rows, const std::vector<bool>& left_out,
                             std::vector<PhotoFitIteration>& history)
{
  poseStage (state, rows, left_out, history);
  shapeStages (state, rows, left_out, history);
}

void
MultiViewProblem::poseStage (PoseShapeState& state, PhotoRows rows, const std::vector<bool>& left_out,
                             std::vector<PhotoFitIteration>& history)
{
  resetOutlineLabels (state);
  runStage (state, PhotoFitStage::similarity, rows, left_out, history, settings_.similarity_iterations);
}

void
MultiViewProblem::shapeStages (PoseShapeState& state, PhotoRows rows, const std::vector<bool>& left_out,
                               std::vector<PhotoFitIteration>& history, int budget)
{
  const int iterations = budget < 0 ? settings_.shape_iterations : budget;
  resetOutlineLabels (state);
  runStage (state, PhotoFitStage::shape, rows, left_out, history, iterations);
  if (extendFaceLabels (state))
    runStage (state, PhotoFitStage::shape, rows, left_out, history, iterations);
  requireOutlineMatch (state);
}

std::vector<int>
MultiViewProblem::landmarkVertices () const
{
  std::vector<int> vertices;
  for (const Landmark& landmark : landmarks_)
    vertices.push_back (landmark.vertex);
  return vertices;
}

void
MultiViewProblem::runStage (PoseShapeState& state, PhotoFitStage stage, PhotoRows kinds,
                            const std::vector<bool>& left_out, std::vector<PhotoFitIteration>& history,
                            int budget) const
{
  const bool shape = stage == PhotoFitStage::shape;
  for (int it = 0; it < budget; ++it) {
    PhotoFitIteration iteration;
    iteration.stage = stage;
    const std::vector<PoseShapeRow> current = rows (state, kinds, left_out, iteration);
    if (hasOutline ())
      requireEnoughRows (
          static_cast<size_t> (iteration.outline_correspondences + iteration.outline_inside), 3, "the traced outlines",
          "outline points of the model lie within " + std::to_string (settings_.max_distance) + " mm of them",
          kOutlineHint);
    history.push_back (iteration);
    const Eigen::Matrix3Xd before = state.posed ();
    if (!solver (shape).step (state, current))
      throw NumericalError ("PhotoFitting: the normal equations could not be solved");
    if (converged (before, state))
      break;
  }
}

void
MultiViewProblem::requireOutlineMatch (const PoseShapeState& state) const
{
  // The profile line of a side view must lie on the outline for at least a quarter of its vertices: otherwise the
  // outline does not show this face's profile, and a fit to a few of its points looks converged but means nothing.
  const std::vector<int> matched = profileLineMatches (state);
  const auto profile_count = static_cast<int> (model_->profileLine ().size ());
  for (const int count : matched)
    if (count >= 0 && 4 * count < profile_count)
      throw InvalidInputError ("the traced outline does not match the model's profile: after the fit only " +
                               std::to_string (count) + " of the model's " + std::to_string (profile_count) +
                               " profile-line vertices lie on it (at least a quarter must); check " + kOutlineHint);
}

bool
MultiViewProblem::converged (const Eigen::Matrix3Xd& before, const PoseShapeState& after)
{
  const double motion = (after.posed () - before).colwise ().squaredNorm ().mean () / (after.scale () * after.scale ());
  return motion < kMotionEpsilon;
}

bool
MultiViewProblem::hasPerspectiveCamera () const
{
  for (const ViewData& data : views_)
    if (data.camera && data.camera->isPerspective ())
      return true;
  return false;
}

double
MultiViewProblem::imageError (const PhotoFitIteration& residuals) const
{
  double landmark_weight = 0.0;
  for (const Landmark& landmark : landmarks_)
    landmark_weight += landmark.weight;
  const double outline = residuals.outline_correspondences;
  const double outline_landmarks = residuals.outline_landmarks * settings_.outline_landmark_weight;
  const double total = outline + landmark_weight + outline_landmarks;
  return total > 0.0 ? (residuals.outline_rms * residuals.outline_rms * outline +
                        residuals.landmark_rms * residuals.landmark_rms * landmark_weight +
                        residuals.outline_landmark_rms * residuals.outline_landmark_rms * outline_landmarks) /
                           total
                     : 0.0;
}

PhotoFit
MultiViewProblem::stagedFit (const PoseShapeState& start, PhotoRows rows, const std::string& returned)
{
  PoseShapeState state = start;
  std::vector<PhotoFitIteration> history;
  fitStages (state, rows, {}, history);
  PhotoFit fit = result (state, rows);
  fit.history = std::move (history);
  fit.final_residuals.stage = fit.history.empty () ? PhotoFitStage::similarity : fit.history.back ().stage;
  fit.returned = returned;
  return fit;
}

PhotoFit
MultiViewProblem::result (const PoseShapeState& state, PhotoRows kinds) const
{
  const MorphableModel& model = *model_;
  PhotoFit fit;
  fit.selection = settings_.shape.components;
  fit.coefficients_mm = state.coefficients;
  fit.coefficients = coefficientsInStandardDeviations (model, state.coefficients, fit.selection);
  fit.scale = state.scale ();
  fit.rotation = state.rotation;
  fit.translation = state.translation;
  fit.model_mesh = model.generateMesh (state.coefficients, fit.selection);
  fit.image_mesh = fit.model_mesh;
  fit.image_mesh.vertices = (fit.scale * fit.rotation * fit.model_mesh.vertices).colwise () + fit.translation;
  rows (state, kinds, {}, fit.final_residuals);
  fit.ignored_landmarks = ignored_;
  for (const ViewData& data : views_) {
    int two_sided = 0;
    for (const char label : data.two_sided)
      two_sided += label;
    fit.views.push_back ({data.view.source (), *data.camera, data.estimated, data.focal_source, data.camera_rms,
                          data.landmarks, static_cast<int> (data.outline_landmarks.size ()),
                          static_cast<int> (data.view.outline ().size ()), two_sided,
                          !data.outline        ? ""
                          : data.hairline >= 0 ? "marked"
                                               : "from the fit"});
  }
  return fit;
}
} // namespace morphreg

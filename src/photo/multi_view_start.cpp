// SPDX-License-Identifier: BSD-3-Clause
// Where a photo fit starts (the pose from the landmarks, or for the orthographic pair the scale from the landmarks
// or the outline), and the cameras of photos that came without one.
#include <morphreg/common/error.h>
#include <morphreg/photo/camera_estimation.h>
#include <morphreg/photo/multi_view_problem.h>

#include <cmath>
#include <limits>

namespace morphreg
{
PoseShapeState
MultiViewProblem::initialState () const
{
  PoseShapeState state = meanState ();
  bool orthographic = true;
  const ViewData* best = nullptr;
  for (const ViewData& data : views_) {
    orthographic = orthographic && data.view.camera () && !data.view.camera ()->isPerspective ();
    if (data.view.camera () && data.view.camera ()->isPerspective () && data.landmarks >= 6 &&
        (!best || data.landmarks > best->landmarks))
      best = &data;
  }
  if (orthographic)
    return orthographicStart (state);
  for (const ViewData& data : views_)
    if (data.view.camera () && !best)
      throw InvalidInputError ("PhotoFitting: " + data.view.source () +
                               " has a camera, but no photo with a camera has the 6 landmarks that place the head in "
                               "the cameras' frame");
  if (!best)
    return state; // every camera is estimated: the views' frame is the model's, the mean head at the identity
  // The head's similarity from the given camera's pose relative to the mean head's landmarks (scale 1).
  const auto [points, pixels] = viewLandmarks (static_cast<size_t> (best - views_.data ()), state);
  const PhotoCamera& camera = *best->camera;
  const PhotoCamera relative = estimatePose (points, pixels, camera.intrinsics (), best->view.source ()).camera;
  state.rotation = camera.rotation ().transpose () * relative.rotation ();
  state.translation = camera.rotation ().transpose () * (relative.translation () - camera.translation ());
  return state;
}

std::pair<Eigen::Matrix3Xd, Eigen::Matrix2Xd>
MultiViewProblem::viewLandmarks (size_t view, const PoseShapeState& state) const
{
  const Eigen::Index count = views_[view].landmarks;
  Eigen::Matrix3Xd points (3, count);
  Eigen::Matrix2Xd pixels (2, count);
  const Eigen::Matrix3Xd posed = state.posed ();
  Eigen::Index column = 0;
  for (const Landmark& landmark : landmarks_)
    if (landmark.view == view) {
      points.col (column) = posed.col (landmark.vertex);
      pixels.col (column++) = landmark.pixel;
    }
  return {points, pixels};
}

void
MultiViewProblem::estimateCameras ()
{
  const PoseShapeState at = initialState ();
  for (size_t v = 0; v < views_.size (); ++v) {
    ViewData& data = views_[v];
    if (data.view.camera ())
      continue;
    const auto [points, pixels] = viewLandmarks (v, at);
    const FocalRange range =
        FocalRange::forImage (data.view.width (), data.view.height (), data.view.focalLength35mm ());
    const CameraEstimate estimate =
        estimateCamera (points, pixels, data.view.width (), data.view.height (), range, data.view.source ());
    data.camera = estimate.camera;
    data.estimated = true;
    data.focal_source = range.source;
    data.camera_rms = estimate.rms_pixels;
  }
}

PoseShapeState
MultiViewProblem::orthographicStart (PoseShapeState state) const
{
  // No rotation, the model's nose tip at the origin (the nose tip centres both photos), and the scale from the
  // landmarks when there are some (a partial outline says little about the head's size), else from the outline.
  const Eigen::Vector3d nose = model_->meanVertex (model_->landmarkVertex ("nose_tip"));
  const double scale = landmarks_.size () >= 2 ? landmarkScale () : outlineScale (nose);
  state.log_scale = std::log (scale);
  state.translation = -scale * nose;
  return state;
}

double
MultiViewProblem::landmarkScale () const
{
  // The least-squares ratio of the landmarks' spread in each photo (world units) to the mean head's.
  double products = 0.0, squares = 0.0;
  for (size_t v = 0; v < views_.size (); ++v) {
    const auto [points, pixels] = viewLandmarks (v, meanState ());
    if (points.cols () < 2)
      continue;
    const PhotoCamera& camera = *views_[v].camera;
    Eigen::Matrix2Xd image = camera.intrinsics ().topLeftCorner<2, 2> ().inverse () *
                             (pixels.colwise () - camera.intrinsics ().topRightCorner<2, 1> ());
    Eigen::Matrix2Xd model = camera.rotation ().topRows<2> () * points;
    image.colwise () -= Eigen::Vector2d (image.rowwise ().mean ());
    model.colwise () -= Eigen::Vector2d (model.rowwise ().mean ());
    products += (image.array () * model.array ()).sum ();
    squares += model.squaredNorm ();
  }
  if (!(squares > 0.0) || !(products > 0.0))
    throw InvalidInputError ("PhotoFitting: the landmarks fix no scale (they coincide, or mirror the model's)");
  return products / squares;
}

double
MultiViewProblem::outlineScale (const Eigen::Vector3d& nose) const
{
  // Among scales from 0.5 to 2 times the one that gives the profile line the outline's height, the one at which
  // the profile-line vertices (nose tip on the photo's) lie closest to the outline, each distance (model mm)
  // truncated at the max correspondence distance; an outline that shows part of the profile still finds its size.
  const ViewData* view = nullptr;
  for (const ViewData& data : views_)
    view = view ? view : data.outline ? &data : nullptr;
  if (!view)
    throw InvalidInputError ("PhotoFitting: neither landmarks nor a traced outline give the head's size");
  const PhotoCamera& camera = *view->camera;
  const std::vector<int>& line = model_->profileLine ();
  Eigen::Matrix2Xd unit (2, static_cast<Eigen::Index> (line.size ())); // the profile line at scale 1, pixels
  for (size_t k = 0; k < line.size (); ++k)
    unit.col (static_cast<Eigen::Index> (k)) =
        camera.project (model_->meanVertex (line[k]) - nose) - camera.project (Eigen::Vector3d::Zero ());
  const double model_height = unit.row (1).maxCoeff () - unit.row (1).minCoeff ();
  const Eigen::Matrix2Xd& outline = view->outline->points ();
  const double image_height = outline.row (1).maxCoeff () - outline.row (1).minCoeff ();
  if (!(model_height > 0.0) || !(image_height > 0.0))
    throw InvalidInputError ("PhotoFitting: the model's profile line or the outline has no height");
  const double pixels_per_unit = camera.pixelsPerUnit (Eigen::Vector3d::Zero ());
  double best_scale = image_height / model_height, best_score = std::numeric_limits<double>::infinity ();
  constexpr int kCandidates = 25;
  for (int k = 0; k < kCandidates; ++k) {
    const double scale = image_height / model_height * std::pow (2.0, (k - kCandidates / 2) / 12.0);
    double score = 0.0;
    for (Eigen::Index i = 0; i < unit.cols (); ++i) {
      const Eigen::Vector2d projected = camera.project (Eigen::Vector3d::Zero ()) + scale * unit.col (i);
      score += std::min ((view->outline->closestPoint (projected) - projected).norm () / (pixels_per_unit * scale),
                         settings_.max_distance);
    }
    if (score < best_score)
      best_score = score, best_scale = scale;
  }
  return best_scale;
}
} // namespace morphreg

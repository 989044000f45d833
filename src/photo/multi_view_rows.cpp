// SPDX-License-Identifier: BSD-3-Clause
// The rows of MultiViewProblem: landmarks, outline landmarks and traced outlines, linearised at the current state.
#include "model_outline.h"

#include <morphreg/photo/multi_view_problem.h>

#include <Eigen/LU>

#include <cmath>

namespace morphreg
{
namespace
{
/** Model mm: an outline point farther than this beyond either end of a traced outline has no row (the outline may
 *  show part of the head: its end says nothing about where the outline goes on). */
constexpr double kEndSlack = 5.0;

/** A camera looking along the model's X axis within this angle sees the model's profile line as its outline. */
const double kSideViewCosine = std::cos (15.0 * M_PI / 180.0);

/** The row of the pixel residual \a residual of the point \a point (slot \a vertex) with pixel derivative \a J:
 *  w |J (X' - X) + r|^2 written as (X' - T)^T W (X' - T). */
PoseShapeRow
pointRow (int vertex, const Eigen::Vector3d& point, const Eigen::Matrix<double, 2, 3>& J,
          const Eigen::Vector2d& residual, double weight)
{
  const Eigen::Matrix2d normal = J * J.transpose ();
  const Eigen::Vector3d step = J.transpose () * normal.inverse () * residual;
  return {vertex, point - step, weight * J.transpose () * J};
}

/** The row of the residual \a along (pixels) of the point along the image direction \a direction. */
PoseShapeRow
lineRow (int vertex, const Eigen::Vector3d& point, const Eigen::Matrix<double, 2, 3>& J,
         const Eigen::Vector2d& direction, double along, double weight)
{
  const Eigen::Vector3d gradient = J.transpose () * direction;
  return {vertex, point - gradient * (along / gradient.squaredNorm ()), weight * gradient * gradient.transpose ()};
}

/** Whether candidate \a k's pixel is hidden from its outline point \a closest by another candidate: one lies clearly
 *  nearer to that point (within 3/4 of its distance; on an outline the candidate nearest to its outline point is
 *  itself). The outline shows only the outermost points, so those inside a notch (the lips' inner edges) or behind
 *  another part of the outline have no outline point. */
bool
hiddenFromOutline (const Eigen::Matrix2Xd& pixels, Eigen::Index k, const Eigen::Vector2d& closest)
{
  const double limit = 0.5625 * (pixels.col (k) - closest).squaredNorm ();
  for (Eigen::Index j = 0; j < pixels.cols (); ++j)
    if (j != k && (pixels.col (j) - closest).squaredNorm () < limit)
      return true;
  return false;
}
} // namespace

bool
MultiViewProblem::isSideView (size_t view, const PoseShapeState& state) const
{
  const Eigen::Vector3d nose =
      state.scale () * state.rotation * state.vertices.col (model_->landmarkVertex ("nose_tip")) + state.translation;
  return std::abs (views_[view].camera->towardsCamera (nose).dot (state.rotation.col (0))) > kSideViewCosine;
}

MultiViewProblem::ViewOutline
MultiViewProblem::outlineCandidates (size_t view, const TriangleMesh& posed, const PoseShapeState& state) const
{
  const PhotoCamera& camera = *views_[view].camera;
  ViewOutline outline;
  outline.side = isSideView (view, state);
  if (outline.side)
    outline.vertices = model_->profileLine ();
  else {
    const detail::ProjectedModel projected = detail::projectModel (posed, camera);
    const double cell = 1.0 / millimetresPerPixel (view, state); // one model mm
    outline.vertices = detail::silhouetteVertices (topology_, posed.triangles, projected, std::max (cell, 1.0));
  }
  outline.pixels.resize (2, static_cast<Eigen::Index> (outline.vertices.size ()));
  for (size_t k = 0; k < outline.vertices.size (); ++k)
    outline.pixels.col (static_cast<Eigen::Index> (k)) = camera.project (posed.vertices.col (outline.vertices[k]));
  return outline;
}

std::vector<PoseShapeRow>
MultiViewProblem::rows (const PoseShapeState& state, PhotoRows kinds, const std::vector<bool>& left_out,
                        PhotoFitIteration& residuals, std::vector<PhotoRowKind>* row_kinds) const
{
  const TriangleMesh posed{state.posed (), model_->triangles ()};
  std::vector<PoseShapeRow> rows;
  RowSums sums;
  if (kinds == PhotoRows::all)
    for (size_t l = 0; l < landmarks_.size (); ++l)
      if (left_out.empty () || !left_out[l])
        addLandmarkRow (landmarks_[l], posed.vertices, state, rows, sums);
  for (size_t v = 0; v < views_.size (); ++v) {
    if (views_[v].outline)
      addOutlineRows (v, outlineCandidates (v, posed, state), posed.vertices, state, &rows, sums);
    if (kinds == PhotoRows::all && !views_[v].outline_landmarks.empty ())
      addOutlineLandmarkRows (v, posed, state, rows, sums);
  }
  if (row_kinds)
    *row_kinds = std::move (sums.kinds);
  const auto rms = [] (double sum, int count) { return count > 0 ? std::sqrt (sum / count) : 0.0; };
  residuals.outline_correspondences = sums.outline_count;
  residuals.outline_inside = sums.inside;
  residuals.outline_rms = rms (sums.outline, sums.outline_count);
  residuals.landmark_rms = rms (sums.landmark, sums.landmark_count);
  residuals.outline_landmarks = sums.outline_landmark_count;
  residuals.outline_landmark_rms = rms (sums.outline_landmark, sums.outline_landmark_count);
  return rows;
}

void
MultiViewProblem::addLandmarkRow (const Landmark& landmark, const Eigen::Matrix3Xd& posed, const PoseShapeState& state,
                                  std::vector<PoseShapeRow>& rows, RowSums& sums) const
{
  const PhotoCamera& camera = *views_[landmark.view].camera;
  const double mm_per_pixel = millimetresPerPixel (landmark.view, state);
  const Eigen::Vector3d point = posed.col (landmark.vertex);
  const Eigen::Vector2d residual = camera.project (point) - landmark.pixel;
  rows.push_back (pointRow (landmark.vertex, point, camera.jacobian (point), residual,
                            landmark.weight * mm_per_pixel * mm_per_pixel));
  sums.kinds.push_back (PhotoRowKind::landmark);
  sums.landmark += residual.squaredNorm () * mm_per_pixel * mm_per_pixel;
  ++sums.landmark_count;
}

int
MultiViewProblem::addOutlineRows (size_t view, const ViewOutline& outline, const Eigen::Matrix3Xd& posed,
                                  const PoseShapeState& state, std::vector<PoseShapeRow>* rows, RowSums& sums) const
{
  const ViewData& data = views_[view];
  const PhotoCamera& camera = *data.camera;
  const double mm_per_pixel = millimetresPerPixel (view, state), weight = mm_per_pixel * mm_per_pixel;
  int matched = 0;
  for (Eigen::Index k = 0; k < outline.pixels.cols (); ++k) {
    const Eigen::Vector2d pixel = outline.pixels.col (k);
    const Polyline2d::Projection closest = data.outline->project (pixel);
    const double distance = (closest.point - pixel).norm () * mm_per_pixel;
    if (!(distance <= settings_.max_distance) || (distance > kEndSlack && data.outline->isEnd (closest.point)) ||
        hiddenFromOutline (outline.pixels, k, closest.point))
      continue; // too far, beyond the end of an outline that shows part of the head, or not on the outline
    ++matched;
    if (!rows)
      continue;
    const int vertex = outline.vertices[static_cast<size_t> (k)];
    const Eigen::Vector3d point = posed.col (vertex);
    const Eigen::Matrix<double, 2, 3> J = camera.jacobian (point);
    const Eigen::Vector2d residual = pixel - closest.point;
    if (data.two_sided[static_cast<size_t> (closest.segment + (closest.along < 0.5 ? 0 : 1))]) {
      rows->push_back (pointRow (vertex, point, J, residual, weight));
      sums.kinds.push_back (PhotoRowKind::outline);
      sums.outline += distance * distance;
      ++sums.outline_count;
    }
    else if (const double outside = residual.dot (data.outline->outwardNormal (closest.segment)); outside > 0.0) {
      rows->push_back (lineRow (vertex, point, J, data.outline->outwardNormal (closest.segment), outside, weight));
      sums.kinds.push_back (PhotoRowKind::outline);
      sums.outline += outside * outside * weight;
      ++sums.outline_count;
    }
    else
      ++sums.inside;
    if (outline.side && !camera.isPerspective () && settings_.sagittal_weight > 0.0) {
      rows->push_back (sagittalRow (vertex, point, camera, state));
      sums.kinds.push_back (PhotoRowKind::depth);
    }
  }
  return matched;
}

PoseShapeRow
MultiViewProblem::sagittalRow (int vertex, const Eigen::Vector3d& point, const PhotoCamera& camera,
                               const PoseShapeState& state) const
{
  // The profile line lies in the plane through the world origin (the nose tip of the orthographic pair) facing the
  // camera: docs/method.md, "Profile fit".
  const Eigen::Vector3d axis = camera.rotation ().row (2).transpose ();
  const double s2 = state.scale () * state.scale ();
  return {vertex, point - axis * axis.dot (point), settings_.sagittal_weight / s2 * axis * axis.transpose ()};
}

void
MultiViewProblem::addOutlineLandmarkRows (size_t view, const TriangleMesh& posed, const PoseShapeState& state,
                                          std::vector<PoseShapeRow>& rows, RowSums& sums) const
{
  const ViewData& data = views_[view];
  const PhotoCamera& camera = *data.camera;
  const detail::ProjectedModel projected = detail::projectModel (posed, camera);
  const double mm_per_pixel = millimetresPerPixel (view, state);
  const double weight = settings_.outline_landmark_weight * mm_per_pixel * mm_per_pixel;
  for (const OutlineLandmark& landmark : data.outline_landmarks) {
    int best = -1;
    double best_distance = std::numeric_limits<double>::infinity ();
    for (const int v : landmark.nearby)
      if (detail::onContourGenerator (topology_, projected.facing, v) &&
          (projected.pixels.col (v) - landmark.pixel).squaredNorm () < best_distance) {
        best = v;
        best_distance = (projected.pixels.col (v) - landmark.pixel).squaredNorm ();
      }
    if (best < 0)
      continue; // the surface near the landmark does not turn away from this camera
    const Eigen::Vector3d point = posed.vertices.col (best);
    const Eigen::Matrix<double, 2, 3> J = camera.jacobian (point);
    const Eigen::Vector2d outward = (J * projected.normals.col (best)).normalized ();
    const double along = outward.dot (projected.pixels.col (best) - landmark.pixel);
    if (!landmark.two_sided && along <= 0.0)
      continue; // inside the mark of a contour that may lie outside the head (hair)
    rows.push_back (lineRow (best, point, J, outward, along, weight));
    sums.kinds.push_back (PhotoRowKind::outline_landmark);
    sums.outline_landmark += along * along * mm_per_pixel * mm_per_pixel;
    ++sums.outline_landmark_count;
  }
}

double
MultiViewProblem::landmarkError (const PoseShapeState& state, const std::vector<bool>& which) const
{
  const Eigen::Matrix3Xd posed = state.posed ();
  double sum = 0.0;
  int count = 0;
  for (size_t l = 0; l < landmarks_.size (); ++l)
    if (which[l]) {
      const Landmark& landmark = landmarks_[l];
      const double mm_per_pixel = millimetresPerPixel (landmark.view, state);
      sum += (views_[landmark.view].camera->project (posed.col (landmark.vertex)) - landmark.pixel).squaredNorm () *
             mm_per_pixel * mm_per_pixel;
      ++count;
    }
  return count > 0 ? std::sqrt (sum / count) : 0.0;
}

std::vector<int>
MultiViewProblem::profileLineMatches (const PoseShapeState& state) const
{
  const TriangleMesh posed{state.posed (), model_->triangles ()};
  std::vector<int> matches;
  for (size_t v = 0; v < views_.size (); ++v) {
    const ViewOutline outline =
        views_[v].outline ? outlineCandidates (v, posed, state) : ViewOutline{{}, Eigen::Matrix2Xd (), false};
    RowSums sums;
    matches.push_back (outline.side ? addOutlineRows (v, outline, posed.vertices, state, nullptr, sums) : -1);
  }
  return matches;
}
} // namespace morphreg

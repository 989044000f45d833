// SPDX-License-Identifier: BSD-3-Clause
// Where a traced outline is the face's (two-sided rows) and where it is hair, ears or neck (one-sided rows): the
// face zone of the model, the user's hairline mark, and the fit itself (the outline leaves the fitted model).
#include <morphreg/photo/multi_view_problem.h>

#include <cmath>
#include <limits>

namespace morphreg
{
namespace
{
/** For each point of \a points, the candidate pixel nearest to it (index into \a pixels) and its distance. */
std::vector<std::pair<Eigen::Index, double>>
nearestCandidates (const Eigen::Matrix2Xd& points, const Eigen::Matrix2Xd& pixels)
{
  std::vector<std::pair<Eigen::Index, double>> nearest (static_cast<size_t> (points.cols ()),
                                                        {-1, std::numeric_limits<double>::infinity ()});
  for (Eigen::Index k = 0; k < points.cols () && pixels.cols () > 0; ++k) {
    Eigen::Index j = 0;
    const double squared = (pixels.colwise () - points.col (k)).colwise ().squaredNorm ().minCoeff (&j);
    nearest[static_cast<size_t> (k)] = {j, std::sqrt (squared)};
  }
  return nearest;
}
} // namespace

void
MultiViewProblem::resetOutlineLabels (const PoseShapeState& state)
{
  const TriangleMesh posed{state.posed (), model_->triangles ()};
  for (size_t v = 0; v < views_.size (); ++v) {
    ViewData& data = views_[v];
    if (!data.outline)
      continue;
    const ViewOutline candidates = outlineCandidates (v, posed, state);
    const double mm_per_pixel = millimetresPerPixel (v, state);
    const auto nearest = nearestCandidates (data.outline->points (), candidates.pixels);
    for (size_t k = 0; k < nearest.size (); ++k)
      data.two_sided[k] = nearest[k].first >= 0 && nearest[k].second * mm_per_pixel <= settings_.max_distance &&
                          face_zone_[static_cast<size_t> (candidates.vertices[static_cast<size_t> (nearest[k].first)])];
    if (data.hairline >= 0)
      for (size_t k = 0; k < data.two_sided.size (); ++k)
        data.two_sided[k] = data.two_sided[k] && !beyondHairline (data, static_cast<Eigen::Index> (k));
  }
}

bool
MultiViewProblem::beyondHairline (const ViewData& data, Eigen::Index k) const
{
  if (data.hairline < 0)
    return false;
  // The hair lies on the side of the mark that holds the outline's topmost point (the crown).
  Eigen::Index top = 0;
  data.outline->points ().row (1).minCoeff (&top);
  return top > data.hairline ? k > data.hairline : k < data.hairline;
}

bool
MultiViewProblem::extendFaceLabels (const PoseShapeState& state)
{
  const TriangleMesh posed{state.posed (), model_->triangles ()};
  bool changed = false;
  for (size_t v = 0; v < views_.size (); ++v) {
    ViewData& data = views_[v];
    if (!data.outline)
      continue;
    const std::vector<double> gaps = outlineGaps (v, posed, state);
    std::vector<double> along (gaps.size (), 0.0); // outline length from its start, model mm
    for (size_t k = 1; k < gaps.size (); ++k)
      along[k] = along[k - 1] + (data.outline->points ().col (static_cast<Eigen::Index> (k)) -
                                 data.outline->points ().col (static_cast<Eigen::Index> (k) - 1))
                                        .norm () *
                                    millimetresPerPixel (v, state);
    // The face goes on along the outline from the face zone until the outline leaves the skull (hairStarts, at two
    // points in a row), at the user's mark, or where the model's outline is far.
    const auto count = static_cast<Eigen::Index> (gaps.size ());
    for (const int direction : {1, -1})
      for (Eigen::Index k = direction > 0 ? 1 : count - 2; k >= 0 && k < count; k += direction) {
        const Eigen::Index next = k + direction;
        const bool hair = hairStarts (gaps, along, k, direction) &&
                          (next < 0 || next >= count || hairStarts (gaps, along, next, direction));
        if (data.two_sided[k - direction] && !data.two_sided[k] && !hair && !beyondHairline (data, k)) {
          data.two_sided[k] = 1;
          changed = true;
        }
      }
  }
  return changed;
}

bool
MultiViewProblem::hairStarts (const std::vector<double>& gaps, const std::vector<double>& along, Eigen::Index k,
                              int direction)
{
  if (!std::isfinite (gaps[k]) || gaps[k] > kHairMax)
    return true;
  // The lowest gap over the last kHairRise mm of outline walked: a skull larger than the fitted model makes the gap
  // grow slowly, hair makes it jump.
  double lowest = gaps[k];
  for (Eigen::Index j = k - direction;
       j >= 0 && j < static_cast<Eigen::Index> (gaps.size ()) && std::abs (along[k] - along[j]) <= kHairRise;
       j -= direction)
    lowest = std::min (lowest, gaps[j]);
  return gaps[k] > kHairGap && gaps[k] - lowest > kHairStep;
}

std::vector<double>
MultiViewProblem::outlineGaps (size_t view, const TriangleMesh& posed, const PoseShapeState& state) const
{
  const ViewData& data = views_[view];
  const ViewOutline candidates = outlineCandidates (view, posed, state);
  const double mm_per_pixel = millimetresPerPixel (view, state);
  const Eigen::Matrix2Xd& points = data.outline->points ();
  const auto nearest = nearestCandidates (points, candidates.pixels);
  std::vector<double> gaps (nearest.size (), std::numeric_limits<double>::infinity ());
  for (size_t k = 0; k < nearest.size (); ++k) {
    if (nearest[k].first < 0 || nearest[k].second * mm_per_pixel > settings_.max_distance)
      continue;
    const auto segment = std::min<Eigen::Index> (static_cast<Eigen::Index> (k), points.cols () - 2);
    const Eigen::Vector2d offset =
        points.col (static_cast<Eigen::Index> (k)) - candidates.pixels.col (nearest[k].first);
    gaps[k] = data.outline->outwardNormal (segment).dot (offset) * mm_per_pixel;
  }
  return gaps;
}
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/registration/target_surface.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace morphreg
{
namespace
{
/** Whether the largest angular gap between \a neighbours around \a centre, in the plane of \a normal, exceeds 90
 *  degrees. */
bool
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

double
median (std::vector<double> values)
{
  std::nth_element (values.begin (), values.begin () + values.size () / 2, values.end ());
  return values[values.size () / 2];
}

/** The noise of \a points over their neighbourhoods' radius (see kNoisyTargetRatio): the median over up to 500
 *  points, spread evenly through the target's order, of each one's plane residual over its neighbourhood's radius. */
double
measureNoiseRatio (const Eigen::Matrix3Xd& points, const TargetSurface::NeighbourSearch& search, int neighbours)
{
  const Eigen::Index n = points.cols ();
  const int k = std::min<int> (neighbours, static_cast<int> (n));
  if (n < 4)
    return 0.0;
  const Eigen::Index step = std::max<Eigen::Index> (1, n / 500);
  std::vector<double> ratios;
  pcl::Indices indices;
  std::vector<float> squared;
  for (Eigen::Index i = 0; i < n; i += step) {
    search (static_cast<pcl::index_t> (i), k, indices, squared);
    Eigen::Matrix3Xd neighbourhood (3, indices.size ());
    for (size_t j = 0; j < indices.size (); ++j)
      neighbourhood.col (static_cast<Eigen::Index> (j)) = points.col (indices[j]);
    const PointPlane plane = fitPlane (neighbourhood);
    const double radius = squared.empty () ? 0.0 : std::sqrt (squared.back ());
    if (!plane.normal.allFinite () || !(radius > 0.0))
      continue;
    const double residual = std::sqrt (
        (plane.normal.transpose () * (neighbourhood.colwise () - plane.centroid)).squaredNorm () / indices.size ());
    ratios.push_back (residual / radius);
  }
  return ratios.empty () ? 0.0 : median (ratios);
}
} // namespace

void
TargetSurface::setInputTarget (Eigen::Matrix3Xd points, Eigen::Matrix3Xd normals, NeighbourSearch search)
{
  if (normals.cols () != 0 && normals.cols () != points.cols ())
    throw InvalidInputError ("TargetSurface: " + std::to_string (normals.cols ()) + " normals for " +
                             std::to_string (points.cols ()) + " points");
  raw_points_ = std::move (points);
  given_normals_ = std::move (normals);
  search_ = std::move (search);
  centroid_ = raw_points_.cols () ? Eigen::Vector3d (raw_points_.rowwise ().mean ()) : Eigen::Vector3d::Zero ();
  turnGivenNormalsOutwards ();
  reset ();
}

void
TargetSurface::setViewpoint (std::optional<Eigen::Vector3d> viewpoint)
{
  viewpoint_ = viewpoint;
  reset ();
}

void
TargetSurface::turnGivenNormalsOutwards ()
{
  Eigen::Index inwards = 0, outwards = 0;
  for (Eigen::Index i = 0; i < given_normals_.cols (); ++i) {
    const double side = given_normals_.col (i).dot (raw_points_.col (i) - centroid_);
    inwards += side < 0.0 ? 1 : 0;
    outwards += side > 0.0 ? 1 : 0;
  }
  if (inwards > outwards)
    given_normals_ = -given_normals_;
}

void
TargetSurface::setNeighbours (int k)
{
  if (k < 4)
    throw InvalidInputError ("TargetSurface::setNeighbours: at least 4 neighbours are needed, got " +
                             std::to_string (k));
  if (k != neighbours_)
    reset ();
  neighbours_ = k;
}

void
TargetSurface::setSmoothing (TargetSmoothing smoothing)
{
  if (smoothing != mode_)
    reset ();
  mode_ = smoothing;
}

bool
TargetSurface::getSmoothing ()
{
  decideSmoothing ();
  return smoothing_;
}

void
TargetSurface::decideSmoothing ()
{
  if (decided_)
    return;
  decided_ = true;
  smoothing_ = mode_ == TargetSmoothing::on;
  if (mode_ != TargetSmoothing::automatic || !search_)
    return;
  noise_ratio_ = measureNoiseRatio (raw_points_, search_, neighbours_);
  smoothing_ = noise_ratio_ > kNoisyTargetRatio;
}

void
TargetSurface::reset ()
{
  decided_ = false;
  const Eigen::Index n = raw_points_.cols ();
  points_.resize (3, n);
  normals_.setZero (3, n);
  has_normal_.assign (static_cast<size_t> (n), 0);
  boundary_.assign (static_cast<size_t> (n), 0);
  ready_.assign (static_cast<size_t> (n), 0);
}

void
TargetSurface::compute (const pcl::Correspondences& correspondences)
{
  if (!search_)
    throw InvalidInputError ("TargetSurface: no target (call setInputTarget)");
  decideSmoothing ();
  std::vector<pcl::index_t> pending;
  for (const pcl::Correspondence& c : correspondences)
    if (!ready_[static_cast<size_t> (c.index_match)]) {
      ready_[static_cast<size_t> (c.index_match)] = 1;
      pending.push_back (c.index_match);
    }
  const auto count = static_cast<long> (pending.size ());
  // After the first iterations only a few points are new: not worth waking the other threads for.
#pragma omp parallel for schedule(dynamic, 64) if (count > 256)
  for (long c = 0; c < count; ++c)
    computePoint (pending[static_cast<size_t> (c)]);
}

void
TargetSurface::compute (pcl::Correspondences& correspondences, const Eigen::Matrix3Xd& source)
{
  compute (static_cast<const pcl::Correspondences&> (correspondences));
  for (pcl::Correspondence& c : correspondences)
    c.distance = static_cast<float> ((points_.col (c.index_match) - source.col (c.index_query)).squaredNorm ());
}

void
TargetSurface::computePoint (pcl::index_t i)
{
  pcl::Indices neighbours;
  std::vector<float> distances;
  search_ (i, std::min<int> (neighbours_, static_cast<int> (raw_points_.cols ())), neighbours, distances);
  Eigen::Matrix3Xd points (3, neighbours.size ());
  for (size_t j = 0; j < neighbours.size (); ++j)
    points.col (static_cast<Eigen::Index> (j)) = raw_points_.col (neighbours[j]);
  const PointPlane plane = fitPlane (points);
  const Eigen::Vector3d point = raw_points_.col (i);
  points_.col (i) = smoothing_ && plane.normal.allFinite ()
                        ? Eigen::Vector3d (point - plane.normal * plane.normal.dot (point - plane.centroid))
                        : point;
  Eigen::Vector3d normal = given_normals_.cols () ? Eigen::Vector3d (given_normals_.col (i)) : Eigen::Vector3d::Zero ();
  if (!normal.allFinite () || normal.norm () < 1e-6) {
    normal = plane.normal;
    const Eigen::Vector3d outwards =
        viewpoint_ ? Eigen::Vector3d (*viewpoint_ - point) : Eigen::Vector3d (point - centroid_);
    if (normal.dot (outwards) < 0.0)
      normal = -normal;
  }
  normal.normalize ();
  normals_.col (i) = normal;
  const bool has_normal = normal.allFinite ();
  boundary_[static_cast<size_t> (i)] = !has_normal || isBoundaryPoint (point, normal, points);
  has_normal_[static_cast<size_t> (i)] = has_normal;
}
} // namespace morphreg

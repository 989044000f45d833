// SPDX-License-Identifier: BSD-3-Clause
#include "point_grid.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

namespace morphreg
{
namespace detail
{
namespace
{
constexpr double kMaxCells = 4.0e6;  ///< the grid's cell count stays below this (16 MB of cell offsets)
constexpr double kFarCells = 1.0e6;  ///< cell coordinates are clamped to +-this before conversion to int
constexpr double kStrayShare = 1e-3; ///< per axis, this share of the points at either end may lie beyond the grid

/** A candidate as one integer that sorts by distance: the squared distance's float bits (non-negative floats order
 *  as their bit patterns) above the point's position in the grid's order. */
std::uint64_t
candidate (float distance, int position)
{
  std::uint32_t bits;
  std::memcpy (&bits, &distance, sizeof bits);
  return (std::uint64_t (bits) << 32) | std::uint32_t (position);
}

double
squaredDistance (std::uint64_t candidate)
{
  const auto bits = static_cast<std::uint32_t> (candidate >> 32);
  float distance;
  std::memcpy (&distance, &bits, sizeof distance);
  return distance;
}

/** The cells per axis of a grid of \a cell mm over \a extent. */
Eigen::Array3d
cellCounts (const Eigen::Vector3d& extent, double cell)
{
  return (extent.array () / cell).floor () + 1.0;
}

/** The value below which a \a fraction of \a values lie (the smallest for fraction 0). */
double
quantile (const Eigen::RowVectorXd& values, double fraction)
{
  std::vector<double> sorted (values.data (), values.data () + values.size ());
  const auto at = static_cast<std::ptrdiff_t> (fraction * static_cast<double> (sorted.size () - 1));
  std::nth_element (sorted.begin (), sorted.begin () + at, sorted.end ());
  return sorted[static_cast<std::size_t> (at)];
}
} // namespace

PointGrid::PointGrid (const Eigen::Matrix3Xd& points, double cell_size)
{
  // The grid spans the points but their outermost thousandth per axis: far strays (a laser's hit on a wall) would
  // stretch the cells over the whole scan. The strays fall into the border cells, which reach out without limit.
  Eigen::Vector3d low, high;
  for (int a = 0; a < 3; ++a) {
    low[a] = quantile (points.row (a), kStrayShare);
    high[a] = quantile (points.row (a), 1.0 - kStrayShare);
  }
  const Eigen::Vector3d extent = high - low;
  cell_size_ = cell_size > 0.0 && std::isfinite (cell_size) ? cell_size : std::max (extent.maxCoeff (), 1.0) / 64.0;
  for (Eigen::Array3d counts = cellCounts (extent, cell_size_); counts.prod () > kMaxCells;
       counts = cellCounts (extent, cell_size_))
    cell_size_ *= 1.01 * std::cbrt (counts.prod () / kMaxCells);
  origin_ = low;
  dims_ = cellCounts (extent, cell_size_).cast<int> ();

  std::vector<int> cell_of (static_cast<std::size_t> (points.cols ()));
  cell_start_.assign (static_cast<std::size_t> (dims_.prod ()) + 1, 0);
  for (Eigen::Index i = 0; i < points.cols (); ++i) {
    const Eigen::Array3i c = cellOf (points.col (i).array ());
    cell_of[i] = (c.z () * dims_.y () + c.y ()) * dims_.x () + c.x ();
    ++cell_start_[cell_of[i] + 1];
  }
  for (std::size_t c = 1; c < cell_start_.size (); ++c)
    cell_start_[c] += cell_start_[c - 1];
  std::vector<int> fill (cell_start_.begin (), cell_start_.end () - 1);
  order_.resize (cell_of.size ());
  for (std::size_t i = 0; i < cell_of.size (); ++i)
    order_[fill[cell_of[i]]++] = static_cast<int> (i);
  sorted_.resize (3, points.cols ());
  for (std::size_t k = 0; k < order_.size (); ++k)
    sorted_.col (k) = points.col (order_[k]).cast<float> ();
}

double
PointGrid::nearestK (const Eigen::Vector3d& query, int k, double max_radius, std::vector<int>& indices,
                     std::vector<double>& squared) const
{
  thread_local std::vector<std::uint64_t> candidates;
  for (double radius = std::min (2.0 * cell_size_, max_radius);;) {
    const Eigen::Array3i lo = cellOf (query.array () - radius), hi = cellOf (query.array () + radius);
    candidates.clear ();
    gather (lo, hi, query, candidates);
    const int found = std::min (k, static_cast<int> (candidates.size ()));
    if (found > 0)
      std::nth_element (candidates.begin (), candidates.begin () + (found - 1), candidates.end ());
    const double kth = found > 0 ? squaredDistance (candidates[found - 1]) : std::numeric_limits<double>::infinity ();
    const double covered = coveredRadius (lo, hi, query); // every point nearer than this is a candidate
    if (found == k && kth <= covered * covered) {
      indices.resize (found);
      squared.resize (found);
      for (int j = 0; j < found; ++j) {
        squared[j] = squaredDistance (candidates[j]);
        indices[j] = order_[candidates[j] & 0xffffffffu];
      }
      return kth;
    }
    if (covered >= max_radius || radius >= max_radius) {
      indices.clear ();
      squared.clear ();
      return std::numeric_limits<double>::infinity ();
    }
    // k found: the k nearest lie within the k-th found; else the cube doubles
    radius = std::min (std::max (found == k ? std::sqrt (kth) : 2.0 * radius, 1.001 * radius), max_radius);
  }
}

Eigen::Array3i
PointGrid::cellOf (const Eigen::Array3d& point) const
{
  return ((point - origin_.array ()) / cell_size_)
      .floor ()
      .max (-kFarCells)
      .min (kFarCells)
      .cast<int> ()
      .max (0)
      .min (dims_ - 1);
}

void
PointGrid::gather (const Eigen::Array3i& lo, const Eigen::Array3i& hi, const Eigen::Vector3d& query,
                   std::vector<std::uint64_t>& candidates) const
{
  const Eigen::Vector3f at = query.cast<float> ();
  for (int z = lo.z (); z <= hi.z (); ++z)
    for (int y = lo.y (); y <= hi.y (); ++y) {
      const int row = (z * dims_.y () + y) * dims_.x ();
      // the cells lo.x .. hi.x of one row are adjacent, so are their points
      for (int p = cell_start_[row + lo.x ()]; p < cell_start_[row + hi.x () + 1]; ++p)
        candidates.push_back (candidate ((sorted_.col (p) - at).squaredNorm (), p));
    }
}

double
PointGrid::coveredRadius (const Eigen::Array3i& lo, const Eigen::Array3i& hi, const Eigen::Vector3d& query) const
{
  double radius = std::numeric_limits<double>::infinity ();
  for (int a = 0; a < 3; ++a) {
    if (lo[a] > 0)
      radius = std::min (radius, query[a] - (origin_[a] + lo[a] * cell_size_));
    if (hi[a] < dims_[a] - 1)
      radius = std::min (radius, origin_[a] + (hi[a] + 1) * cell_size_ - query[a]);
  }
  return std::max (radius, 0.0);
}
} // namespace detail
} // namespace morphreg

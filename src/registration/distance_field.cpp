// SPDX-License-Identifier: BSD-3-Clause
#include "distance_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace morphreg
{
namespace detail
{
namespace
{
/** The 1D squared distance transform of the sampled function \a f into \a d. */
void
transform1d (const std::vector<double>& f, std::vector<double>& d)
{
  const int n = static_cast<int> (f.size ());
  std::vector<int> v (n);
  std::vector<double> z (n + 1);
  int k = 0;
  v[0] = 0;
  z[0] = -std::numeric_limits<double>::infinity ();
  z[1] = std::numeric_limits<double>::infinity ();
  for (int q = 1; q < n; ++q) {
    double s;
    while (true) {
      s = ((f[q] + q * q) - (f[v[k]] + v[k] * v[k])) / (2.0 * q - 2.0 * v[k]);
      if (s > z[k] || k == 0)
        break;
      --k;
    }
    if (s <= z[k]) { // k == 0 and the new parabola is lower everywhere
      v[0] = q;
      z[1] = std::numeric_limits<double>::infinity ();
      continue;
    }
    ++k;
    v[k] = q;
    z[k] = s;
    z[k + 1] = std::numeric_limits<double>::infinity ();
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[k + 1] < q)
      ++k;
    d[q] = (q - v[k]) * (q - v[k]) + f[v[k]];
  }
}

} // namespace

Eigen::Vector3d
Grid::centre (Eigen::Index index) const
{
  const Eigen::Index x = index % size[0], y = (index / size[0]) % size[1], z = index / (size[0] * size[1]);
  return origin + cell * (Eigen::Vector3d (static_cast<double> (x), static_cast<double> (y), static_cast<double> (z)) +
                          Eigen::Vector3d::Constant (0.5));
}

Grid
gridOver (const Eigen::Vector3d& low, const Eigen::Vector3d& high, double cell)
{
  const double edge = std::max (cell, (high - low).maxCoeff () / 128.0);
  const Eigen::Array3i size = ((high - low).array () / edge).ceil ().cast<int> ().max (1);
  return {low, edge, size};
}

Grid
gridAround (const Eigen::Matrix3Xd& points, double margin, double cell)
{
  const Eigen::Vector3d widen = Eigen::Vector3d::Constant (margin);
  return gridOver (points.rowwise ().minCoeff () - widen, points.rowwise ().maxCoeff () + widen, cell);
}

DistanceField::DistanceField (const Grid& grid, const Eigen::Matrix3Xd& seeds, double truncation)
  : grid_ (grid), truncation_ (static_cast<float> (truncation))
{
  const double infinity = 1e20;
  std::vector<double> squared (grid_.count (), infinity);
  for (Eigen::Index i = 0; i < seeds.cols (); ++i) {
    const Eigen::Index c = grid_.index (seeds.col (i));
    if (c >= 0)
      squared[c] = 0.0;
  }
  const Eigen::Index strides[3] = {1, grid_.size[0], static_cast<Eigen::Index> (grid_.size[0]) * grid_.size[1]};
  for (int axis = 0; axis < 3; ++axis) {
    const int length = grid_.size[axis];
    const Eigen::Index lines = grid_.count () / length;
#pragma omp parallel for schedule(static)
    for (Eigen::Index line = 0; line < lines; ++line) {
      // The first cell of this line: all coordinates but \a axis from \a line.
      const Eigen::Index below = line % strides[axis], above = line / strides[axis];
      const Eigen::Index first = below + above * strides[axis] * length;
      std::vector<double> f (length), d (length);
      for (int q = 0; q < length; ++q)
        f[q] = squared[first + q * strides[axis]];
      transform1d (f, d);
      for (int q = 0; q < length; ++q)
        squared[first + q * strides[axis]] = d[q];
    }
  }
  distances_.resize (grid_.count ());
  for (Eigen::Index i = 0; i < grid_.count (); ++i)
    distances_[i] = std::min (truncation_, static_cast<float> (std::sqrt (squared[i]) * grid_.cell));
}

} // namespace detail
} // namespace morphreg

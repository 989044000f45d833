// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private to the library: a dense voxel grid and the truncated distance transform on it that the global start
// (global_alignment.cpp) scores its rotations with, once for the scan and once for the model.
#include <Eigen/Core>

#include <vector>

namespace morphreg
{
namespace detail
{
/** A dense 3D grid of cells of edge \a cell from \a origin. */
struct Grid
{
  Eigen::Vector3d origin;
  double cell;
  Eigen::Array3i size;

  /** The number of cells. */
  Eigen::Index
  count () const
  {
    return static_cast<Eigen::Index> (size[0]) * size[1] * size[2];
  }

  /** The cell holding \a p, or -1 outside the grid. */
  Eigen::Index
  index (const Eigen::Vector3d& p) const
  {
    const Eigen::Array3d f = (p - origin).array () / cell;
    if ((f < 0.0).any () || (f >= size.cast<double> ()).any ())
      return -1;
    const Eigen::Array3i i = f.cast<int> ();
    return (static_cast<Eigen::Index> (i[2]) * size[1] + i[1]) * size[0] + i[0];
  }

  /** The centre of the cell \a index. */
  Eigen::Vector3d
  centre (Eigen::Index index) const;
};

/** A grid of edge at least \a cell over the box [low, high], with at most about 128 cells along its longest side. */
Grid
gridOver (const Eigen::Vector3d& low, const Eigen::Vector3d& high, double cell);

/** A grid of edge at least \a cell over the bounding box of \a points widened by \a margin on every side. */
Grid
gridAround (const Eigen::Matrix3Xd& points, double margin, double cell);

/** Truncated distances to the nearest of some seed points, on a grid (exact squared Euclidean distance
 *  transform, Felzenszwalb and Huttenlocher's lower envelope of parabolas, one axis at a time). */
class DistanceField
{
public:
  /** The field of \a seeds (3 x N; those outside \a grid are ignored) on \a grid, truncated at \a truncation. */
  DistanceField (const Grid& grid, const Eigen::Matrix3Xd& seeds, double truncation);

  /** The truncated distance at \a p (the truncation outside the grid). */
  float
  at (const Eigen::Vector3d& p) const
  {
    const Eigen::Index c = grid_.index (p);
    return c < 0 ? truncation_ : distances_[c];
  }

private:
  Grid grid_;
  float truncation_;
  std::vector<float> distances_;
};

} // namespace detail
} // namespace morphreg

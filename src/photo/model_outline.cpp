// SPDX-License-Identifier: BSD-3-Clause
#include "model_outline.h"

#include <morphreg/mesh/mesh_normals.h>

#include <algorithm>
#include <cmath>

namespace morphreg
{
namespace detail
{
namespace
{
/** A coverage grid of the projection in cells of a fixed pixel size. */
class CoverageGrid
{
public:
  CoverageGrid (const Eigen::Matrix2Xd& pixels, double cell) : cell_ (cell)
  {
    origin_ = pixels.rowwise ().minCoeff ().array () - 2.0 * cell;
    const Eigen::Vector2d span = pixels.rowwise ().maxCoeff () - origin_;
    width_ = static_cast<int> (std::ceil (span.x () / cell)) + 3;
    height_ = static_cast<int> (std::ceil (span.y () / cell)) + 3;
    filled_.assign (static_cast<size_t> (width_) * static_cast<size_t> (height_), 0);
  }

  Eigen::Vector2i
  cellOf (const Eigen::Vector2d& pixel) const
  {
    return ((pixel - origin_) / cell_).array ().floor ().cast<int> ();
  }

  bool
  filled (int x, int y) const
  {
    return x >= 0 && y >= 0 && x < width_ && y < height_ && filled_[static_cast<size_t> (y) * width_ + x];
  }

  /** Marks the cells whose centres \a a, \a b, \a c cover (with half a cell of slack), and their corners' cells. */
  void
  fill (const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c)
  {
    const Eigen::Vector2i low = cellOf (a.cwiseMin (b).cwiseMin (c)), high = cellOf (a.cwiseMax (b).cwiseMax (c));
    const double area = (b - a).x () * (c - a).y () - (b - a).y () * (c - a).x ();
    for (int y = low.y (); y <= high.y (); ++y)
      for (int x = low.x (); x <= high.x (); ++x) {
        const Eigen::Vector2d q = origin_ + cell_ * Eigen::Vector2d (x + 0.5, y + 0.5);
        bool inside = true;
        for (const auto& [p, r] : {std::pair (a, b), std::pair (b, c), std::pair (c, a)}) {
          const double cross = (r - p).x () * (q - p).y () - (r - p).y () * (q - p).x ();
          inside = inside && (area >= 0.0 ? cross : -cross) >= -0.5 * cell_ * (r - p).norm ();
        }
        if (inside)
          set (x, y);
      }
    for (const Eigen::Vector2d& corner : {a, b, c})
      set (cellOf (corner).x (), cellOf (corner).y ());
  }

  /** Whether a filled cell within one cell of \a pixel's has an empty neighbour. */
  bool
  nearBoundary (const Eigen::Vector2d& pixel) const
  {
    const Eigen::Vector2i at = cellOf (pixel);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (filled (at.x () + dx, at.y () + dy) && hasEmptyNeighbour (at.x () + dx, at.y () + dy))
          return true;
    return false;
  }

private:
  void
  set (int x, int y)
  {
    if (x >= 0 && y >= 0 && x < width_ && y < height_)
      filled_[static_cast<size_t> (y) * width_ + x] = 1;
  }

  bool
  hasEmptyNeighbour (int x, int y) const
  {
    return !filled (x - 1, y) || !filled (x + 1, y) || !filled (x, y - 1) || !filled (x, y + 1);
  }

  double cell_;
  Eigen::Vector2d origin_;
  int width_ = 0, height_ = 0;
  std::vector<unsigned char> filled_;
};
} // namespace

ProjectedModel
projectModel (const TriangleMesh& mesh, const PhotoCamera& camera)
{
  ProjectedModel projected{Eigen::Matrix2Xd (2, mesh.numVertices ()), Eigen::VectorXd (mesh.numVertices ()),
                           vertexNormals (mesh)};
  for (Eigen::Index i = 0; i < mesh.numVertices (); ++i) {
    const Eigen::Vector3d p = mesh.vertices.col (i);
    projected.pixels.col (i) = camera.project (p);
    projected.facing[i] = projected.normals.col (i).dot (camera.towardsCamera (p));
  }
  return projected;
}

bool
onContourGenerator (const MeshTopology& topology, const Eigen::VectorXd& facing, int v)
{
  if (!(facing[v] >= 0.0))
    return false;
  const auto [begin, end] = topology.neighbours (v);
  return std::any_of (begin, end, [&facing] (int n) { return facing[n] < 0.0; });
}

std::vector<int>
silhouetteVertices (const MeshTopology& topology, const TriangleMesh::Triangles& triangles,
                    const ProjectedModel& projected, double cell)
{
  CoverageGrid grid (projected.pixels, cell);
  for (Eigen::Index t = 0; t < triangles.cols (); ++t)
    grid.fill (projected.pixels.col (triangles (0, t)), projected.pixels.col (triangles (1, t)),
               projected.pixels.col (triangles (2, t)));
  std::vector<int> vertices;
  for (int v = 0; v < static_cast<int> (projected.pixels.cols ()); ++v)
    if (onContourGenerator (topology, projected.facing, v) && grid.nearBoundary (projected.pixels.col (v)))
      vertices.push_back (v);
  return vertices;
}
} // namespace detail
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include "hole_filling.h"

#include <morphreg/warp/thin_plate_spline.h>

#include <algorithm>

namespace morphreg
{
namespace detail
{
namespace
{
/** The most observed vertices one fill interpolates: the fit is cubic in them, and an evenly thinned border
 *  already fixes the fill's shape. */
constexpr int kMaxAnchors = 400;

/** The observed vertices of \a rings rings around \a hole, thinned evenly to at most kMaxAnchors. */
std::vector<int>
anchors (const MeshTopology& topology, const std::vector<int>& hole, const std::vector<char>& missed, int rings)
{
  const std::vector<int> ring = topology.ringIndex (hole, rings);
  std::vector<int> around;
  for (std::size_t v = 0; v < ring.size (); ++v)
    if (ring[v] > 0 && !missed[v])
      around.push_back (static_cast<int> (v));
  if (around.empty ())
    for (std::size_t v = 0; v < missed.size (); ++v)
      if (!missed[v])
        around.push_back (static_cast<int> (v));
  if (around.size () <= static_cast<std::size_t> (kMaxAnchors))
    return around;
  std::vector<int> thinned;
  const double stride = static_cast<double> (around.size ()) / kMaxAnchors;
  for (int k = 0; k < kMaxAnchors; ++k)
    thinned.push_back (around[static_cast<std::size_t> (k * stride)]);
  return thinned;
}
} // namespace

std::vector<std::vector<int>>
connectedMisses (const MeshTopology& topology, const std::vector<char>& missed)
{
  std::vector<std::vector<int>> holes;
  std::vector<char> seen (missed.size (), 0);
  for (std::size_t seed = 0; seed < missed.size (); ++seed) {
    if (!missed[seed] || seen[seed])
      continue;
    std::vector<int> hole{static_cast<int> (seed)};
    seen[seed] = 1;
    for (std::size_t next = 0; next < hole.size (); ++next) {
      const auto [begin, end] = topology.neighbours (hole[next]);
      for (const int* n = begin; n != end; ++n)
        if (missed[*n] && !seen[*n]) {
          seen[*n] = 1;
          hole.push_back (*n);
        }
    }
    holes.push_back (std::move (hole));
  }
  return holes;
}

int
fillHole (const MeshTopology& topology, const Eigen::Matrix3Xd& reference, const std::vector<int>& hole,
          const std::vector<char>& missed, int rings, double lambda, Eigen::Matrix3Xd& displacement)
{
  const std::vector<int> border = anchors (topology, hole, missed, rings);
  Eigen::Matrix3Xd source (3, border.size ()), target (3, border.size ()), inside (3, hole.size ());
  for (std::size_t k = 0; k < border.size (); ++k) {
    source.col (k) = reference.col (border[k]);
    target.col (k) = source.col (k) + displacement.col (border[k]);
  }
  for (std::size_t k = 0; k < hole.size (); ++k)
    inside.col (k) = reference.col (hole[k]);
  ThinPlateSpline<double, 3> spline;
  spline.setRegularization (lambda);
  spline.fit (source, target);
  const Eigen::Matrix3Xd moved = spline.evaluate (inside);
  for (std::size_t k = 0; k < hole.size (); ++k)
    displacement.col (hole[k]) = moved.col (k) - inside.col (k);
  return static_cast<int> (border.size ());
}
} // namespace detail
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/mesh/triangle_locator.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>

namespace morphreg
{
namespace
{
constexpr int kLeafSize = 4;

/** Barycentric weights of the point of segment (corner i, corner j) closest to \a p. */
Eigen::Vector3d
closestOnEdge (const Eigen::Vector3d& p, const Eigen::Vector3d* corners, int i, int j)
{
  const Eigen::Vector3d edge = corners[j] - corners[i];
  const double length2 = edge.squaredNorm ();
  const double s = length2 > 0.0 ? std::clamp ((p - corners[i]).dot (edge) / length2, 0.0, 1.0) : 0.0;
  Eigen::Vector3d weights = Eigen::Vector3d::Zero ();
  weights[i] = 1.0 - s;
  weights[j] = s;
  return weights;
}

Eigen::Vector3d
pointAt (const Eigen::Vector3d& weights, const Eigen::Vector3d* corners)
{
  return weights[0] * corners[0] + weights[1] * corners[1] + weights[2] * corners[2];
}

double
boxSquaredDistance (const Eigen::Vector3d& p, const Eigen::Vector3d& low, const Eigen::Vector3d& high)
{
  return (low - p).cwiseMax (p - high).cwiseMax (0.0).squaredNorm ();
}
} // namespace

Eigen::Vector3d
closestPointOnTriangle (const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        const Eigen::Vector3d& c)
{
  // Voronoi regions of the corners, then of the edges, then the face (signed areas from dot products).
  const Eigen::Vector3d ab = b - a, ac = c - a;
  const double d1 = ab.dot (p - a), d2 = ac.dot (p - a);
  if (d1 <= 0.0 && d2 <= 0.0)
    return {1.0, 0.0, 0.0};
  const double d3 = ab.dot (p - b), d4 = ac.dot (p - b);
  if (d3 >= 0.0 && d4 <= d3)
    return {0.0, 1.0, 0.0};
  const double d5 = ab.dot (p - c), d6 = ac.dot (p - c);
  if (d6 >= 0.0 && d5 <= d6)
    return {0.0, 0.0, 1.0};
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 / (d1 - d3);
    return {1.0 - v, v, 0.0};
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 / (d2 - d6);
    return {1.0 - w, 0.0, w};
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return {0.0, 1.0 - w, w};
  }
  const double sum = va + vb + vc;
  if (sum > 0.0 && std::isfinite (sum))
    return {va / sum, vb / sum, vc / sum};
  // Degenerate (flat) triangle: the nearest of its edges.
  const Eigen::Vector3d corners[3] = {a, b, c};
  Eigen::Vector3d best;
  double best_distance = std::numeric_limits<double>::infinity ();
  for (int k = 0; k < 3; ++k) {
    const Eigen::Vector3d weights = closestOnEdge (p, corners, k, (k + 1) % 3);
    const double distance = (pointAt (weights, corners) - p).squaredNorm ();
    if (distance < best_distance) {
      best_distance = distance;
      best = weights;
    }
  }
  return best;
}

TriangleLocator::TriangleLocator (const TriangleMesh& mesh) : mesh_ (mesh)
{
  validateMesh (mesh_, "TriangleLocator mesh");
  const Eigen::Index m = mesh_.numTriangles ();
  Eigen::Matrix3Xd centroids (3, m);
  for (Eigen::Index t = 0; t < m; ++t)
    centroids.col (t) = (mesh_.vertices.col (mesh_.triangles (0, t)) + mesh_.vertices.col (mesh_.triangles (1, t)) +
                         mesh_.vertices.col (mesh_.triangles (2, t))) /
                        3.0;
  order_.resize (static_cast<size_t> (m));
  std::iota (order_.begin (), order_.end (), 0);
  nodes_.reserve (static_cast<size_t> (2 * m / kLeafSize + 2));
  build (0, static_cast<int> (m), centroids);

  const MeshTopology topology (mesh_);
  boundary_vertices_ = topology.boundaryVertexMask ();
  boundary_edges_.assign (static_cast<size_t> (m), 0);
  std::vector<std::array<int, 2>> open = topology.boundaryEdges ();
  for (auto& edge : open)
    std::sort (edge.begin (), edge.end ());
  std::sort (open.begin (), open.end ());
  for (Eigen::Index t = 0; t < m; ++t)
    for (int k = 0; k < 3; ++k) {
      std::array<int, 2> edge{mesh_.triangles ((k + 1) % 3, t), mesh_.triangles ((k + 2) % 3, t)};
      std::sort (edge.begin (), edge.end ());
      if (std::binary_search (open.begin (), open.end (), edge))
        boundary_edges_[static_cast<size_t> (t)] |= static_cast<unsigned char> (1u << k);
    }
}

int
TriangleLocator::build (int begin, int end, const Eigen::Matrix3Xd& centroids)
{
  const int index = static_cast<int> (nodes_.size ());
  nodes_.push_back ({Eigen::Vector3d::Constant (std::numeric_limits<double>::infinity ()),
                     Eigen::Vector3d::Constant (-std::numeric_limits<double>::infinity ()), begin, end - begin, -1});
  Eigen::Vector3d centre_low = nodes_[index].low, centre_high = nodes_[index].high;
  for (int i = begin; i < end; ++i) {
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d v = mesh_.vertices.col (mesh_.triangles (k, order_[i]));
      nodes_[index].low = nodes_[index].low.cwiseMin (v);
      nodes_[index].high = nodes_[index].high.cwiseMax (v);
    }
    centre_low = centre_low.cwiseMin (centroids.col (order_[i]));
    centre_high = centre_high.cwiseMax (centroids.col (order_[i]));
  }
  if (end - begin <= kLeafSize)
    return index;
  // Median split along the longest extent of the centroids.
  Eigen::Index axis = 0;
  (centre_high - centre_low).maxCoeff (&axis);
  const int middle = begin + (end - begin) / 2;
  std::nth_element (order_.begin () + begin, order_.begin () + middle, order_.begin () + end,
                    [&] (int a, int b) { return centroids (axis, a) < centroids (axis, b); });
  const int left = build (begin, middle, centroids);
  const int right = build (middle, end, centroids);
  nodes_[index].first = left;
  nodes_[index].count = 0;
  nodes_[index].right = right;
  return index;
}

TriangleLocator::Hit
TriangleLocator::closestPoint (const Eigen::Vector3d& query) const
{
  if (!query.allFinite ())
    throw InvalidInputError ("TriangleLocator::closestPoint: the query point is not finite");
  Hit hit;
  double best = std::numeric_limits<double>::infinity ();
  std::vector<int> stack{0};
  while (!stack.empty ()) {
    const Node& node = nodes_[stack.back ()];
    stack.pop_back ();
    if (boxSquaredDistance (query, node.low, node.high) >= best)
      continue;
    if (node.count == 0) {
      // Visit the nearer child first (pushed last).
      const int left = node.first, right = node.right;
      const bool left_nearer = boxSquaredDistance (query, nodes_[left].low, nodes_[left].high) <=
                               boxSquaredDistance (query, nodes_[right].low, nodes_[right].high);
      stack.push_back (left_nearer ? right : left);
      stack.push_back (left_nearer ? left : right);
      continue;
    }
    for (int i = node.first; i < node.first + node.count; ++i) {
      const int t = order_[i];
      const Eigen::Vector3d corners[3] = {mesh_.vertices.col (mesh_.triangles (0, t)),
                                          mesh_.vertices.col (mesh_.triangles (1, t)),
                                          mesh_.vertices.col (mesh_.triangles (2, t))};
      const Eigen::Vector3d weights = closestPointOnTriangle (query, corners[0], corners[1], corners[2]);
      const Eigen::Vector3d point = pointAt (weights, corners);
      const double distance = (point - query).squaredNorm ();
      if (distance < best) {
        best = distance;
        hit.point = point;
        hit.barycentric = weights;
        hit.triangle = t;
      }
    }
  }
  hit.distance = std::sqrt (best);
  hit.on_boundary = onBoundary (hit.triangle, hit.barycentric);
  return hit;
}

bool
TriangleLocator::onBoundary (int triangle, const Eigen::Vector3d& barycentric) const
{
  int zeros = 0, zero_corner = -1, kept_corner = -1;
  for (int k = 0; k < 3; ++k) {
    if (barycentric[k] == 0.0) {
      ++zeros;
      zero_corner = k;
    }
    else
      kept_corner = k;
  }
  if (zeros == 2)
    return boundary_vertices_[static_cast<size_t> (mesh_.triangles (kept_corner, triangle))];
  return zeros == 1 && (boundary_edges_[static_cast<size_t> (triangle)] >> zero_corner & 1u) != 0;
}

} // namespace morphreg

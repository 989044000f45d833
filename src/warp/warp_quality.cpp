// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/warp/warp_quality.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace morphreg
{
namespace
{
/** Vertices with a neighbour in another segment. */
std::vector<int>
borderVertices (const MeshTopology& topology, const std::vector<int>& labels)
{
  std::vector<int> border;
  for (Eigen::Index v = 0; v < topology.numVertices (); ++v) {
    const auto [begin, end] = topology.neighbours (static_cast<int> (v));
    if (std::any_of (begin, end, [&] (int n) { return labels[n] != labels[v]; }))
      border.push_back (static_cast<int> (v));
  }
  return border;
}
} // namespace

WarpQuality
evaluateWarp (const TriangleMesh& warped, const TriangleMesh& truth, const std::vector<int>& labels, double band_width,
              const TriangleMesh* source)
{
  validateMesh (truth, "true mesh");
  validateMesh (warped, "warped mesh");
  requireSameTopology (truth, warped, "warped mesh");
  if (static_cast<Eigen::Index> (labels.size ()) != truth.numVertices ())
    throw InvalidInputError ("evaluateWarp: " + std::to_string (labels.size ()) + " labels for " +
                             std::to_string (truth.numVertices ()) + " vertices");
  WarpQuality quality;
  const Eigen::VectorXd errors = (warped.vertices - truth.vertices).colwise ().norm ();
  quality.mean_error = errors.mean ();
  quality.rms_error = std::sqrt (errors.squaredNorm () / errors.size ());
  quality.max_error = errors.maxCoeff ();

  const MeshTopology topology (truth);
  const std::vector<double> from_border =
      topology.geodesicDistances (truth.vertices, borderVertices (topology, labels), band_width);
  const auto in_band = [&] (int v) { return from_border[static_cast<std::size_t> (v)] <= band_width; };
  for (const auto& edge : topology.edges ()) {
    const double true_length = (truth.vertices.col (edge.a) - truth.vertices.col (edge.b)).norm ();
    if (true_length <= 0.0)
      continue;
    const double stretch =
        std::abs ((warped.vertices.col (edge.a) - warped.vertices.col (edge.b)).norm () / true_length - 1.0);
    if (labels[edge.a] != labels[edge.b])
      quality.seam = std::max (quality.seam, stretch);
    if (in_band (edge.a) && in_band (edge.b))
      quality.band = std::max (quality.band, stretch);
  }
  if (source != nullptr)
    requireSameTopology (truth, *source, "source mesh");
  const Eigen::VectorXd true_areas = triangleAreas (truth);
  const Eigen::VectorXd source_areas = source != nullptr ? triangleAreas (*source) : true_areas;
  const Eigen::Matrix3Xd true_normals = faceNormals (truth), warped_normals = faceNormals (warped);
  for (Eigen::Index t = 0; t < truth.numTriangles (); ++t)
    if (true_areas[t] < 0.5 * source_areas[t])
      ++quality.collapsed;
    else if (warped_normals.col (t).dot (true_normals.col (t)) < 0.0) {
      ++quality.folded;
      if (in_band (truth.triangles (0, t)) && in_band (truth.triangles (1, t)) && in_band (truth.triangles (2, t)))
        ++quality.folded_in_band;
    }
  return quality;
}

int
countFoldedTriangles (const TriangleMesh& mesh)
{
  const Eigen::Matrix3Xd normals = faceNormals (mesh);
  std::vector<std::array<int, 3>> sides; // (lower vertex, higher vertex, triangle) of every triangle side
  sides.reserve (static_cast<std::size_t> (3 * mesh.numTriangles ()));
  for (Eigen::Index t = 0; t < mesh.numTriangles (); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = mesh.triangles (k, t), b = mesh.triangles ((k + 1) % 3, t);
      sides.push_back ({std::min (a, b), std::max (a, b), static_cast<int> (t)});
    }
  std::sort (sides.begin (), sides.end ());
  std::vector<bool> folded (static_cast<std::size_t> (mesh.numTriangles ()), false);
  for (std::size_t i = 0; i + 1 < sides.size (); ++i)
    if (sides[i][0] == sides[i + 1][0] && sides[i][1] == sides[i + 1][1] &&
        normals.col (sides[i][2]).dot (normals.col (sides[i + 1][2])) < 0.0)
      folded[static_cast<std::size_t> (sides[i][2])] = folded[static_cast<std::size_t> (sides[i + 1][2])] = true;
  return static_cast<int> (std::count (folded.begin (), folded.end (), true));
}

} // namespace morphreg

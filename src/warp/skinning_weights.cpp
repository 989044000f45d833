// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/warp/skinning_weights.h>

#include <cmath>
#include <limits>
#include <string>

namespace morphreg
{
namespace
{
void
requireConsistent (const TriangleMesh& mesh, const std::vector<int>& labels, const std::vector<int>& bone_segments,
                   const Eigen::MatrixXd& bone_distances, const SkinningFalloff& falloff)
{
  if (static_cast<Eigen::Index> (labels.size ()) != mesh.numVertices ())
    throw InvalidInputError ("skinning weights: " + std::to_string (labels.size ()) + " segment labels for " +
                             std::to_string (mesh.numVertices ()) + " vertices");
  if (bone_distances.rows () != mesh.numVertices () ||
      bone_distances.cols () != static_cast<Eigen::Index> (bone_segments.size ()))
    throw InvalidInputError ("skinning weights: the bone distances are not vertices x bones");
  if (!(falloff.width > 0.0) || !(falloff.reach > 0.0) || !std::isfinite (falloff.width * falloff.reach))
    throw InvalidInputError ("skinning weights: the falloff width and reach must be finite and > 0");
}

/** Each vertex's nearest bone among those of its segment. */
std::vector<int>
seedBones (const std::vector<int>& labels, const std::vector<int>& bone_segments, const Eigen::MatrixXd& bone_distances)
{
  std::vector<int> seeds (labels.size (), -1);
  for (std::size_t v = 0; v < labels.size (); ++v) {
    double nearest = std::numeric_limits<double>::infinity ();
    for (std::size_t b = 0; b < bone_segments.size (); ++b)
      if (bone_segments[b] == labels[v] &&
          bone_distances (static_cast<Eigen::Index> (v), static_cast<Eigen::Index> (b)) < nearest) {
        nearest = bone_distances (static_cast<Eigen::Index> (v), static_cast<Eigen::Index> (b));
        seeds[v] = static_cast<int> (b);
      }
    if (seeds[v] < 0)
      throw InvalidInputError ("skinning weights: segment " + std::to_string (labels[v]) + " (of vertex " +
                               std::to_string (v) + ") has no bone");
  }
  return seeds;
}
} // namespace

Eigen::MatrixXd
geodesicSkinningWeights (const TriangleMesh& mesh, const std::vector<int>& labels,
                         const std::vector<int>& bone_segments, const Eigen::MatrixXd& bone_distances,
                         const SkinningFalloff& falloff)
{
  validateMesh (mesh, "mesh to skin");
  requireConsistent (mesh, labels, bone_segments, bone_distances, falloff);
  const std::vector<int> seeds = seedBones (labels, bone_segments, bone_distances);
  const MeshTopology topology (mesh);
  Eigen::MatrixXd weights = Eigen::MatrixXd::Zero (mesh.numVertices (), bone_distances.cols ());
  for (Eigen::Index b = 0; b < weights.cols (); ++b) {
    std::vector<int> sources;
    for (std::size_t v = 0; v < seeds.size (); ++v)
      if (seeds[v] == b)
        sources.push_back (static_cast<int> (v));
    if (sources.empty ())
      continue;
    const std::vector<double> geodesic =
        topology.geodesicDistances (mesh.vertices, sources, falloff.reach * falloff.width);
    for (Eigen::Index v = 0; v < weights.rows (); ++v)
      if (geodesic[static_cast<std::size_t> (v)] <= falloff.reach * falloff.width)
        weights (v, b) = std::exp (-geodesic[static_cast<std::size_t> (v)] / falloff.width);
  }
  // Every vertex seeds one bone, at geodesic distance 0: each row has a weight of 1 before normalising.
  return weights.array ().colwise () / weights.rowwise ().sum ().array ();
}

Eigen::Matrix3Xd
linearBlendSkinning (const Eigen::Matrix3Xd& vertices, const Eigen::MatrixXd& weights,
                     const std::vector<Eigen::Isometry3d>& transforms)
{
  if (weights.rows () != vertices.cols () || weights.cols () != static_cast<Eigen::Index> (transforms.size ()))
    throw InvalidInputError ("linear blend skinning: the weights are not vertices x bones");
  Eigen::Matrix3Xd moved = Eigen::Matrix3Xd::Zero (3, vertices.cols ());
  for (std::size_t b = 0; b < transforms.size (); ++b) {
    const Eigen::Index bone = static_cast<Eigen::Index> (b);
    for (Eigen::Index v = 0; v < vertices.cols (); ++v)
      if (weights (v, bone) > 0.0)
        moved.col (v) += weights (v, bone) * (transforms[b] * vertices.col (v));
  }
  return moved;
}

} // namespace morphreg

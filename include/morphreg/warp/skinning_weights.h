// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file skinning_weights.h
 *  \brief Smooth skinning weights of a segmented mesh for a skeleton, derived from the segment labels and geodesic
 *  distances (no artist's weights needed).
 */
#include <morphreg/mesh/triangle_mesh.h>

#include <Eigen/Geometry>

#include <vector>

namespace morphreg
{
/** \brief How each bone's weight falls off along the mesh. */
struct SkinningFalloff
{
  double width = 30.0; ///< mm: a bone's weight falls as exp(-g / width) with the geodesic distance g from its seeds
  double reach = 8.0;  ///< widths: beyond reach * width along the mesh a bone's weight is 0
};

/** \brief Skinning weights: each vertex's seed bone is the nearest bone (distance to its head-tail segment, from
 *  \a bone_distances) among the bones of the vertex's own segment; bone b's weight at a vertex is
 *  exp(-g_b / width), g_b the geodesic distance along \a mesh to b's seed vertices (0 on them), cut off at the
 *  falloff's reach; each row is then normalised to sum to 1. A vertex deep inside a bone's region follows that bone
 *  alone; across the border between two bones both weights fall smoothly. Throws InvalidInputError if the label or
 *  distance counts do not match the mesh, or a segment that has vertices has no bone.
 *  \param[in] mesh the mesh in the posture of the joints
 *  \param[in] labels the segment of each vertex
 *  \param[in] bone_segments the segment of each bone
 *  \param[in] bone_distances numVertices () x bones: each vertex's distance to each bone (boneDistances())
 *  \param[in] falloff the width and reach
 *  \return numVertices () x bones weights, rows summing to 1
 */
Eigen::MatrixXd
geodesicSkinningWeights (const TriangleMesh& mesh, const std::vector<int>& labels,
                         const std::vector<int>& bone_segments, const Eigen::MatrixXd& bone_distances,
                         const SkinningFalloff& falloff = SkinningFalloff ());

/** \brief Linear blend skinning: each vertex moved by the weighted mean of the bones' transforms.
 *  \param[in] vertices the vertices (mm)
 *  \param[in] weights vertices x bones weights, rows summing to 1
 *  \param[in] transforms one rigid transform per bone
 *  \return the moved vertices
 */
Eigen::Matrix3Xd
linearBlendSkinning (const Eigen::Matrix3Xd& vertices, const Eigen::MatrixXd& weights,
                     const std::vector<Eigen::Isometry3d>& transforms);

} // namespace morphreg

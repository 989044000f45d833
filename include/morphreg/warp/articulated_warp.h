// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file articulated_warp.h
 *  \brief Re-posturing a segmented body mesh with rigid bones: bone motions from the joints, linear blend skinning
 *  with weights derived from the segments and geodesic distances, then an as-rigid-as-possible refinement.
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/warp/skeleton.h>
#include <morphreg/warp/skinning_weights.h>

#include <pcl/PolygonMesh.h>

#include <memory>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief Warps a mesh from one posture to another with a skeleton of rigid bones, where a thin plate spline would
 *  bend the bones: each bone's rigid motion comes from its joints in both postures (estimateBoneTransforms()); the
 *  mesh follows the bones by linear blend skinning with geodesicSkinningWeights() (each bone carries vertices of its
 *  own segment); an as-rigid-as-possible refinement (AsRigidAsPossible) then keeps the blended zones near the
 *  joints close to rigid copies of their rest shape, pinned to any surface landmarks. A segment beside
 *  SegmentedWarp: same labels, same evaluation (evaluateWarp()).
 *
 *  \code
 *  morphreg::ArticulatedWarp warp (morphreg::makeHumanSkeleton (), labels, segment_names);
 *  warp.setJoints (joints_standing, joints_seated);      // joint name -> position, mm
 *  morphreg::TriangleMesh seated = warp.warp (standing);
 *  \endcode
 */
class ArticulatedWarp
{
public:
  using Ptr = std::shared_ptr<ArticulatedWarp>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const ArticulatedWarp>; ///< shared pointer to const

  /** \brief A warp for meshes whose vertices carry \a labels (indices into \a segment_names). Throws
   *  InvalidInputError if a bone names a segment that is not in \a segment_names (the skeleton does not match the
   *  labels), or a label is outside them.
   *  \param[in] skeleton the bones
   *  \param[in] labels the segment of each vertex of the meshes this will warp
   *  \param[in] segment_names the segments' names, as the bones name them
   */
  ArticulatedWarp (Skeleton skeleton, std::vector<int> labels, const std::vector<std::string>& segment_names);

  /** \brief Sets the joints in the source and the target posture and estimates the bones' motions; errors as
   *  estimateBoneTransforms() (missing, coincident or non-finite joints, naming the bone).
   *  \param[in] source joint positions on the mesh to warp (mm)
   *  \param[in] target joint positions in the target posture (mm)
   */
  void
  setJoints (const LandmarkPositions& source, const LandmarkPositions& target);

  /** \brief Surface landmarks: vertex \a vertices[k] of the mesh must end at column k of \a targets (mm). They pin
   *  the refinement; the skinning does not see them. Replaces earlier ones; none by default.
   *  \param[in] vertices vertex indices of the mesh to warp
   *  \param[in] targets their target positions (3 x vertices.size (), mm)
   */
  void
  setSurfaceLandmarks (const std::vector<int>& vertices, const Eigen::Matrix3Xd& targets);

  /** \brief How the bones' weights fall off along the mesh (default: width 30 mm, reach 8 widths).
   *  \param[in] falloff the falloff
   */
  void
  setSkinningFalloff (const SkinningFalloff& falloff);

  /** \brief The skinning falloff.
   *  \return the falloff
   */
  const SkinningFalloff&
  getSkinningFalloff () const
  {
    return falloff_;
  }

  /** \brief The weight of the as-rigid-as-possible term against staying on the skinned positions (>= 0; 0 = linear
   *  blend skinning alone; default 1).
   *  \param[in] rigidity the weight
   */
  void
  setRigidity (double rigidity);

  /** \brief The rigidity weight.
   *  \return the weight
   */
  double
  getRigidity () const
  {
    return rigidity_;
  }

  /** \brief The number of as-rigid-as-possible iterations (>= 0; default 5).
   *  \param[in] iterations the number
   */
  void
  setIterations (int iterations);

  /** \brief The number of as-rigid-as-possible iterations.
   *  \return the number
   */
  int
  getIterations () const
  {
    return iterations_;
  }

  /** \brief The skeleton.
   *  \return the skeleton
   */
  const Skeleton&
  skeleton () const
  {
    return skeleton_;
  }

  /** \brief The bones' motions from setJoints() (InvalidInputError before).
   *  \return one rigid transform per bone, source to target
   */
  const std::vector<Eigen::Isometry3d>&
  boneTransforms () const;

  /** \brief The skinning weights of \a mesh (the mesh to warp, in the source posture).
   *  \param[in] mesh the mesh
   *  \return numVertices () x bones weights, rows summing to 1
   */
  Eigen::MatrixXd
  skinningWeights (const TriangleMesh& mesh) const;

  /** \brief \a mesh moved by linear blend skinning alone (no refinement, surface landmarks unused).
   *  \param[in] mesh the mesh to warp
   *  \return the skinned mesh (same triangles)
   */
  TriangleMesh
  skin (const TriangleMesh& mesh) const;

  /** \brief \a mesh warped: skinned, then refined (the refinement's system is factorised once per call).
   *  \param[in] mesh the mesh to warp, labelled like the warp, in the source posture of the joints
   *  \return the warped mesh (same triangles)
   */
  TriangleMesh
  warp (const TriangleMesh& mesh) const;

  /** \brief As warp(TriangleMesh) for a pcl::PolygonMesh of triangles; vertex normals are recomputed.
   *  \param[in] input the mesh to warp
   *  \param[out] output the warped mesh
   */
  void
  warp (const pcl::PolygonMesh& input, pcl::PolygonMesh& output) const;

private:
  void
  requireMesh (const TriangleMesh& mesh) const;

  Skeleton skeleton_;
  std::vector<int> labels_;
  std::vector<int> bone_segments_;
  LandmarkPositions source_joints_;
  std::vector<Eigen::Isometry3d> transforms_;
  std::vector<int> landmark_vertices_;
  Eigen::Matrix3Xd landmark_targets_;
  SkinningFalloff falloff_;
  double rigidity_ = 1.0;
  int iterations_ = 5;
};

} // namespace morphreg

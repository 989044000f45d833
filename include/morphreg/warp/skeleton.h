// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file skeleton.h
 *  \brief A skeleton of rigid bones between named joints, and the rigid motion of each bone between two postures
 *  given only the joint positions in both.
 */
#include <morphreg/common/landmarks.h>

#include <Eigen/Geometry>

#include <memory>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief One rigid bone of a Skeleton: it runs from its head joint to its tail joint and carries the vertices of one
 *  mesh segment.
 */
struct Bone
{
  std::string name;    ///< unique, e.g. "upperleg.L"
  std::string head;    ///< joint name where the bone starts (e.g. the hip)
  std::string tail;    ///< joint name where it ends (e.g. the knee)
  std::string segment; ///< the mesh segment (region name of the label file) whose vertices the bone may carry
  /** Optional: with twist_to, a pair of joints whose direction (from, to), seen across the bone, fixes the bone's
   *  twist about its own axis (head and tail alone leave it open), e.g. the two hips for a thigh. Both empty: no
   *  twist, the bone takes the shortest rotation of its direction. */
  std::string twist_from;
  std::string twist_to; ///< the other joint of the twist pair (empty with twist_from)
};

/** \brief Named bones between named joints, validated on construction: at least one bone, unique names, head and
 *  tail different joints, twist joints both given or both empty and different.
 *
 *  \code
 *  morphreg::Skeleton skeleton ({{"thigh.L", "hip.L", "knee.L", "legs", "hip.R", "hip.L"},
 *                               {"shin.L", "knee.L", "ankle.L", "legs", "hip.R", "hip.L"}});
 *  std::vector<Eigen::Isometry3d> motion = morphreg::estimateBoneTransforms (skeleton, standing, seated);
 *  \endcode
 */
class Skeleton
{
public:
  using Ptr = std::shared_ptr<Skeleton>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const Skeleton>; ///< shared pointer to const

  /** \brief Takes \a bones; throws InvalidInputError naming the bone for any of the problems above.
   *  \param[in] bones the bones
   *  \param[in] other_joints joints the skeleton knows but no bone uses (e.g. a rig's intermediate joints, which
   *  move rigidly with neither neighbouring bone): landmarks with these names are joints, not surface points
   */
  explicit Skeleton (std::vector<Bone> bones, std::vector<std::string> other_joints = {});

  /** \brief The bones, in the order given.
   *  \return the bones
   */
  const std::vector<Bone>&
  bones () const
  {
    return bones_;
  }

  /** \brief The number of bones.
   *  \return bones ().size ()
   */
  int
  numBones () const
  {
    return static_cast<int> (bones_.size ());
  }

  /** \brief Every joint the bones name (heads, tails and twist joints), sorted.
   *  \return the joint names
   */
  std::vector<std::string>
  boneJointNames () const;

  /** \brief Every joint the skeleton knows: boneJointNames() and the other joints, sorted.
   *  \return the joint names
   */
  std::vector<std::string>
  jointNames () const;

  /** \brief The positions of every joint of boneJointNames() in \a joints; throws InvalidInputError naming \a what
   *  (e.g. "the source joints") and the joints it lacks.
   *  \param[in] joints joint positions by name (mm); other names are ignored
   *  \param[in] what the joint set, for the message
   */
  void
  requireJoints (const LandmarkPositions& joints, const std::string& what) const;

  /** \brief The bone segments (head to tail) as columns of two 3 x numBones() matrices.
   *  \param[in] joints joint positions by name (mm), with every joint of the skeleton
   *  \return heads and tails
   */
  std::pair<Eigen::Matrix3Xd, Eigen::Matrix3Xd>
  boneEnds (const LandmarkPositions& joints) const;

private:
  std::vector<Bone> bones_;
  std::vector<std::string> other_joints_;
};

/** \brief The rigid motion of each bone from the \a source posture to the \a target one, from the joints alone: the
 *  shortest rotation that turns the bone's head-to-tail direction into its target direction, then the twist about
 *  the target direction that best aligns the bone's twist pair (the part of its direction across the bone; no twist
 *  for a bone without a pair, or when that part is under a tenth of the pair's length in either posture), then the
 *  translation that carries the head onto its target. Throws InvalidInputError naming the bone and the joints for a
 *  joint missing in either set, a head and tail closer than 1e-6 mm (a bone of no length) or coincident twist
 *  joints.
 *  \param[in] skeleton the bones
 *  \param[in] source joint positions in the source posture (mm)
 *  \param[in] target joint positions in the target posture (mm)
 *  \return one transform per bone, source to target
 */
std::vector<Eigen::Isometry3d>
estimateBoneTransforms (const Skeleton& skeleton, const LandmarkPositions& source, const LandmarkPositions& target);

/** \brief The distance of each column of \a points to each bone's head-tail segment.
 *  \param[in] skeleton the bones
 *  \param[in] joints joint positions (mm) with every joint of the skeleton
 *  \param[in] points the points (mm)
 *  \return points.cols () x numBones () distances (mm)
 */
Eigen::MatrixXd
boneDistances (const Skeleton& skeleton, const LandmarkPositions& joints, const Eigen::Matrix3Xd& points);

/** \brief For each column of \a points, the index of the nearest bone (distance to the head-tail segment).
 *  \param[in] skeleton the bones
 *  \param[in] joints joint positions (mm) with every joint of the skeleton
 *  \param[in] points the points (mm)
 *  \return one bone index per point
 */
std::vector<int>
nearestBones (const Skeleton& skeleton, const LandmarkPositions& joints, const Eigen::Matrix3Xd& points);

} // namespace morphreg

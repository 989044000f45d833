// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/warp/skeleton.h>

#include <algorithm>
#include <cmath>
#include <set>

namespace morphreg
{
namespace
{
constexpr double kCoincident = 1e-6; ///< mm: joints closer than this are one point

void
requireBone (const Bone& bone)
{
  const std::string prefix = "Skeleton: bone '" + bone.name + "': ";
  if (bone.head.empty () || bone.tail.empty ())
    throw InvalidInputError (prefix + "needs a head and a tail joint");
  if (bone.head == bone.tail)
    throw InvalidInputError (prefix + "head and tail are the same joint '" + bone.head + "'");
  if (bone.twist_from.empty () != bone.twist_to.empty ())
    throw InvalidInputError (prefix + "give both twist joints or neither");
  if (!bone.twist_from.empty () && bone.twist_from == bone.twist_to)
    throw InvalidInputError (prefix + "the two twist joints are the same joint '" + bone.twist_from + "'");
}

/** \a to - \a from in \a joints, refused if the two joints coincide (\a what names them for the message). */
Eigen::Vector3d
jointDirection (const LandmarkPositions& joints, const std::string& from, const std::string& to,
                const std::string& what)
{
  const Eigen::Vector3d direction = joints.at (to) - joints.at (from);
  if (!direction.allFinite () || direction.norm () < kCoincident)
    throw InvalidInputError (what + ": joints '" + from + "' and '" + to + "' coincide (or are not finite)");
  return direction;
}

/** The angle (radians) about the unit \a axis that turns the part of \a from across the axis into that of \a to;
 *  0 if either part is under a tenth of its vector's length (the twist is then not defined by the pair).
 */
double
twistAngle (const Eigen::Vector3d& axis, const Eigen::Vector3d& from, const Eigen::Vector3d& to)
{
  const Eigen::Vector3d a = from - axis * axis.dot (from), b = to - axis * axis.dot (to);
  if (a.norm () < 0.1 * from.norm () || b.norm () < 0.1 * to.norm ())
    return 0.0;
  return std::atan2 (axis.dot (a.cross (b)), a.dot (b));
}

Eigen::Isometry3d
boneTransform (const Bone& bone, const LandmarkPositions& source, const LandmarkPositions& target)
{
  const std::string what = "bone '" + bone.name + "'";
  const Eigen::Vector3d from = jointDirection (source, bone.head, bone.tail, what + " in the source joints");
  const Eigen::Vector3d to = jointDirection (target, bone.head, bone.tail, what + " in the target joints");
  Eigen::Matrix3d rotation = Eigen::Quaterniond::FromTwoVectors (from, to).toRotationMatrix ();
  if (!bone.twist_from.empty ()) {
    const Eigen::Vector3d axis = to.normalized ();
    const double angle = twistAngle (
        axis,
        rotation * jointDirection (source, bone.twist_from, bone.twist_to, what + " (twist) in the source joints"),
        jointDirection (target, bone.twist_from, bone.twist_to, what + " (twist) in the target joints"));
    rotation = Eigen::AngleAxisd (angle, axis).toRotationMatrix () * rotation;
  }
  Eigen::Isometry3d transform = Eigen::Isometry3d::Identity ();
  transform.linear () = rotation;
  transform.translation () = target.at (bone.head) - rotation * source.at (bone.head);
  return transform;
}
} // namespace

Skeleton::Skeleton (std::vector<Bone> bones, std::vector<std::string> other_joints)
  : bones_ (std::move (bones)), other_joints_ (std::move (other_joints))
{
  if (bones_.empty ())
    throw InvalidInputError ("Skeleton: no bones");
  std::set<std::string> names;
  for (const Bone& bone : bones_) {
    if (bone.name.empty ())
      throw InvalidInputError ("Skeleton: a bone has no name");
    if (!names.insert (bone.name).second)
      throw InvalidInputError ("Skeleton: two bones are named '" + bone.name + "'");
    requireBone (bone);
  }
}

std::vector<std::string>
Skeleton::jointNames () const
{
  std::vector<std::string> names = boneJointNames ();
  names.insert (names.end (), other_joints_.begin (), other_joints_.end ());
  std::sort (names.begin (), names.end ());
  names.erase (std::unique (names.begin (), names.end ()), names.end ());
  return names;
}

std::vector<std::string>
Skeleton::boneJointNames () const
{
  std::set<std::string> names;
  for (const Bone& bone : bones_)
    for (const std::string* joint : {&bone.head, &bone.tail, &bone.twist_from, &bone.twist_to})
      if (!joint->empty ())
        names.insert (*joint);
  return {names.begin (), names.end ()};
}

void
Skeleton::requireJoints (const LandmarkPositions& joints, const std::string& what) const
{
  std::string missing;
  for (const std::string& name : boneJointNames ())
    if (!joints.count (name))
      missing += " " + name;
  if (!missing.empty ())
    throw InvalidInputError (what + " lack joints the skeleton's bones need:" + missing);
  for (const std::string& name : boneJointNames ())
    if (!joints.at (name).allFinite ())
      throw InvalidInputError (what + ": joint '" + name + "' is not finite");
}

std::pair<Eigen::Matrix3Xd, Eigen::Matrix3Xd>
Skeleton::boneEnds (const LandmarkPositions& joints) const
{
  requireJoints (joints, "the joints");
  Eigen::Matrix3Xd heads (3, numBones ()), tails (3, numBones ());
  for (int b = 0; b < numBones (); ++b) {
    heads.col (b) = joints.at (bones_[static_cast<std::size_t> (b)].head);
    tails.col (b) = joints.at (bones_[static_cast<std::size_t> (b)].tail);
  }
  return {heads, tails};
}

std::vector<Eigen::Isometry3d>
estimateBoneTransforms (const Skeleton& skeleton, const LandmarkPositions& source, const LandmarkPositions& target)
{
  skeleton.requireJoints (source, "the source joints");
  skeleton.requireJoints (target, "the target joints");
  std::vector<Eigen::Isometry3d> transforms;
  for (const Bone& bone : skeleton.bones ())
    transforms.push_back (boneTransform (bone, source, target));
  return transforms;
}

Eigen::MatrixXd
boneDistances (const Skeleton& skeleton, const LandmarkPositions& joints, const Eigen::Matrix3Xd& points)
{
  const auto [heads, tails] = skeleton.boneEnds (joints);
  Eigen::MatrixXd distances (points.cols (), skeleton.numBones ());
  for (int b = 0; b < skeleton.numBones (); ++b) {
    const Eigen::Vector3d axis = tails.col (b) - heads.col (b);
    const double length2 = std::max (axis.squaredNorm (), kCoincident * kCoincident);
    for (Eigen::Index i = 0; i < points.cols (); ++i) {
      const double t = std::clamp ((points.col (i) - heads.col (b)).dot (axis) / length2, 0.0, 1.0);
      distances (i, b) = (points.col (i) - heads.col (b) - t * axis).norm ();
    }
  }
  return distances;
}

std::vector<int>
nearestBones (const Skeleton& skeleton, const LandmarkPositions& joints, const Eigen::Matrix3Xd& points)
{
  const Eigen::MatrixXd distances = boneDistances (skeleton, joints, points);
  std::vector<int> nearest (static_cast<std::size_t> (points.cols ()));
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    distances.row (i).minCoeff (&nearest[static_cast<std::size_t> (i)]);
  return nearest;
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file makehuman_bodies.h
 *  \brief Reader for the MakeHuman body set (a folder of the exported bodies): three subjects standing and seated in
 *  one vertex numbering, their joint centres, the four body segments and the landmark sets. MakeHuman works in
 *  decimetres; everything returned here is converted to millimetres.
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/warp/skeleton.h>

#include <map>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief Pose of a MakeHuman body. */
enum class BodyPose
{
  standing, ///< the rest pose
  seated    ///< sitting on a chair
};

/** \brief The MakeHuman body folder, validated on construction (files present, counts consistent).
 *
 *  \code
 *  morphreg::MakeHumanBodies bodies (data_dir + "/makehuman_bodies");
 *  TriangleMesh standing = bodies.loadMesh ("base", morphreg::BodyPose::standing);      // mm
 *  Eigen::Matrix3Xd joints = bodies.joints ("base", morphreg::BodyPose::standing, bodies.majorJoints ());
 *  \endcode
 */
class MakeHumanBodies
{
public:
  /** \brief MakeHuman units (decimetres) to millimetres. */
  static constexpr double kMillimetresPerUnit = 100.0;

  /** \brief Reads the JSON files of \a directory; throws IoError / FormatError naming the file and the problem.
   *  \param[in] directory the makehuman_bodies folder
   */
  explicit MakeHumanBodies (const std::string& directory);

  /** \brief The subjects ("base", "caucasian-male-young", "caucasian-female-young").
   *  \return their names
   */
  std::vector<std::string>
  subjects () const;

  /** \brief A subject's body mesh in \a pose, in millimetres.
   *  \param[in] subject one of subjects()
   *  \param[in] pose standing or seated
   *  \return the mesh; every subject and pose share one topology
   */
  TriangleMesh
  loadMesh (const std::string& subject, BodyPose pose) const;

  /** \brief Joint centres (3 x names.size(), mm) of a subject in \a pose; throws InvalidInputError for an
   *  unknown subject or joint name.
   *  \param[in] subject one of subjects()
   *  \param[in] pose standing or seated
   *  \param[in] names the joints wanted, e.g. majorJoints()
   *  \return one column per name
   */
  Eigen::Matrix3Xd
  joints (const std::string& subject, BodyPose pose, const std::vector<std::string>& names) const;

  /** \brief The sparse landmark set as columns (mm): the 51 major joints of a subject in \a pose, then the 16
   *  surface vertices of \a mesh (the subject's mesh in that pose), the landmarks of the between-subject warps.
   *  \param[in] subject one of subjects()
   *  \param[in] pose standing or seated
   *  \param[in] mesh the subject's mesh in \a pose (loadMesh())
   *  \return 3 x 67 positions
   */
  Eigen::Matrix3Xd
  jointAndSurfaceLandmarks (const std::string& subject, BodyPose pose, const TriangleMesh& mesh) const;

  /** \brief Joint positions (mm) of a subject in \a pose by name, for the \a names wanted (e.g. majorJoints());
   *  InvalidInputError for an unknown subject or joint name.
   *  \param[in] subject one of subjects()
   *  \param[in] pose standing or seated
   *  \param[in] names the joints wanted
   *  \return name -> position
   */
  LandmarkPositions
  namedJoints (const std::string& subject, BodyPose pose, const std::vector<std::string>& names) const;

  /** \brief All joint names (head and tail of every bone).
   *  \return the names, sorted
   */
  std::vector<std::string>
  jointNames () const;

  /** \brief The 51 major joints of mh_landmark_sets.json (the sparse landmark set).
   *  \return their names
   */
  const std::vector<std::string>&
  majorJoints () const
  {
    return major_joints_;
  }

  /** \brief The 16 surface vertex indices of mh_landmark_sets.json (knees, thighs, hips, buttocks).
   *  \return the vertex indices
   */
  const std::vector<int>&
  surfaceVertices () const
  {
    return surface_vertices_;
  }

  /** \brief Segment label per vertex (index into segmentNames()).
   *  \return one label per vertex
   */
  const std::vector<int>&
  segmentLabels () const
  {
    return segment_labels_;
  }

  /** \brief The body segments: "left_arm", "right_arm", "upper_body", "lower_body".
   *  \return the names, indexed by segmentLabels()
   */

  const std::vector<std::string>&
  segmentNames () const
  {
    return segment_names_;
  }

private:
  const std::map<std::string, Eigen::Vector3d>&
  jointTable (const std::string& subject, BodyPose pose) const;

  std::string directory_;
  std::map<std::string, std::map<std::string, Eigen::Vector3d>> joints_; ///< key: subject or subject_seated
  std::vector<std::string> major_joints_;
  std::vector<int> surface_vertices_;
  std::vector<int> segment_labels_;
  std::vector<std::string> segment_names_;
  int num_vertices_ = 0;
};

/** \brief A skeleton of 27 rigid bones over the 51 major joints of the MakeHuman bodies (MakeHumanBodies::
 *  majorJoints()), carrying the four segments of mh_segments.json: the spine from spine05 to the head (the two lowest
 *  bones in lower_body, the rest in upper_body), per side a clavicle (upper_body), shoulder, upper arm, forearm and
 *  hand (the arm's segment), a pelvis bone from spine05 to the hip, a thigh (hip to knee), shin (knee to ankle) and
 *  foot (lower_body). Twists come from the eyes (head), the two hips (thigh and shin), the two shoulders (upper
 *  arm), thumb and little finger tips (forearm and hand) and the outer toes (foot). Bones are named after
 *  MakeHuman's ("upperleg.L" for the left thigh, "lowerleg.L", "upperarm.L", ...), so the limb parts of
 *  limbPartErrors() find them. The other major joints (the jaw, the intermediate arm and leg joints, the wrists'
 *  tails) are the skeleton's other joints: they follow the skin rather than a bone.
 *  \return the skeleton
 */
Skeleton
makeHumanSkeleton ();

} // namespace morphreg

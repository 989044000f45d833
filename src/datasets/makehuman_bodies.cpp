// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/json_file.h>
#include <morphreg/datasets/makehuman_bodies.h>
#include <morphreg/io/mesh_io.h>

#include <nlohmann/json.hpp>

namespace morphreg
{
namespace
{
/** Runs \a read on \a json; a missing key or wrong type becomes a FormatError naming the file. */
template <typename Read>
void
readField (const std::string& path, Read read)
{
  try {
    read ();
  }
  catch (const nlohmann::json::exception& e) {
    throw FormatError (path + ": unexpected content (" + e.what () + ")");
  }
}

std::string
poseKey (const std::string& subject, BodyPose pose)
{
  return pose == BodyPose::seated ? subject + "_seated" : subject;
}
} // namespace

MakeHumanBodies::MakeHumanBodies (const std::string& directory) : directory_ (directory)
{
  const std::string joints_path = directory + "/mh_joints.json";
  const nlohmann::json joints = readJsonFile (joints_path);
  readField (joints_path, [&] {
    num_vertices_ = joints.at ("num_body_vertices").get<int> ();
    for (const auto& [key, subject] : joints.at ("subjects").items ())
      for (const auto& [name, position] : subject.at ("joints").items ()) {
        const auto xyz = position.get<std::vector<double>> ();
        if (xyz.size () != 3)
          throw FormatError (joints_path + ": joint '" + name + "' of '" + key + "' does not have 3 coordinates");
        joints_[key][name] = kMillimetresPerUnit * Eigen::Vector3d (xyz[0], xyz[1], xyz[2]);
      }
  });

  const std::string sets_path = directory + "/mh_landmark_sets.json";
  const nlohmann::json sets = readJsonFile (sets_path);
  readField (sets_path, [&] {
    major_joints_ = sets.at ("major_joints").get<std::vector<std::string>> ();
    surface_vertices_ = sets.at ("surface_vertices").get<std::vector<int>> ();
  });
  for (int vertex : surface_vertices_)
    if (vertex < 0 || vertex >= num_vertices_)
      throw FormatError (sets_path + ": surface vertex " + std::to_string (vertex) + " is out of range [0, " +
                         std::to_string (num_vertices_) + ")");

  const std::string segments_path = directory + "/mh_segments.json";
  const nlohmann::json segments = readJsonFile (segments_path);
  readField (segments_path, [&] {
    segment_names_ = segments.at ("segments").get<std::vector<std::string>> ();
    segment_labels_ = segments.at ("labels").get<std::vector<int>> ();
  });
  if (static_cast<int> (segment_labels_.size ()) != num_vertices_)
    throw FormatError (segments_path + ": " + std::to_string (segment_labels_.size ()) + " labels for " +
                       std::to_string (num_vertices_) + " vertices");
  for (int label : segment_labels_)
    if (label < 0 || label >= static_cast<int> (segment_names_.size ()))
      throw FormatError (segments_path + ": segment label " + std::to_string (label) + " is out of range");
}

std::vector<std::string>
MakeHumanBodies::subjects () const
{
  std::vector<std::string> names;
  for (const auto& entry : joints_)
    if (joints_.count (entry.first + "_seated"))
      names.push_back (entry.first);
  return names;
}

TriangleMesh
MakeHumanBodies::loadMesh (const std::string& subject, BodyPose pose) const
{
  jointTable (subject, pose); // validates the subject
  TriangleMesh mesh = loadTriangleMesh (directory_ + "/mh_" + poseKey (subject, pose) + ".ply");
  if (mesh.numVertices () != num_vertices_)
    throw FormatError (directory_ + "/mh_" + poseKey (subject, pose) + ".ply: " + std::to_string (mesh.numVertices ()) +
                       " vertices, expected " + std::to_string (num_vertices_));
  mesh.vertices *= kMillimetresPerUnit;
  return mesh;
}

const std::map<std::string, Eigen::Vector3d>&
MakeHumanBodies::jointTable (const std::string& subject, BodyPose pose) const
{
  const auto it = joints_.find (poseKey (subject, pose));
  if (it == joints_.end ())
    throw InvalidInputError ("MakeHumanBodies: no subject '" + poseKey (subject, pose) + "' in " + directory_);
  return it->second;
}

Eigen::Matrix3Xd
MakeHumanBodies::joints (const std::string& subject, BodyPose pose, const std::vector<std::string>& names) const
{
  const auto& table = jointTable (subject, pose);
  Eigen::Matrix3Xd positions (3, static_cast<Eigen::Index> (names.size ()));
  for (std::size_t i = 0; i < names.size (); ++i) {
    const auto it = table.find (names[i]);
    if (it == table.end ())
      throw InvalidInputError ("MakeHumanBodies: no joint '" + names[i] + "' for '" + subject + "'");
    positions.col (static_cast<Eigen::Index> (i)) = it->second;
  }
  return positions;
}

Eigen::Matrix3Xd
MakeHumanBodies::jointAndSurfaceLandmarks (const std::string& subject, BodyPose pose, const TriangleMesh& mesh) const
{
  if (mesh.numVertices () != num_vertices_)
    throw InvalidInputError ("MakeHumanBodies: a mesh of " + std::to_string (mesh.numVertices ()) +
                             " vertices is not one of the bodies (" + std::to_string (num_vertices_) + ")");
  Eigen::Matrix3Xd landmarks = joints (subject, pose, major_joints_);
  const Eigen::Index num_joints = landmarks.cols ();
  landmarks.conservativeResize (3, num_joints + static_cast<Eigen::Index> (surface_vertices_.size ()));
  for (std::size_t k = 0; k < surface_vertices_.size (); ++k)
    landmarks.col (num_joints + static_cast<Eigen::Index> (k)) = mesh.vertices.col (surface_vertices_[k]);
  return landmarks;
}

LandmarkPositions
MakeHumanBodies::namedJoints (const std::string& subject, BodyPose pose, const std::vector<std::string>& names) const
{
  const Eigen::Matrix3Xd positions = joints (subject, pose, names);
  LandmarkPositions named;
  for (std::size_t i = 0; i < names.size (); ++i)
    named[names[i]] = positions.col (static_cast<Eigen::Index> (i));
  return named;
}

std::vector<std::string>
MakeHumanBodies::jointNames () const
{
  std::vector<std::string> names;
  for (const auto& entry : joints_.begin ()->second)
    names.push_back (entry.first);
  return names;
}

} // namespace morphreg

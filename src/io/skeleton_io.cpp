// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/skeleton_io.h>

#include <algorithm>

namespace morphreg
{
namespace
{
/** Field \a key of bone \a index, a non-empty string; FormatError naming the file and bone otherwise. */
std::string
textField (const nlohmann::json& bone, const char* key, std::size_t index, const std::string& path)
{
  if (!bone.contains (key) || !bone[key].is_string () || bone[key].get<std::string> ().empty ())
    throw FormatError (path + ": bone " + std::to_string (index) + " needs \"" + key + "\" as a non-empty string");
  return bone[key].get<std::string> ();
}

Bone
parseBone (const nlohmann::json& entry, std::size_t index, const std::string& path)
{
  if (!entry.is_object ())
    throw FormatError (path + ": bone " + std::to_string (index) + " is not an object");
  Bone bone{textField (entry, "name", index, path),
            textField (entry, "head", index, path),
            textField (entry, "tail", index, path),
            textField (entry, "segment", index, path),
            "",
            ""};
  if (entry.contains ("twist")) {
    const nlohmann::json& twist = entry["twist"];
    if (!twist.is_array () || twist.size () != 2 || !twist[0].is_string () || !twist[1].is_string ())
      throw FormatError (path + ": bone " + std::to_string (index) + " ('" + bone.name +
                         "'): \"twist\" must be two joint names [from, to]");
    bone.twist_from = twist[0].get<std::string> ();
    bone.twist_to = twist[1].get<std::string> ();
  }
  return bone;
}
} // namespace

Skeleton
loadSkeleton (const std::string& path)
{
  const nlohmann::json document = readJsonFile (path);
  if (!document.is_object () || !document.contains ("bones") || !document["bones"].is_array ())
    throw FormatError (path + ": a skeleton file needs {\"bones\": [...]}");
  std::vector<Bone> bones;
  for (std::size_t i = 0; i < document["bones"].size (); ++i)
    bones.push_back (parseBone (document["bones"][i], i, path));
  std::vector<std::string> other_joints;
  if (document.contains ("other_joints")) {
    if (!document["other_joints"].is_array ())
      throw FormatError (path + ": \"other_joints\" must be a list of joint names");
    for (const nlohmann::json& name : document["other_joints"]) {
      if (!name.is_string ())
        throw FormatError (path + ": \"other_joints\" must be a list of joint names");
      other_joints.push_back (name.get<std::string> ());
    }
  }
  try {
    return Skeleton (std::move (bones), std::move (other_joints));
  }
  catch (const InvalidInputError& e) {
    throw InvalidInputError (path + ": " + e.what ());
  }
}

void
saveSkeleton (const std::string& path, const Skeleton& skeleton)
{
  nlohmann::json bones = nlohmann::json::array ();
  for (const Bone& bone : skeleton.bones ()) {
    nlohmann::json entry = {{"name", bone.name}, {"head", bone.head}, {"tail", bone.tail}, {"segment", bone.segment}};
    if (!bone.twist_from.empty ())
      entry["twist"] = {bone.twist_from, bone.twist_to};
    bones.push_back (entry);
  }
  std::vector<std::string> other_joints;
  const std::vector<std::string> bone_joints = skeleton.boneJointNames ();
  for (const std::string& name : skeleton.jointNames ())
    if (!std::binary_search (bone_joints.begin (), bone_joints.end (), name))
      other_joints.push_back (name);
  writeJsonFile (path, {{"bones", bones}, {"other_joints", other_joints}});
}

} // namespace morphreg

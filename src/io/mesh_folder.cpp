// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/mesh_folder.h>

#include <algorithm>
#include <filesystem>

namespace morphreg
{
namespace
{
/** The heads and profile line listed in \a manifest_path, the population.json of \a directory. */
MeshFolder
readPopulation (const std::string& directory, const std::string& manifest_path)
{
  const nlohmann::json manifest = readJsonFile (manifest_path);
  MeshFolder folder;
  folder.manifest = manifest_path;
  try {
    for (const auto& head : manifest.at ("heads"))
      folder.files.push_back (directory + "/" + head.at ("file").get<std::string> ());
    if (manifest.contains ("profile_line"))
      folder.profile_line = manifest.at ("profile_line").get<std::vector<int>> ();
  }
  catch (const nlohmann::json::exception& e) {
    throw FormatError (manifest_path +
                       ": expected {\"heads\": [{\"file\": mesh file}, ...], \"profile_line\": "
                       "[vertex, ...]} (" +
                       e.what () + ")");
  }
  return folder;
}
} // namespace

MeshFolder
readMeshFolder (const std::string& directory)
{
  if (!std::filesystem::is_directory (directory))
    throw IoError (directory + ": not a directory");
  const std::string manifest_path = directory + "/population.json";
  if (std::filesystem::exists (manifest_path))
    return readPopulation (directory, manifest_path);
  MeshFolder folder;
  for (const auto& entry : std::filesystem::directory_iterator (directory)) {
    const std::string ext = fileExtension (entry.path ().string ());
    if (entry.is_regular_file () &&
        (ext == ".ply" || ext == ".obj" || ext == ".vtk" || ext == ".stl" || ext == ".gltf" || ext == ".glb"))
      folder.files.push_back (entry.path ().string ());
  }
  std::sort (folder.files.begin (), folder.files.end ());
  if (folder.files.empty ())
    throw InvalidInputError (directory + ": no mesh files (.ply .obj .vtk .stl .gltf .glb) in the folder");
  return folder;
}
} // namespace morphreg

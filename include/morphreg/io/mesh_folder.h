// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file mesh_folder.h
 *  \brief A folder of meshes in correspondence, the training set of a model: the heads its population.json lists
 *  (as the synthetic populations write it, with the profile line of their topology), else every mesh file in it.
 *
 *  population.json layout: {"heads": [{"file": mesh file, ...}, ...], "profile_line": [vertex, ...]}; file names
 *  are relative to the folder, "profile_line" is optional.
 */
#include <string>
#include <vector>

namespace morphreg
{
/** \brief The meshes of a folder and, from its population.json, the profile line of their topology. */
struct MeshFolder
{
  std::vector<std::string> files; ///< the mesh files, in population.json's order or by name
  std::vector<int> profile_line;  ///< empty without population.json or without "profile_line" in it
  std::string manifest;           ///< the population.json read; empty when the folder has none
};

/** \brief The meshes of \a directory: the heads listed in its population.json, else every .ply .obj .vtk .stl
 *  .gltf .glb file in name order. Throws IoError when \a directory is no folder, FormatError naming population.json
 *  for a wrong layout, InvalidInputError naming the folder when it holds no mesh.
 *  \param[in] directory the folder
 *  \return its mesh files and profile line
 */
MeshFolder
readMeshFolder (const std::string& directory);
} // namespace morphreg

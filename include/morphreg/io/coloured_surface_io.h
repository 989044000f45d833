// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file coloured_surface_io.h
 *  \brief A scan file's colours as a ColouredSurface, whatever its format: what registration and resampling sample
 *  onto the fitted and the resampled meshes.
 */
#include <morphreg/mesh/coloured_surface.h>

#include <string>

namespace morphreg
{
/** \brief The scan in \a path (.pcd .ply .obj .stl .off .vtk .gltf .glb) as a surface with its colours: the rgb of
 *  PLY, PCD and OBJ vertices, the diffuse textures (map_Kd) of an OBJ's materials at its texture coordinates, glTF's
 *  COLOR_0 and base-colour textures. Coordinates as loadCloud() and loadPolygonMesh() give them (glTF in mm); points
 *  that are not finite (a cloud's missing points) are left out with their triangles. A file without colours gives a
 *  surface without (hasColours() false). Throws as the file's loader does, and IoError naming the OBJ file and the
 *  missing file for a material library or texture that is missing.
 *  \param[in] path the scan file
 *  \return its surface and colours
 */
ColouredSurface
loadColouredSurface (const std::string& path);

} // namespace morphreg

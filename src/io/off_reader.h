// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private: morphreg's own reader of ASCII OFF meshes (neither PCL nor VTK reads OFF), shared by the mesh loader and
// validateGeometryFile.
#include <pcl/PolygonMesh.h>

#include <string>

namespace morphreg
{
/** An ASCII Object File Format mesh: "OFF", the vertex, face and edge counts, the vertices (x y z), the faces
 *  (n i_1 .. i_n; anything after them on the line, e.g. a colour, is ignored). FormatError naming the file and line
 *  of a bad count, coordinate or corner index, or counts that the file is too small to hold.
 */
pcl::PolygonMesh
readOffMesh (const std::string& path);
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private: morphreg's own writer of binary PLY meshes. PCL's mesh writer knows a fixed set of vertex fields and
// drops any other (a per-vertex "quality", say), so savePolygonMesh writes PLY meshes with this one.
#include <pcl/PolygonMesh.h>

#include <string>

namespace morphreg
{
/** The bytes of \a mesh as a binary little-endian PLY file: every vertex field of its cloud as a vertex property in
 *  the cloud's order, as PCL and MeshLab name them (PCL's packed rgb / rgba as uchar red, green, blue [, alpha],
 *  normal_x, normal_y, normal_z as nx, ny, nz; any other field by its name and type, e.g. float quality; padding
 *  fields "_" skipped), then the faces as lists of int vertex indices. InvalidInputError naming \a path for a field
 *  of several values or of a 64-bit integer type (PLY has none), or a polygon of more than 255 corners.
 *  \param[in] path the file the bytes are for, for messages
 *  \param[in] mesh the mesh
 *  \return the file's bytes
 */
std::string
plyMeshBytes (const std::string& path, const pcl::PolygonMesh& mesh);
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private to the mesh and coloured surface loaders: a mesh file read by the reader of its (already checked) format.
#include <morphreg/io/file_format.h>

#include <pcl/PolygonMesh.h>

#include <string>

namespace morphreg
{
/** The extensions loadPolygonMesh() reads. */
inline constexpr const char* kMeshExtensions = ".ply .obj .vtk .stl .off .gltf .glb";

/** \a path read by the reader of \a format (checkGeometryFile's answer): vertices, with normals and colours where the
 *  file has them, and polygons, none for a file of points. FormatError naming the file if the reader fails. */
pcl::PolygonMesh
readPolygonFile (const std::string& path, FileFormat format);
} // namespace morphreg

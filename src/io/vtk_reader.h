// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private: morphreg's own reader of legacy VTK POLYDATA files (VTK's dereferences null on some malformed files),
// shared by the mesh loader and validateGeometryFile.
#include <pcl/PolygonMesh.h>

#include <string>

namespace morphreg
{
/** A legacy VTK POLYDATA file (ASCII or BINARY, the classic cell layout or format 5's OFFSETS and CONNECTIVITY): its
 *  points and its polygons, triangle strips cut into triangles (vertices, lines and the point and cell attributes
 *  are checked and skipped). FormatError naming the file (and the line, in ASCII) of a bad header, a count beyond
 *  what the file holds, a coordinate that is not finite, or a cell index beyond the points.
 */
pcl::PolygonMesh
readVtkFile (const std::string& path);
} // namespace morphreg

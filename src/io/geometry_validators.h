// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private: one structural validator per format (src/io/<format>_validation.cpp), each throwing FormatError naming the
// file (and line) on the first problem. validateGeometryFile (file_validation.h) chooses among them by content.
#include <string>

namespace morphreg
{
namespace validation
{
/** A PLY file: header, element counts against the file size, then the data (binary walked, ASCII parsed). */
void
validatePlyFile (const std::string& path);

/** A PCD file, read by morphreg's PCD reader (pcd_reader.cpp) without keeping its points; binary data, which any
 *  bytes are, is only checked to fit in the file. */
void
validatePcdFile (const std::string& path);

/** An OBJ file: every v, vn, vt and f line, and the face indices against the vertex count. */
void
validateObjFile (const std::string& path);

/** An ASCII STL file: its grammar, with finite vertex coordinates. */
void
validateAsciiStlFile (const std::string& path);

} // namespace validation
} // namespace morphreg

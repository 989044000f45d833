// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file file_validation.h
 *  \brief Structural checks of mesh and cloud files before PCL's or VTK's readers see them: the format recognised from
 *  the content, sizes and counts in headers checked against the file's size, malformed lines reported with the file
 *  and line. Sizes read from a header never drive an allocation before they are checked against the file.
 *
 *  What each format must satisfy:
 *  - PLY: a well-formed header with at least one vertex; every element count fits in the file; binary data (lists walked row by row) ends
 *    within the file; ASCII rows have the right number of finite numbers; face indices lie in [0, vertex count).
 *  - PCD: read by morphreg's own reader (readPcdFile, pcd_reader.h; PCL's crashes on some malformed files): at
 *    least one point; FIELDS, SIZE, TYPE and COUNT of one length and valid types, with x, y and z as 4-byte floats;
 *    WIDTH * HEIGHT = POINTS; binary data fits in the file; binary_compressed sizes agree with the file and with
 *    POINTS, and the data unpacks to them; ASCII rows have one number of its field's type per value.
 *  - OBJ: read by morphreg's own reader (readObjFile; PCL's crashes on some malformed files): v has 3, 4 or 6 finite
 *    numbers, vn 3, vt 1 to 3; faces have at least 3 corners whose indices (v, v/t, v//n, v/t/n, negative =
 *    relative) are in range.
 *  - STL: binary files are exactly 84 + 50 N bytes; ASCII files follow solid / facet normal / outer loop / 3 vertex
 *    / endloop / endfacet / endsolid with finite coordinates.
 *  - VTK legacy: read by morphreg's own reader (readVtkFile; VTK's dereferences null on some malformed files):
 *    ASCII or BINARY POLYDATA; finite point coordinates; POINTS n has its 3n values; VERTICES, LINES, POLYGONS and
 *    TRIANGLE_STRIPS have consistent sizes (the classic layout or OFFSETS/CONNECTIVITY) and indices below n; the
 *    attributes after them (NORMALS, SCALARS, FIELD, ...) hold the values their headers claim.
 *  - OFF: read by morphreg's own reader, which checks every count, coordinate and index as it reads.
 *  - glTF and GLB: read by readGltfFile (gltf_reader.h), which checks the GLB header and chunks against the file,
 *    the JSON, buffers and buffer views before tinygltf parses it, then every accessor, index, node and Draco payload
 *    as it reads.
 */
#include <morphreg/io/file_format.h>

#include <string>

namespace morphreg
{
/** \brief Checks that \a path holds a complete, well-formed mesh or cloud file of a supported format, whatever its
 *  name says. Used after writing a file to detect a truncated write, and by the loaders. Throws IoError if the
 *  file is missing or unreadable, FormatError naming the file (and the line where there is one) and the problem
 *  otherwise: unknown content, a header claiming more than the file holds, a cut-off file, a malformed line.
 *  \param[in] path the file
 *  \return its format, as recognised from the content
 */
FileFormat
validateGeometryFile (const std::string& path);

/** \brief The loaders' gate: \a path must be a readable file with one of the \a allowed extensions, whose content is
 *  the format its extension names (a PLY named .pcd is a FormatError that says so), and which passes
 *  validateGeometryFile(). OFF, PCD, VTK, glTF and GLB files are only recognised here: morphreg's readers of
 *  them check them as they read.
 *  \param[in] path the file
 *  \param[in] allowed the accepted extensions, space-separated, with their dots (e.g. ".ply .obj")
 *  \param[in] what what the file should hold (e.g. "mesh"), for the messages
 *  \return the file's format
 */
FileFormat
checkGeometryFile (const std::string& path, const std::string& allowed, const std::string& what);

} // namespace morphreg

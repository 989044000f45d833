// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file file_format.h
 *  \brief Recognising a mesh or cloud file's format from its content, so that a file whose name lies (a PLY renamed
 *  to .pcd) is never handed to the wrong library reader.
 */
#include <morphreg/common/length_unit.h>

#include <optional>
#include <string>

namespace morphreg
{
/** \brief The mesh and cloud formats morphreg reads, as recognised from a file's first bytes. */
enum class FileFormat
{
  Ply,       ///< Stanford PLY (ASCII or binary): starts with the line "ply"
  Pcd,       ///< PCL's point cloud data: a header of keywords such as VERSION, FIELDS, ..., DATA
  Obj,       ///< Wavefront OBJ: lines starting with v, vn, vt, f, o, g, ...
  StlAscii,  ///< ASCII STL: starts with "solid"
  StlBinary, ///< binary STL: 80 header bytes, a triangle count N, and exactly 50 bytes per triangle
  VtkLegacy, ///< VTK's legacy format: starts with "# vtk DataFile Version"
  Off,       ///< Object File Format: starts with the word OFF (or a variant such as COFF)
  Gltf,      ///< glTF 2.0 as JSON text (.gltf): starts with '{' (after white space or a byte order mark)
  Glb,       ///< binary glTF 2.0 (.glb): starts with the magic bytes "glTF"
  Unknown    ///< none of the above
};

/** \brief Recognises the format of \a path from its content (its first 64 KB, and its size for binary STL);
 *  the file's name plays no part. Throws IoError if the file cannot be read.
 *  \param[in] path the file
 *  \return the format, FileFormat::Unknown if the content is none of the supported formats
 */
FileFormat
sniffFileFormat (const std::string& path);

/** \brief The format's name for messages: "PLY", "PCD", "OBJ", "STL", "VTK", "OFF", "glTF", "GLB" or "unknown".
 *  \param[in] format the format
 *  \return its name
 */
std::string
fileFormatName (FileFormat format);

/** \brief The extension, with its dot, that files of \a format have (".ply", ".stl", ".gltf", ".glb", ...; "" for
 *  Unknown).
 *  \param[in] format the format
 *  \return the extension
 */
std::string
fileFormatExtension (FileFormat format);

/** \brief The length unit \a format fixes by specification, which morphreg's reader converts to mm: the metre for
 *  glTF and GLB; none for the formats that leave the unit to the file's writer (PLY, PCD, OBJ, STL, VTK, OFF).
 *  \param[in] format the format
 *  \return the unit, or none
 */
std::optional<LengthUnit>
specifiedLengthUnit (FileFormat format);

} // namespace morphreg

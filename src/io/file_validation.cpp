// SPDX-License-Identifier: BSD-3-Clause
#include "geometry_validators.h"
#include "off_reader.h"
#include "vtk_reader.h"

#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/file_validation.h>
#include <morphreg/io/gltf_reader.h>

#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>

namespace morphreg
{
namespace
{
/** Content that is none of the supported formats; for a .stl, why it is neither kind of STL. */
FormatError
unknownContent (const std::string& path)
{
  const std::string ext = fileExtension (path);
  const std::uint64_t size = std::filesystem::file_size (path);
  unsigned char count_bytes[4] = {0, 0, 0, 0};
  std::ifstream stream (path, std::ios::binary);
  if (ext == ".stl" && size >= 84 && stream.seekg (80) && stream.read (reinterpret_cast<char*> (count_bytes), 4)) {
    const std::uint64_t triangles =
        count_bytes[0] | count_bytes[1] << 8 | count_bytes[2] << 16 | static_cast<std::uint64_t> (count_bytes[3]) << 24;
    return FormatError (path + ": not an STL file: it does not start with 'solid' (ASCII STL), and its " +
                        std::to_string (size) + " bytes are not the 84 + 50 x " + std::to_string (triangles) + " = " +
                        std::to_string (84 + 50 * triangles) + " bytes of a binary STL with the " +
                        std::to_string (triangles) + " triangles its header gives (the file is cut short or corrupt)");
  }
  if (ext == ".glb")
    return FormatError (path + ": not a GLB file: it does not start with the magic bytes 'glTF'");
  return FormatError (path + ": the content is none of the supported mesh and cloud formats (PLY, PCD, OBJ, STL, "
                             "VTK legacy, OFF, glTF, GLB)");
}

/** The formats PCL and VTK read: checked before their readers see the file. */
void
validateForLibraryReader (const std::string& path, FileFormat format)
{
  switch (format) {
  case FileFormat::Ply:
    validation::validatePlyFile (path);
    break;
  case FileFormat::Obj:
    validation::validateObjFile (path);
    break;
  case FileFormat::StlAscii:
    validation::validateAsciiStlFile (path);
    break;
  case FileFormat::StlBinary: // recognised by its size being exactly what its triangle count needs
    if (std::filesystem::file_size (path) == 84)
      throw FormatError (path + ": the STL file has no triangles (its triangle count is 0)");
    break;
  case FileFormat::Pcd: // read by morphreg's own readers, which check as they read
  case FileFormat::VtkLegacy:
  case FileFormat::Off:
  case FileFormat::Gltf:
  case FileFormat::Glb:
  case FileFormat::Unknown:
    break;
  }
}
} // namespace

FileFormat
validateGeometryFile (const std::string& path)
{
  requireReadableFile (path);
  const FileFormat format = sniffFileFormat (path);
  if (format == FileFormat::Unknown)
    throw unknownContent (path);
  if (format == FileFormat::Off)
    readOffMesh (path);
  else if (format == FileFormat::Gltf || format == FileFormat::Glb)
    readGltfFile (path);
  else if (format == FileFormat::VtkLegacy)
    readVtkFile (path);
  else if (format == FileFormat::Pcd)
    validation::validatePcdFile (path);
  else
    validateForLibraryReader (path, format);
  return format;
}

FileFormat
checkGeometryFile (const std::string& path, const std::string& allowed, const std::string& what)
{
  requireReadableFile (path);
  requireExtension (path, allowed, what);
  const FileFormat format = sniffFileFormat (path);
  if (format == FileFormat::Unknown)
    throw unknownContent (path);
  const std::string ext = fileExtension (path);
  const std::string actual_ext = fileFormatExtension (format);
  if (actual_ext != ext) {
    std::string named = ext.substr (1);
    for (char& c : named)
      c = static_cast<char> (std::toupper (static_cast<unsigned char> (c)));
    const bool allowed_format = (" " + allowed + " ").find (" " + actual_ext + " ") != std::string::npos;
    throw FormatError (
        path + ": the content is a " + fileFormatName (format) + " file, not " + named +
        (allowed_format ? "; rename it to " + actual_ext : "; a " + what + " must be one of " + allowed));
  }
  validateForLibraryReader (path, format);
  return format;
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/file_format.h>

#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace morphreg
{
namespace
{
/** The first line of \a prefix that is neither blank nor a '#' comment, as its first word; "" if there is none. */
std::string
firstWord (const std::string& prefix)
{
  std::istringstream lines (prefix);
  for (std::string line; std::getline (lines, line);) {
    std::istringstream words (line);
    std::string word;
    if (words >> word && word[0] != '#')
      return word;
  }
  return "";
}

/** OFF and its variants: [ST][C][N][4][n]OFF. */
bool
isOffKeyword (const std::string& word)
{
  if (word.size () < 3 || word.compare (word.size () - 3, 3, "OFF") != 0)
    return false;
  return word.substr (0, word.size () - 3).find_first_not_of ("STCN4n") == std::string::npos;
}

FileFormat
sniffText (const std::string& prefix)
{
  static const std::set<std::string> pcd_keywords = {"VERSION", "FIELDS", "COLUMNS",   "SIZE",   "TYPE", "COUNT",
                                                     "WIDTH",   "HEIGHT", "VIEWPOINT", "POINTS", "DATA"};
  static const std::set<std::string> obj_keywords = {"v", "vn", "vt", "vp", "f",      "l",
                                                     "p", "o",  "g",  "s",  "mtllib", "usemtl"};
  const std::string word = firstWord (prefix);
  if (pcd_keywords.count (word))
    return FileFormat::Pcd;
  if (isOffKeyword (word))
    return FileFormat::Off;
  if (obj_keywords.count (word))
    return FileFormat::Obj;
  return FileFormat::Unknown;
}

bool
startsWith (const std::string& text, const std::string& start)
{
  return text.compare (0, start.size (), start) == 0;
}

/** Binary STL: the triangle count in bytes 80 to 83 (little endian) accounts for the file's size exactly. */
bool
isBinaryStl (const std::string& prefix, std::uint64_t size)
{
  if (prefix.size () < 84)
    return false;
  std::uint64_t count = 0;
  for (int i = 3; i >= 0; --i)
    count = (count << 8) | static_cast<unsigned char> (prefix[80 + i]);
  return size == 84 + 50 * count;
}
} // namespace

FileFormat
sniffFileFormat (const std::string& path)
{
  std::ifstream stream (path, std::ios::binary);
  std::error_code ec;
  const std::uint64_t size = std::filesystem::file_size (path, ec);
  if (!stream || ec)
    throw IoError (path + ": cannot be opened for reading");
  std::string prefix (65536, '\0');
  stream.read (&prefix[0], static_cast<std::streamsize> (prefix.size ()));
  prefix.resize (static_cast<std::size_t> (stream.gcount ()));
  if (startsWith (prefix, "ply\n") || startsWith (prefix, "ply\r\n"))
    return FileFormat::Ply;
  if (startsWith (prefix, "# vtk DataFile Version"))
    return FileFormat::VtkLegacy;
  if (startsWith (prefix, "glTF"))
    return FileFormat::Glb;
  if (isBinaryStl (prefix, size))
    return FileFormat::StlBinary;
  const std::size_t start = prefix.find_first_not_of (" \t\r\n", startsWith (prefix, "\xEF\xBB\xBF") ? 3 : 0);
  if (start != std::string::npos && prefix[start] == '{')
    return FileFormat::Gltf;
  if (start != std::string::npos && prefix.compare (start, 5, "solid") == 0 &&
      (prefix.size () == start + 5 || std::isspace (static_cast<unsigned char> (prefix[start + 5]))))
    return FileFormat::StlAscii;
  return sniffText (prefix);
}

std::string
fileFormatName (FileFormat format)
{
  switch (format) {
  case FileFormat::Ply:
    return "PLY";
  case FileFormat::Pcd:
    return "PCD";
  case FileFormat::Obj:
    return "OBJ";
  case FileFormat::StlAscii:
  case FileFormat::StlBinary:
    return "STL";
  case FileFormat::VtkLegacy:
    return "VTK";
  case FileFormat::Off:
    return "OFF";
  case FileFormat::Gltf:
    return "glTF";
  case FileFormat::Glb:
    return "GLB";
  case FileFormat::Unknown:
    break;
  }
  return "unknown";
}

std::string
fileFormatExtension (FileFormat format)
{
  if (format == FileFormat::Unknown)
    return "";
  std::string extension = "." + fileFormatName (format);
  for (char& c : extension)
    c = static_cast<char> (std::tolower (static_cast<unsigned char> (c)));
  return extension;
}

std::optional<LengthUnit>
specifiedLengthUnit (FileFormat format)
{
  if (format == FileFormat::Gltf || format == FileFormat::Glb)
    return LengthUnit::metre;
  return std::nullopt;
}

} // namespace morphreg

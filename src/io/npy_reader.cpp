// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/npy_reader.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <regex>
#include <sstream>

namespace morphreg
{
namespace
{
std::string
shapeText (const std::vector<std::size_t>& shape)
{
  std::ostringstream text;
  text << '(';
  for (std::size_t i = 0; i < shape.size (); ++i)
    text << (i ? ", " : "") << shape[i];
  text << ')';
  return text.str ();
}

/** Value of \a key in the header dict (a Python literal up to the next top-level comma), or "". */
std::string
headerEntry (const std::string& header, const std::string& key)
{
  const std::regex pattern ("['\"]" + key + "['\"]\\s*:\\s*(\\([^)]*\\)|'[^']*'|\"[^\"]*\"|True|False)");
  std::smatch match;
  return std::regex_search (header, match, pattern) ? match[1].str () : std::string ();
}

std::vector<std::size_t>
parseShape (const std::string& literal, const std::string& path)
{
  std::vector<std::size_t> shape;
  std::string inner = literal.substr (1, literal.size () - 2);
  std::istringstream items (inner);
  for (std::string item; std::getline (items, item, ',');) {
    item.erase (0, item.find_first_not_of (" \t"));
    item.erase (item.find_last_not_of (" \t") + 1);
    if (item.empty ())
      continue;
    if (item.find_first_not_of ("0123456789") != std::string::npos || item.size () > 15)
      throw FormatError (path + ": npy header has an invalid shape " + literal);
    shape.push_back (static_cast<std::size_t> (std::stoull (item)));
  }
  return shape;
}
} // namespace

NpyArray
readNpyFloat32 (const std::string& path)
{
  requireReadableFile (path);
  std::ifstream stream (path, std::ios::binary | std::ios::ate);
  const auto file_size = static_cast<std::uint64_t> (stream.tellg ());
  stream.seekg (0);

  char preamble[8];
  if (file_size < 10 || !stream.read (preamble, 8) || std::memcmp (preamble, "\x93NUMPY", 6) != 0)
    throw FormatError (path + ": not a NumPy .npy file (magic string \\x93NUMPY missing)");
  const int major = static_cast<unsigned char> (preamble[6]);
  if (major < 1 || major > 3)
    throw FormatError (path + ": unsupported .npy format version " + std::to_string (major));
  const int length_bytes = major == 1 ? 2 : 4;
  unsigned char length_field[4] = {0, 0, 0, 0};
  if (!stream.read (reinterpret_cast<char*> (length_field), length_bytes))
    throw FormatError (path + ": truncated .npy preamble");
  const std::uint64_t header_length = length_field[0] | (length_field[1] << 8) |
                                      (static_cast<std::uint64_t> (length_field[2]) << 16) |
                                      (static_cast<std::uint64_t> (length_field[3]) << 24);
  const std::uint64_t data_offset = 6 + 2 + length_bytes + header_length;
  if (data_offset > file_size)
    throw FormatError (path + ": .npy header length " + std::to_string (header_length) +
                       " runs past the end of the file");
  std::string header (header_length, '\0');
  stream.read (header.data (), static_cast<std::streamsize> (header_length));

  const std::string descr = headerEntry (header, "descr");
  if (descr.size () < 2 || descr.substr (1, descr.size () - 2) != "<f4")
    throw FormatError (path + ": .npy dtype is " + (descr.empty () ? std::string ("missing") : descr) +
                       ", expected '<f4' (little-endian float32)");
  const std::string fortran = headerEntry (header, "fortran_order");
  if (fortran != "False")
    throw FormatError (path + ": .npy array must be in C order (fortran_order is " +
                       (fortran.empty () ? std::string ("missing") : fortran) + ")");
  const std::string shape_literal = headerEntry (header, "shape");
  if (shape_literal.empty ())
    throw FormatError (path + ": .npy header has no shape");

  NpyArray array;
  array.shape = parseShape (shape_literal, path);
  std::uint64_t count = 1;
  for (const std::size_t extent : array.shape) {
    if (extent != 0 && count > (std::uint64_t (1) << 40) / extent)
      throw FormatError (path + ": .npy shape " + shapeText (array.shape) + " is implausibly large");
    count *= extent;
  }
  const std::uint64_t data_bytes = file_size - data_offset;
  if (data_bytes != count * 4) {
    std::ostringstream msg;
    msg << path << ": shape " << shapeText (array.shape) << " needs " << count * 4 << " data bytes, the file has "
        << data_bytes << (data_bytes < count * 4 ? " (truncated)" : " (trailing bytes)");
    throw FormatError (msg.str ());
  }
  array.data.resize (count);
  if (!stream.read (reinterpret_cast<char*> (array.data.data ()), static_cast<std::streamsize> (count * 4)))
    throw IoError (path + ": read error in the .npy data");
  for (std::size_t i = 0; i < array.data.size (); ++i)
    if (!std::isfinite (array.data[i]))
      throw FormatError (path + ": element " + std::to_string (i) + " is not finite (NaN or Inf)");
  return array;
}

void
requireNpyShape (const NpyArray& array, const std::vector<std::size_t>& expected_shape, const std::string& path)
{
  if (array.shape != expected_shape)
    throw FormatError (path + ": array shape " + shapeText (array.shape) + ", expected " + shapeText (expected_shape));
}

} // namespace morphreg

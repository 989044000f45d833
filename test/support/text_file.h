// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Writing a small test file from a string, and reading a file back as bytes.
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace morphreg
{
namespace test
{
/** Writes \a text to \a path byte for byte, creating its folder if needed. */
inline void
writeText (const std::string& path, const std::string& text)
{
  std::filesystem::create_directories (std::filesystem::path (path).parent_path ());
  std::ofstream (path, std::ios::binary) << text;
}

/** The bytes of the file at \a path (empty if it cannot be read). */
inline std::string
readBytes (const std::string& path)
{
  std::ifstream stream (path, std::ios::binary);
  return std::string (std::istreambuf_iterator<char> (stream), {});
}
} // namespace test
} // namespace morphreg

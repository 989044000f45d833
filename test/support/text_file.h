#pragma once
// Writing a small test file from a string.
#include <filesystem>
#include <fstream>
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
} // namespace test
} // namespace morphreg

#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace morphreg
{
void
requireReadableFile (const std::string& path)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  if (!fs::exists (path, ec))
    throw IoError (path + ": no such file");
  if (fs::is_directory (path, ec))
    throw IoError (path + ": is a directory, expected a file");
  std::ifstream stream (path, std::ios::binary);
  if (!stream)
    throw IoError (path + ": cannot be opened for reading");
  if (fs::file_size (path, ec) == 0)
    throw FormatError (path + ": file is empty");
}

std::string
fileExtension (const std::string& path)
{
  std::string ext = std::filesystem::path (path).extension ().string ();
  std::transform (ext.begin (), ext.end (), ext.begin (), [] (unsigned char c) { return std::tolower (c); });
  return ext;
}

void
requireExtension (const std::string& path, const std::string& allowed, const std::string& what)
{
  const std::string ext = fileExtension (path);
  std::istringstream options (allowed);
  for (std::string option; options >> option;)
    if (option == ext)
      return;
  throw IoError (path + ": unsupported " + what + " format '" + ext + "' (supported: " + allowed + ")");
}

} // namespace morphreg

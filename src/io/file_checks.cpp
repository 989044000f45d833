// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <unistd.h>

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

void
requireWritableOutput (const std::string& path)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  if (path.empty ())
    throw IoError ("an output file name is empty");
  if (fs::is_directory (path, ec))
    throw IoError (path + ": is a directory, expected a file name to write");
  const fs::path folder = fs::path (path).parent_path ().empty () ? fs::path (".") : fs::path (path).parent_path ();
  if (!fs::exists (folder, ec))
    throw IoError (path + ": cannot be written: the folder " + folder.string () + " does not exist");
  if (!fs::is_directory (folder, ec))
    throw IoError (path + ": cannot be written: " + folder.string () + " is not a folder");
  if (::access (folder.c_str (), W_OK | X_OK) != 0)
    throw IoError (path + ": cannot be written: no permission to write in " + folder.string ());
}

void
requireNotAnInput (const std::string& output, const std::vector<std::string>& inputs)
{
  namespace fs = std::filesystem;
  std::error_code output_error;
  const fs::path target = fs::weakly_canonical (output, output_error);
  for (const std::string& input : inputs) {
    if (input.empty ())
      continue;
    std::error_code input_error, link_error;
    const fs::path source = fs::weakly_canonical (input, input_error);
    const bool same_name = !output_error && !input_error && source == target;
    if (same_name || fs::equivalent (output, input, link_error))
      throw InvalidInputError (output + ": is also an input (" + input +
                               "); writing it would overwrite that input, choose another output file");
  }
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

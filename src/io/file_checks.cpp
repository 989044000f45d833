// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

namespace morphreg
{
void
requireReadableFile (const std::string& path, std::uintmax_t max_bytes)
{
  struct stat status;
  if (::stat (path.c_str (), &status) != 0)
    throw IoError (path + (errno == ENOENT || errno == ENOTDIR ? ": no such file" : ": cannot be read"));
  if (S_ISDIR (status.st_mode))
    throw IoError (path + ": is a directory, expected a file");
  if (!S_ISREG (status.st_mode))
    throw IoError (path + ": is not a regular file (" +
                   (S_ISFIFO (status.st_mode)  ? "a FIFO"
                    : S_ISCHR (status.st_mode) ? "a character device"
                    : S_ISBLK (status.st_mode) ? "a block device"
                                               : "a socket") +
                   "); give a file");
  if (::access (path.c_str (), R_OK) != 0)
    throw IoError (path + ": cannot be opened for reading");
  if (status.st_size == 0)
    throw FormatError (path + ": file is empty");
  if (static_cast<std::uintmax_t> (status.st_size) > max_bytes)
    throw FormatError (path + ": " + std::to_string (status.st_size) + " bytes, more than the " +
                       std::to_string (max_bytes >> 20) + " MiB a file of this kind may have: is it the right file?");
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

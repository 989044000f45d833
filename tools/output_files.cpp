// SPDX-License-Identifier: BSD-3-Clause
#include "output_files.h"

#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>

namespace morphreg
{
namespace tools
{
namespace
{
/** The inode of \a path, 0 if there is no such file. */
ino_t
inodeOf (const std::string& path)
{
  struct stat status;
  return ::stat (path.c_str (), &status) == 0 ? status.st_ino : 0;
}

std::vector<std::string>
filesIn (const std::string& folder)
{
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator (folder, ec))
    files.push_back (entry.path ().string ());
  std::sort (files.begin (), files.end ());
  return files;
}
} // namespace

OutputFiles::OutputFiles (const std::vector<std::string>& outputs, const std::vector<std::string>& inputs)
{
  for (const std::string& path : outputs) {
    if (path.empty ())
      continue;
    requireWritableOutput (path);
    requireNotAnInput (path, inputs);
    std::vector<std::string> earlier;
    for (const Output& output : outputs_)
      earlier.push_back (output.path);
    if (!earlier.empty ()) // two outputs on one file: the second would overwrite the first
      requireNotAnInput (path, earlier);
    outputs_.push_back ({path, inodeOf (path)});
  }
}

OutputFiles::~OutputFiles ()
{
  if (keep_)
    return;
  for (const Output& output : outputs_) {
    const ino_t now = inodeOf (output.path);
    std::error_code ec;
    if (now != 0 && now != output.inode)
      std::filesystem::remove (output.path, ec);
  }
}

void
OutputFiles::keep ()
{
  keep_ = true;
}

OutputFolder::OutputFolder (const std::string& path, const std::vector<std::string>& inputs) : path_ (path)
{
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists (path, ec) && !fs::is_directory (path, ec))
    throw IoError (path + ": exists and is not a folder; give a folder for the output");
  // The outermost folder this run would create: removed again if the run fails.
  fs::path created = fs::absolute (path, ec).lexically_normal ();
  while (created.has_parent_path () && created.parent_path () != created && !fs::exists (created.parent_path (), ec))
    created = created.parent_path ();
  if (fs::exists (created, ec))
    created.clear ();
  created_ = created.string ();
  const fs::path existing = created_.empty () ? fs::path (path) : created.parent_path ();
  if (!fs::is_directory (existing, ec))
    throw IoError (path + ": cannot be created: " + existing.string () + " is not a folder");
  if (::access (existing.c_str (), W_OK | X_OK) != 0)
    throw IoError (path + ": cannot be written: no permission to write in " + existing.string ());
  requireNotAnInput (path, inputs);
  if (created_.empty ())
    files_before_ = filesIn (path);
}

OutputFolder::~OutputFolder ()
{
  if (keep_)
    return;
  std::error_code ec;
  if (!created_.empty ()) {
    std::filesystem::remove_all (created_, ec);
    return;
  }
  for (const std::string& file : filesIn (path_))
    if (!std::binary_search (files_before_.begin (), files_before_.end (), file))
      std::filesystem::remove_all (file, ec);
}

void
OutputFolder::keep ()
{
  keep_ = true;
}
} // namespace tools
} // namespace morphreg

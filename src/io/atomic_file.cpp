// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>
#include <morphreg/io/file_validation.h>

#include <filesystem>
#include <fstream>

namespace morphreg
{
std::string
partialPath (const std::string& path)
{
  const std::filesystem::path target (path);
  return (target.parent_path () / (".partial." + target.filename ().string ())).string ();
}

void
commitPartial (const std::string& partial, const std::string& path)
{
  std::error_code ec;
  std::filesystem::rename (partial, path, ec);
  if (ec)
    throw IoError (path + ": cannot rename the finished " + partial + " onto it (" + ec.message () + ")");
}

void
requireCompletelyWritten (const std::string& written, const std::string& path)
{
  try {
    validateGeometryFile (written);
  }
  catch (const IoError& e) {
    throw IoError (path + ": was not written completely (disk full, or a file size limit?): " + e.what ());
  }
}

void
writeFileAtomically (const std::string& path, const std::string& content)
{
  writeAtomically (path, [&] (const std::string& partial) {
    std::ofstream stream (partial, std::ios::binary | std::ios::trunc);
    stream.write (content.data (), static_cast<std::streamsize> (content.size ()));
    stream.close ();
    if (!stream)
      throw IoError (path + ": cannot be written (disk full, or no permission?)");
  });
}

} // namespace morphreg

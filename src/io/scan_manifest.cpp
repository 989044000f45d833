// SPDX-License-Identifier: BSD-3-Clause
#include "text_fields.h"

#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/scan_manifest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace morphreg
{
namespace
{
namespace fs = std::filesystem;

const char* const kScanExtensions = ".pcd .ply .obj .stl .off .gltf .glb";

/** True if \a path has one of kScanExtensions. */
bool
isScanFile (const fs::path& path)
{
  std::istringstream extensions (kScanExtensions);
  for (std::string ext; extensions >> ext;)
    if (fileExtension (path.string ()) == ext)
      return true;
  return false;
}

/** \a path as given if absolute, else relative to \a base. */
std::string
resolve (const std::string& path, const fs::path& base)
{
  return path.empty () || fs::path (path).is_absolute () ? path : (base / path).lexically_normal ().string ();
}

/** Ids name output files: no folder separators, no leading dot, not empty. */
void
requirePlainId (const ScanEntry& entry)
{
  if (entry.id.empty () || entry.id.front () == '.' || entry.id.find_first_of ("/\\") != std::string::npos)
    throw FormatError (entry.where + ": id '" + entry.id +
                       "' must be a plain file name (it names the scan's outputs): no '/', no leading '.'");
}

void
requireUniqueIds (const ScanManifest& manifest)
{
  std::map<std::string, std::string> first_seen;
  for (const ScanEntry& entry : manifest) {
    requirePlainId (entry);
    const auto [it, inserted] = first_seen.emplace (entry.id, entry.where);
    if (!inserted)
      throw FormatError (entry.where + ": duplicate scan id '" + entry.id + "' (first at " + it->second +
                         "); give each row a unique id in the third column");
  }
}
} // namespace

ScanManifest
loadScanManifest (const std::string& path)
{
  requireReadableFile (path, kMaxTextFileBytes);
  std::ifstream stream (path);
  const fs::path base = fs::path (path).parent_path ();
  ScanManifest manifest;
  int line_number = 0;
  for (std::string line; std::getline (stream, line);) {
    ++line_number;
    if (line_number == 1 && line.rfind ("\xEF\xBB\xBF", 0) == 0) // a UTF-8 byte order mark
      line.erase (0, 3);
    line = text::trim (line);
    if (line.empty () || line.front () == '#')
      continue;
    const std::vector<std::string> fields = text::splitCsvFields (line);
    if (manifest.empty () && fields[0] == "scan")
      continue; // the header
    const std::string where = path + ":" + std::to_string (line_number);
    if (fields.size () > 3)
      throw FormatError (where + ": " + std::to_string (fields.size ()) + " fields, expected scan[,landmarks[,id]]");
    if (fields[0].empty ())
      throw FormatError (where + ": the scan path is empty");
    ScanEntry entry;
    entry.scan = resolve (fields[0], base);
    entry.landmarks = fields.size () > 1 ? resolve (fields[1], base) : "";
    entry.id = fields.size () > 2 && !fields[2].empty () ? fields[2] : fs::path (fields[0]).stem ().string ();
    entry.where = where;
    manifest.push_back (entry);
  }
  if (manifest.empty ())
    throw FormatError (path + ": no scans listed (rows: scan[,landmarks[,id]])");
  requireUniqueIds (manifest);
  return manifest;
}

ScanManifest
listScanDirectory (const std::string& directory)
{
  std::error_code ec;
  if (!fs::is_directory (directory, ec))
    throw IoError (directory + ": no such folder");
  std::vector<fs::path> files;
  for (const auto& item : fs::directory_iterator (directory))
    if (item.is_regular_file () && isScanFile (item.path ()))
      files.push_back (item.path ());
  std::sort (files.begin (), files.end ());
  ScanManifest manifest;
  for (const fs::path& file : files) {
    ScanEntry entry{file.stem ().string (), file.string (), "", directory};
    for (const char* ext : {".json", ".pp", ".csv", ".pts"}) {
      const fs::path landmarks = file.parent_path () / (entry.id + "_landmarks" + ext);
      if (fs::is_regular_file (landmarks, ec)) {
        entry.landmarks = landmarks.string ();
        break;
      }
    }
    manifest.push_back (entry);
  }
  if (manifest.empty ())
    throw FormatError (directory + ": no scans in the folder (" + kScanExtensions + ")");
  requireUniqueIds (manifest);
  return manifest;
}

ScanManifest
loadScanList (const std::string& directory_or_manifest)
{
  std::error_code ec;
  return fs::is_directory (directory_or_manifest, ec) ? listScanDirectory (directory_or_manifest)
                                                      : loadScanManifest (directory_or_manifest);
}

ScanManifest
manifestShard (const ScanManifest& manifest, int index, int count)
{
  if (count < 1 || index < 0 || index >= count)
    throw InvalidInputError ("shard " + std::to_string (index) + "/" + std::to_string (count) +
                             ": the index must be in [0, " + std::to_string (count) + ")");
  ScanManifest shard;
  for (std::size_t k = static_cast<std::size_t> (index); k < manifest.size (); k += static_cast<std::size_t> (count))
    shard.push_back (manifest[k]);
  return shard;
}

} // namespace morphreg

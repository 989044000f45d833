// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/file_fingerprint.h>
#include <morphreg/pipeline/batch_provenance.h>

#include <set>

namespace morphreg
{
namespace
{
/** A file's path and content hash; null for no file; a file that cannot be read gets its error instead. */
nlohmann::json
fileRecord (const std::string& path)
{
  if (path.empty ())
    return nullptr;
  try {
    return {{"file", path}, {"fnv1a64", hashFile (path)}};
  }
  catch (const Error& e) {
    return {{"file", path}, {"fnv1a64", nullptr}, {"error", e.what ()}};
  }
}

/** The settings that shape a scan's outputs: the registration's and the fitted mesh's colour scale. */
nlohmann::json
settingsRecord (const ScanFileSettings& options)
{
  nlohmann::json settings = toJson (static_cast<const RegistrationSettings&> (options));
  settings["colour_max_mm"] = options.colour_max;
  return settings;
}

nlohmann::json
field (const nlohmann::json& record, const char* key)
{
  return record.is_object () && record.contains (key) ? record[key] : nlohmann::json ();
}

std::string
describeFile (const nlohmann::json& file)
{
  if (!file.is_object ())
    return "none";
  const nlohmann::json hash = field (file, "fnv1a64");
  return field (file, "file").dump () +
         (hash.is_string () ? " (fnv1a64 " + hash.get<std::string> () + ")" : " (unreadable)");
}

/** Why the file records differ ("what changed: now ..., in the report ..."), or empty if they hold the same bytes. */
std::string
fileMismatch (const std::string& what, const nlohmann::json& expected, const nlohmann::json& found,
              const std::string& expected_is, const std::string& found_is)
{
  if (expected.is_null () == found.is_null () && field (expected, "fnv1a64") == field (found, "fnv1a64"))
    return "";
  return what + ": " + describeFile (expected) + " " + expected_is + ", " + describeFile (found) + " " + found_is;
}

/** The settings that differ, "name now (name in the report)", or empty. */
std::string
settingsMismatch (const nlohmann::json& expected, const nlohmann::json& found, const std::string& expected_is,
                  const std::string& found_is)
{
  std::set<std::string> keys;
  for (const nlohmann::json* settings : {&expected, &found})
    if (settings->is_object ())
      for (const auto& item : settings->items ())
        keys.insert (item.key ());
  std::string changed;
  for (const std::string& key : keys)
    if (field (expected, key.c_str ()) != field (found, key.c_str ()))
      changed += (changed.empty () ? "" : ", ") + key + " " + field (expected, key.c_str ()).dump () + " " +
                 expected_is + ", " + field (found, key.c_str ()).dump () + " " + found_is;
  return changed.empty () ? "" : "made with other settings: " + changed;
}
} // namespace

RunRecord
runRecord (const std::string& model_file, const ScanFileSettings& settings, const ScanManifest& scans)
{
  RunRecord run;
  run.shared = {
      {"model", fileRecord (model_file)}, {"settings", settingsRecord (settings)}, {"version", MORPHREG_VERSION}};
  if (run.shared["model"]["fnv1a64"].is_null ())
    throw IoError (run.shared["model"]["error"].get<std::string> ());
  Fnv1a64 hash;
  hash.add (run.shared.dump ());
  for (const ScanEntry& entry : scans)
    hash.add ('\n' + entry.id);
  run.fingerprint = hash.hex ();
  return run;
}

nlohmann::json
scanRecord (const RunRecord& run, const ScanEntry& entry)
{
  nlohmann::json record = run.shared;
  record["scan"] = fileRecord (entry.scan);
  record["landmarks"] = fileRecord (entry.landmarks);
  return record;
}

std::string
recordMismatch (const nlohmann::json& expected, const nlohmann::json& found, const std::string& expected_is,
                const std::string& found_is)
{
  if (!found.is_object ())
    return "no record of what produced it " + found_is + " (written before morphreg kept records)";
  std::string why;
  const auto add = [&why] (const std::string& reason) {
    if (!reason.empty ())
      why += (why.empty () ? "" : "; ") + reason;
  };
  const auto files = [&] (const char* what, const char* key) {
    add (fileMismatch (what, field (expected, key), field (found, key), expected_is, found_is));
  };
  files ("the scan changed", "scan");
  files ("the landmarks changed", "landmarks");
  files ("made with another model", "model");
  add (settingsMismatch (field (expected, "settings"), field (found, "settings"), expected_is, found_is));
  if (field (found, "version") != field (expected, "version"))
    add ("made by morphreg " + field (found, "version").dump () + " " + found_is + ", " +
         field (expected, "version").dump () + " " + expected_is);
  return why;
}
} // namespace morphreg

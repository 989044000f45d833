// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>
#include <morphreg/io/json_file.h>
#include <morphreg/pipeline/batch_summary.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <iomanip>
#include <sstream>

namespace morphreg
{
namespace
{
/** The value at \a pointer ("/a/b") of \a json, or \a fallback if absent or of another type. */
template <typename T>
T
valueAt (const nlohmann::json& json, const std::string& pointer, T fallback)
{
  const nlohmann::json::json_pointer at (pointer);
  if (!json.contains (at))
    return fallback;
  const nlohmann::json& value = json.at (at);
  if constexpr (std::is_arithmetic_v<T>)
    return value.is_number () ? value.get<T> () : fallback;
  else
    return value.is_string () ? value.get<T> () : fallback;
}

/** Where a summary's fields are in a JSON document (JSON pointers). */
struct FieldPointers
{
  const char *status, *rms, *iterations, *seconds, *fit_seconds, *reason;
};

/** In a register report (or the failure record of a scan that threw). */
const FieldPointers kReportFields = {"/status",           "/residuals_mm/scan_to_model/rms",
                                     "/iterations/total", "/timings_s/total",
                                     "/timings_s/fit",    "/failure"};
/** In a row of summary.json. */
const FieldPointers kSummaryFields = {"/status", "/rms_mm", "/iterations", "/seconds", "/fit_seconds", "/reason"};

/** The status, RMS, iterations, timings and reason of a summary row, from \a json (missing fields: unknown). */
ScanSummary
rowFrom (const nlohmann::json& json, const FieldPointers& at)
{
  ScanSummary row;
  row.status = valueAt<std::string> (json, at.status, "failed");
  row.rms = valueAt (json, at.rms, row.rms);
  row.iterations = valueAt (json, at.iterations, row.iterations);
  row.seconds = valueAt (json, at.seconds, row.seconds);
  row.fit_seconds = valueAt (json, at.fit_seconds, row.fit_seconds);
  row.reason = valueAt<std::string> (json, at.reason, "");
  return row;
}

/** A number for JSON: null when not known. */
nlohmann::json
known (double value)
{
  return std::isfinite (value) ? nlohmann::json (value) : nlohmann::json ();
}

/** A CSV field: quoted when it holds a comma, a quote or a line break. */
std::string
csvField (const std::string& text)
{
  if (text.find_first_of (",\"\n") == std::string::npos)
    return text;
  std::string quoted = "\"";
  for (char c : text)
    quoted += c == '"' ? std::string ("\"\"") : std::string (1, c == '\n' ? ' ' : c);
  return quoted + "\"";
}

std::string
fixed (double value, int digits)
{
  if (!std::isfinite (value))
    return "";
  std::ostringstream text;
  text << std::fixed << std::setprecision (digits) << value;
  return text.str ();
}

std::string
csvText (const std::vector<ScanSummary>& rows)
{
  std::string text = "id,status,rms_mm,iterations,seconds,fit_seconds,scan,reason\n";
  for (const ScanSummary& row : rows)
    text += csvField (row.id) + "," + row.status + "," + fixed (row.rms, 4) + "," +
            (row.iterations < 0 ? "" : std::to_string (row.iterations)) + "," + fixed (row.seconds, 3) + "," +
            fixed (row.fit_seconds, 3) + "," + csvField (row.scan) + "," + csvField (row.reason) + "\n";
  return text;
}

nlohmann::json
summaryJson (const std::vector<ScanSummary>& rows, const std::string& shard, const nlohmann::json& run)
{
  nlohmann::json scans = nlohmann::json::array ();
  std::map<std::string, int> counts{{"ok", 0}, {"failed", 0}, {"pending", 0}};
  for (const ScanSummary& row : rows) {
    ++counts[row.status];
    scans.push_back ({{"id", row.id},
                      {"scan", row.scan},
                      {"status", row.status},
                      {"rms_mm", known (row.rms)},
                      {"iterations", row.iterations < 0 ? nlohmann::json () : nlohmann::json (row.iterations)},
                      {"seconds", known (row.seconds)},
                      {"fit_seconds", known (row.fit_seconds)},
                      {"reason", row.reason}});
  }
  return {{"shard", shard}, {"run", run}, {"total", rows.size ()}, {"counts", counts}, {"scans", scans}};
}
} // namespace

ScanSummary
summaryFromReport (const std::string& id, const std::string& scan, const nlohmann::json& report)
{
  ScanSummary row = rowFrom (report, kReportFields);
  row.id = id;
  row.scan = scan;
  if (row.reason.empty () && report.contains ("checks"))
    for (const auto& failure : report["checks"].value ("failures", nlohmann::json::array ()))
      row.reason += (row.reason.empty () ? "" : "; ") + failure.get<std::string> ();
  return row;
}

nlohmann::json
writeSummary (const std::string& base, std::vector<ScanSummary> rows, const std::string& shard,
              const nlohmann::json& run, const nlohmann::json& fields)
{
  std::sort (rows.begin (), rows.end (), [] (const ScanSummary& a, const ScanSummary& b) { return a.id < b.id; });
  nlohmann::json summary = summaryJson (rows, shard, run);
  for (const auto& field : fields.items ())
    summary[field.key ()] = field.value ();
  writeJsonFile (base + ".json", summary);
  writeFileAtomically (base + ".csv", csvText (rows));
  return summary;
}

std::vector<ScanSummary>
readSummary (const std::string& path, std::string* shard, nlohmann::json* run)
{
  const nlohmann::json document = readJsonFile (path);
  if (!document.is_object () || !document.contains ("scans") || !document["scans"].is_array ())
    throw FormatError (path + ": not a batch summary (no \"scans\" array, as a batch registration writes)");
  if (shard != nullptr)
    *shard = valueAt<std::string> (document, "/shard", "");
  if (run != nullptr)
    *run = document.value ("run", nlohmann::json ());
  std::vector<ScanSummary> rows;
  for (const nlohmann::json& item : document["scans"]) {
    if (!item.is_object () || !item.contains ("id") || !item["id"].is_string ())
      throw FormatError (path + ": scans[" + std::to_string (rows.size ()) + "] has no string \"id\"");
    ScanSummary row = rowFrom (item, kSummaryFields);
    row.id = item["id"].get<std::string> ();
    row.scan = valueAt<std::string> (item, "/scan", "");
    rows.push_back (row);
  }
  return rows;
}
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The summary of a batch registration (one row per scan, from its report) and the merging of shard summaries.
#include <nlohmann/json.hpp>

#include <limits>
#include <string>
#include <vector>

namespace morphreg
{
namespace tools
{
/** One scan's line of the summary. NaN / -1: not known (the scan failed before the fit, or is pending). */
struct ScanSummary
{
  std::string id, scan;
  std::string status; ///< "ok", "failed" or "pending" (not registered yet: an interrupted run)
  double rms = std::numeric_limits<double>::quiet_NaN (); ///< scan-to-model RMS over the correspondences, mm
  int iterations = -1;
  double seconds = std::numeric_limits<double>::quiet_NaN ();     ///< the scan's whole registration
  double fit_seconds = std::numeric_limits<double>::quiet_NaN (); ///< the fit alone
  std::string reason;                                             ///< why it failed
};

/** The summary line of a register report (or of the failure record written for a scan that threw). */
ScanSummary
summaryFromReport (const std::string& id, const std::string& scan, const nlohmann::json& report);

/** Writes \a rows (sorted by id) as <base>.csv and <base>.json, each atomically; \a shard is "I/N" or "all", \a run
 *  the record of the run that made them (RunRecord::summary(); JSON only). */
void
writeSummary (const std::string& base, std::vector<ScanSummary> rows, const std::string& shard,
              const nlohmann::json& run);

/** The rows of a summary JSON file written by writeSummary(), with its shard and run record if asked;
 *  FormatError naming the file otherwise. */
std::vector<ScanSummary>
readSummary (const std::string& path, std::string* shard = nullptr, nlohmann::json* run = nullptr);
} // namespace tools
} // namespace morphreg

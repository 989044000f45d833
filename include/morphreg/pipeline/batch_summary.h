// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file batch_summary.h
 *  \brief The summary of a batch registration: one row per scan, from its report, written as CSV and JSON and read
 *  back (to merge the summaries of a study's shards).
 */
#include <nlohmann/json.hpp>

#include <limits>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief One scan's line of the summary. NaN / -1: not known (the scan failed before the fit, or is pending). */
struct ScanSummary
{
  std::string id;     ///< the scan's id
  std::string scan;   ///< the scan file
  std::string status; ///< "ok", "failed" or "pending" (not registered yet: an interrupted run)
  double rms = std::numeric_limits<double>::quiet_NaN ();         ///< scan-to-model RMS over the correspondences, mm
  int iterations = -1;                                            ///< the fit's iterations
  double seconds = std::numeric_limits<double>::quiet_NaN ();     ///< the scan's whole registration
  double fit_seconds = std::numeric_limits<double>::quiet_NaN (); ///< the fit alone
  std::string reason;                                             ///< why it failed
};

/** \brief The summary line of a scan's report (or of the failure record written for a scan that threw).
 *  \param[in] id the scan's id
 *  \param[in] scan the scan file
 *  \param[in] report the report
 *  \return the row */
ScanSummary
summaryFromReport (const std::string& id, const std::string& scan, const nlohmann::json& report);

/** \brief Writes \a rows (sorted by id) as BASE.csv and BASE.json, each atomically.
 *  \param[in] base the files' path without extension
 *  \param[in] rows the rows
 *  \param[in] shard "I/N" or "all"
 *  \param[in] run the record of the run that made them (RunRecord::summary(); JSON only)
 *  \param[in] fields fields the JSON gets at its top level (e.g. "morphreg": the front end's version)
 *  \return the summary JSON as written */
nlohmann::json
writeSummary (const std::string& base, std::vector<ScanSummary> rows, const std::string& shard,
              const nlohmann::json& run, const nlohmann::json& fields = nlohmann::json::object ());

/** \brief The rows of a summary JSON file written by writeSummary(); FormatError naming the file if it is not one.
 *  \param[in] path the summary JSON
 *  \param[out] shard its shard ("I/N" or "all"), if not null
 *  \param[out] run its run record, if not null
 *  \return the rows */
std::vector<ScanSummary>
readSummary (const std::string& path, std::string* shard = nullptr, nlohmann::json* run = nullptr);
} // namespace morphreg

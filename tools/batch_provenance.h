// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What produced a batch registration's outputs: each scan's report records the content hashes of its scan,
// landmarks and model, the settings and morphreg's version, so that a resumed run redoes (and names) every scan
// whose record no longer matches instead of trusting whatever is on disk.
#include "pipeline.h"

#include <morphreg/io/scan_manifest.h>

#include <nlohmann/json.hpp>

#include <string>

namespace morphreg
{
namespace tools
{
/** The parts of a record that all scans of one run share: the model's content hash, the settings and the version,
 *  with the fingerprint of the whole study (those and the manifest's scan ids, in order), which names the run. */
struct RunRecord
{
  nlohmann::json shared;   ///< {"model": {"file", "fnv1a64"}, "settings": {...}, "version": "..."}
  std::string fingerprint; ///< 16 hex digits: equal for every shard of one job array, different for another study

  /** The shared part with the fingerprint: the "run" of a summary, which merge-summaries compares between shards. */
  nlohmann::json
  summary () const
  {
    nlohmann::json json = shared;
    json["fingerprint"] = fingerprint;
    return json;
  }
};

/** The record shared by every scan of \a options run over \a scans (hashes the model file once). */
RunRecord
runRecord (const RegisterOptions& options, const ScanManifest& scans);

/** The record of one scan's outputs: \a run's shared part with the content hashes of the scan and its landmarks
 *  (a file that cannot be read is recorded with its error instead of a hash). */
nlohmann::json
scanRecord (const RunRecord& run, const ScanEntry& entry);

/** Empty if \a found (the "provenance" of a report on disk, or null) matches \a expected, else why not, in words
 *  naming each file or setting that changed, e.g. "made with another model: "b.h5" (fnv1a64 ...) now, "a.h5"
 *  (fnv1a64 ...) in the report"; \a expected_is and \a found_is say where each record is from. */
std::string
recordMismatch (const nlohmann::json& expected, const nlohmann::json& found, const std::string& expected_is = "now",
                const std::string& found_is = "in the report");
} // namespace tools
} // namespace morphreg

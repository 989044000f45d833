// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file batch_provenance.h
 *  \brief What produced a batch registration's outputs: each scan's report records the content hashes of its scan,
 *  landmarks and model, the settings and morphreg's version, so that a resumed run redoes (and names) every scan
 *  whose record no longer matches instead of trusting whatever is on disk.
 */
#include <morphreg/io/scan_manifest.h>
#include <morphreg/pipeline/scan_file_registration.h>

#include <nlohmann/json.hpp>

#include <string>

namespace morphreg
{
/** \brief The parts of a record that all scans of one run share: the model's content hash, the settings and the version,
 *  with the fingerprint of the whole study (those and the manifest's scan ids, in order), which names the run. */
struct RunRecord
{
  nlohmann::json shared;   ///< {"model": {"file", "fnv1a64"}, "settings": {...}, "version": "..."}
  std::string fingerprint; ///< 16 hex digits: equal for every shard of one job array, different for another study

  /** \brief The shared part with the fingerprint: the "run" of a summary, which the merging of shard summaries
   *  compares between shards.
   *  \return the record */
  nlohmann::json
  summary () const
  {
    nlohmann::json json = shared;
    json["fingerprint"] = fingerprint;
    return json;
  }
};

/** \brief The record shared by every scan of a run over \a scans (hashes the model file once); IoError naming the
 *  model file if it cannot be read.
 *  \param[in] model_file the model file
 *  \param[in] settings the per-scan settings
 *  \param[in] scans the whole study (every shard's scans)
 *  \return the record */
RunRecord
runRecord (const std::string& model_file, const ScanFileSettings& settings, const ScanManifest& scans);

/** \brief The record of one scan's outputs: \a run's shared part with the content hashes of the scan and its
 *  landmarks (a file that cannot be read is recorded with its error instead of a hash).
 *  \param[in] run the run's record
 *  \param[in] entry the scan
 *  \return the record */
nlohmann::json
scanRecord (const RunRecord& run, const ScanEntry& entry);

/** \brief Why \a found (the "provenance" of a report on disk, or null) does not match \a expected, in words
 *  naming each file or setting that changed, e.g. "made with another model: "b.h5" (fnv1a64 ...) now, "a.h5"
 *  (fnv1a64 ...) in the report".
 *  \param[in] expected the record of this run
 *  \param[in] found the record on disk
 *  \param[in] expected_is where \a expected is from, for the words
 *  \param[in] found_is where \a found is from, for the words
 *  \return the reasons, or empty if the records match */
std::string
recordMismatch (const nlohmann::json& expected, const nlohmann::json& found, const std::string& expected_is = "now",
                const std::string& found_is = "in the report");
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file batch_registration.h
 *  \brief A study's scans registered to one model, loaded once, several at a time, for every front end: the output
 *  folder checked and locked (a lock per shard of a job array), each scan registered to ID.ply and ID.json
 *  (ScanFileRegistration), resumable (a scan whose report on disk was made from the same scan, landmarks, model,
 *  settings and version is done), cancellable between scans, and summarised in summary.csv / summary.json.
 *
 *  \code
 *  morphreg::BatchRegistrationSettings settings;
 *  settings.jobs = 2;
 *  morphreg::BatchRegistration batch ("model.h5", "study/manifest.csv", "fits", settings);
 *  const morphreg::BatchRegistrationOutcome outcome = batch.run ();
 *  outcome.count ("failed");              // rows: id, status, RMS, reason of every scan
 *  \endcode
 */
#include <morphreg/io/scan_manifest.h>
#include <morphreg/pipeline/batch_provenance.h>
#include <morphreg/pipeline/batch_shard.h>
#include <morphreg/pipeline/batch_summary.h>
#include <morphreg/pipeline/scan_file_registration.h>

#include <nlohmann/json.hpp>

#include <atomic>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief The settings of a batch registration, with their defaults. */
struct BatchRegistrationSettings
{
  ScanFileSettings scan;     ///< each scan's registration: the fit's settings and the fitted mesh's colours
  int jobs = 1;              ///< scans registered at once (at least 1; at most one per scan to register)
  int threads_per_fit = 0;   ///< OpenMP threads of each fit; 0: the usable cores (usableCores ()) over the jobs
  BatchShard shard;          ///< the share of the study this run registers
  bool resume = true;        ///< skip each scan whose report on disk was made by this run's inputs and settings
  bool retry_failed = false; ///< when resuming, register again the scans whose last attempt failed
  /** Fields every report and summary gets at its top level (a front end's "morphreg": its version and command
   *  line); empty: {"morphreg": {"version": ...}}. */
  nlohmann::json report_fields = nlohmann::json::object ();
};

/** \brief Refuses bad batch settings, naming the setting (InvalidInputError): jobs below 1, negative threads per
 *  fit, a shard outside [0, count), bad per-scan settings.
 *  \param[in] settings the settings */
void
requireValidSettings (const BatchRegistrationSettings& settings);

/** \brief What a run is about to do, told before its first scan. */
struct BatchPlan
{
  BatchShard shard;                ///< the share registered
  std::size_t scans = 0;           ///< the scans of the share
  std::size_t done = 0;            ///< of those, done before (skipped)
  std::size_t to_register = 0;     ///< of those, to register
  std::vector<std::string> redone; ///< "id again: why" for each done scan whose record does not match this run
  int jobs = 1;                    ///< scans registered at once
  int threads_per_fit = 1;         ///< OpenMP threads of each fit
};

/** \brief The counts of a run's scans so far. */
struct BatchCounts
{
  int ok = 0;          ///< registered and passed their checks
  int failed = 0;      ///< failed (bad input, a lost scan, failed checks)
  int to_register = 0; ///< the scans this run registers in all
};

/** \brief What a batch registration tells as it goes; every method does nothing by default. */
class BatchObserver
{
public:
  virtual ~BatchObserver () = default;

  /** \brief A finding worth a line on a console (a stale lock taken over, the model file's unit). Called on the
   *  thread of BatchRegistration::run.
   *  \param[in] text the line */
  virtual void
  message ([[maybe_unused]] const std::string& text)
  {}

  /** \brief The run is planned; the scans start next. Called on the thread of BatchRegistration::run.
   *  \param[in] plan the plan */
  virtual void
  planned ([[maybe_unused]] const BatchPlan& plan)
  {}

  /** \brief A worker is about to register a scan. Called on the worker's thread.
   *  \param[in] index the scan's place in the order the run takes them (0-based)
   *  \param[in] id the scan's id */
  virtual void
  scanStarting ([[maybe_unused]] std::size_t index, [[maybe_unused]] const std::string& id)
  {}

  /** \brief A scan is done. Called on a worker's thread, one call at a time.
   *  \param[in] row its summary row
   *  \param[in] counts the counts so far, this scan included */
  virtual void
  scanFinished ([[maybe_unused]] const ScanSummary& row, [[maybe_unused]] const BatchCounts& counts)
  {}
};

/** \brief The outcome of BatchRegistration::run. */
struct BatchRegistrationOutcome
{
  std::vector<ScanSummary> rows;   ///< every scan of the share, by id; "pending" where a cancelled run did not start it
  std::size_t skipped = 0;         ///< scans done before, not registered again
  std::size_t attempted = 0;       ///< scans this run set out to register (ok, failed or pending)
  std::vector<std::string> redone; ///< "id again: why" for each scan registered again because its record changed
  bool cancelled = false;          ///< the run was cancelled (setCancellation) before every scan was registered
  std::string summary_base;        ///< the summary files' path without .csv / .json
  nlohmann::json summary;          ///< the summary JSON as written
  double seconds = 0.0;            ///< from loading the model to the summary

  /** \brief The rows of one status.
   *  \param[in] status "ok", "failed" or "pending"
   *  \return their count */
  std::size_t
  count (const std::string& status) const;
};

/** \brief Registers the scans of a study (its share) to one model into an output folder. */
class BatchRegistration
{
public:
  using Ptr = std::shared_ptr<BatchRegistration>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const BatchRegistration>; ///< shared pointer to const

  /** \brief A run over the scans of \a scan_list; the settings are checked here (requireValidSettings).
   *  \param[in] model_file the model (.h5; loadModel)
   *  \param[in] scan_list a folder of scans or a manifest CSV (loadScanList)
   *  \param[in] out_dir the output folder (created if missing)
   *  \param[in] settings the settings */
  BatchRegistration (std::string model_file, std::string scan_list, std::string out_dir,
                     const BatchRegistrationSettings& settings = {});

  /** \brief Who hears of the run's progress.
   *  \param[in] observer the observer (not owned; nullptr: nobody) */
  void
  setObserver (BatchObserver* observer);

  /** \brief What messages call the model file and the scan list (a front end: its options' names).
   *  \param[in] model the model file's name; default "the model"
   *  \param[in] scan_list the scan list's name; default "the folder of scans" or "the list of scans" */
  void
  setInputNames (const std::string& model, const std::string& scan_list);

  /** \brief A flag that, once true, stops the run taking new scans (a front end sets it from its Ctrl-C handler);
   *  the scans in progress finish, those not started are "pending" in the summary and a rerun registers them.
   *  \param[in] cancel the flag (not owned; nullptr: none) */
  void
  setCancellation (const std::atomic<bool>* cancel);

  /** \brief Runs: reads the study, checks every file it reads and writes (no output on an input, in the folder of
   *  scans or on another scan's output), takes the share's lock of the output folder, registers the scans not
   *  done yet and writes the summary. Throws for bad input (a missing model or scan list, a scan id naming the
   *  summaries, a folder locked by a live run); a scan that cannot be registered is a failed row, not an error.
   *  \return the rows, counts and summary */
  BatchRegistrationOutcome
  run () const;

  /** \brief The summary files' path without extension: OUT/summary, or OUT/summary.shard-I-of-N for one shard.
   *  \return the path */
  std::string
  summaryBase () const;

  /** \brief The settings.
   *  \return the settings */
  const BatchRegistrationSettings&
  settings () const
  {
    return settings_;
  }

private:
  struct Plan;

  /** The scans of \a scans to register, those done, and why some done are registered again. */
  Plan
  planScans (const ScanManifest& scans, const RunRecord& run) const;

  /** Registers the planned scans; returns their reports (null for one not started). */
  std::vector<nlohmann::json>
  registerScans (const Plan& plan, const MorphableModel::ConstPtr& model) const;

  /** Creates the output folder and checks every file the run over \a study reads and writes. */
  void
  checkOutputFolder (const ScanManifest& study) const;

  /** setObserver's observer, or one that does nothing. */
  BatchObserver&
  observer () const;

  /** Whether the cancellation flag is set. */
  bool
  cancelled () const;

  std::string model_file_, scan_list_, out_dir_;
  std::string model_name_ = "the model", scan_list_name_; ///< setInputNames; empty: the default
  BatchRegistrationSettings settings_;
  BatchObserver* observer_ = nullptr;
  const std::atomic<bool>* cancel_ = nullptr;
};

/** \brief The cores this process may run on: its CPU affinity (what a Slurm task bound to its CPUs, or taskset,
 *  allows), not every core of the node, so that jobs x threads never oversubscribe a task's share of a node.
 *  \return at least 1 */
int
usableCores ();

} // namespace morphreg

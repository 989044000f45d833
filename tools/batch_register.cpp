// SPDX-License-Identifier: BSD-3-Clause
// `morphreg register --scans`: the options of a batch run handed to the library's BatchRegistration
// (pipeline/batch_registration.h), its progress on the console, Ctrl-C and SIGTERM, and the exit codes.
#include "batch_test_hold.h"
#include "option_checks.h"
#include "pipeline.h"
#include "progress.h"
#include "provenance.h"

#include <morphreg/common/error.h>
#include <morphreg/io/output_lock.h>
#include <morphreg/pipeline/batch_registration.h>
#include <morphreg/pipeline/batch_shard.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <unistd.h>

namespace morphreg
{
namespace tools
{
namespace
{
using Clock = std::chrono::steady_clock;

/** Ctrl-C count: the first lets the scans in progress finish, the second exits at once. */
std::atomic<int> interrupts{0};
/** The library's cancellation flag, set by the first Ctrl-C. */
std::atomic<bool> cancel{false};

extern "C" void
onInterrupt (int)
{
  cancel.store (true);
  if (interrupts.fetch_add (1) >= 1) {
    releaseOutputLockNow ();
    _exit (130); // partial outputs keep their temporary names; a rerun redoes those scans
  }
}

/** SIGTERM (scancel, a Slurm time limit): stop at once, releasing the lock so that a resubmission elsewhere is not
 *  refused; the scans in progress are redone by the next run. */
extern "C" void
onTerminate (int)
{
  releaseOutputLockNow ();
  _exit (143);
}

/** The run on the console: the library's findings, the plan, each scan's counts with rate and ETA; holds a scan
 *  for the batch tests (batch_test_hold.h); takes Ctrl-C while the scans run. */
class ConsoleBatchObserver : public BatchObserver
{
public:
  ConsoleBatchObserver (const BatchShard& shard, bool quiet) : hold_ (shard.tag ()), quiet_ (quiet) {}

  ~ConsoleBatchObserver () override
  {
    if (previous_interrupt_ != SIG_ERR)
      std::signal (SIGINT, previous_interrupt_);
  }

  void
  message (const std::string& text) override
  {
    std::cout << text << std::endl;
  }

  void
  planned (const BatchPlan& plan) override
  {
    for (const std::string& redo : plan.redone)
      std::cout << "register: registering " << redo << std::endl;
    std::cout << "register: " << plan.scans << " scans"
              << (plan.shard.count > 1 ? " in shard " + plan.shard.text () : "") << ", " << plan.done
              << " already done (skipped), " << plan.to_register << " to register";
    if (!plan.redone.empty ())
      std::cout << " (" << plan.redone.size () << " again: their records do not match this run)";
    std::cout << " with " << plan.jobs << " jobs of " << plan.threads_per_fit << " threads" << std::endl;
    progress_.emplace ("registering", static_cast<int> (plan.to_register), quiet_);
    start_ = Clock::now ();
    previous_interrupt_ = std::signal (SIGINT, onInterrupt);
  }

  void
  scanStarting (std::size_t index, const std::string&) override
  {
    hold_.atScan (index, interrupts);
  }

  void
  scanFinished (const ScanSummary&, const BatchCounts& counts) override
  {
    const int finished = counts.ok + counts.failed;
    const double minutes = std::chrono::duration<double> (Clock::now () - start_).count () / 60.0;
    const double rate = finished / std::max (minutes, 1e-9);
    const long eta = std::lround ((counts.to_register - finished) / std::max (rate, 1e-9) * 60.0);
    std::ostringstream detail;
    detail << ' ' << counts.ok << " ok, " << counts.failed << " failed, " << std::fixed << std::setprecision (1) << rate
           << " scans/min, ETA " << eta / 3600 << ':' << std::setw (2) << std::setfill ('0') << eta / 60 % 60 << ':'
           << std::setw (2) << eta % 60;
    progress_->step (finished, detail.str ());
    finished_ = finished;
  }

  /** Ends the progress line, if any scan finished. */
  void
  finish () const
  {
    if (progress_ && finished_ > 0)
      progress_->finish (finished_);
  }

private:
  const BatchTestHold hold_;
  bool quiet_;
  std::optional<Progress> progress_;
  Clock::time_point start_;
  int finished_ = 0;
  void (*previous_interrupt_) (int) = SIG_ERR;
};

/** The options of one batch run that single-scan mode has and batch mode refuses. */
void
requireBatchOptions (const RegisterOptions& options, const BatchOptions& batch)
{
  if (batch.out_dir.empty ())
    throw InvalidInputError ("register --scans: give --out-dir, the folder of the outputs");
  if (!options.screenshot.empty () || !options.convergence_plot.empty () || !options.truth.empty () ||
      !options.landmarks.empty () || !options.report.empty ())
    throw InvalidInputError ("register --scans: --screenshot, --convergence-plot, --truth, --landmarks and --report "
                             "are for one scan (landmark files go in the manifest's second column)");
}

/** The library's settings of the options: --jobs 0 is one job per usable core. */
BatchRegistrationSettings
batchSettings (const RegisterOptions& options, const BatchOptions& batch)
{
  BatchRegistrationSettings settings;
  settings.scan = options;
  settings.jobs = batch.jobs > 0 ? batch.jobs : usableCores ();
  settings.shard = parseBatchShard (batch.shard);
  settings.retry_failed = batch.retry_failed;
  settings.report_fields = {{"morphreg", provenanceJson ()}};
  return settings;
}

/** The closing line of a batch run; exits 130 after an interrupt, throws FitCheckFailure if a scan failed. */
void
concludeBatch (const BatchRegistrationOutcome& outcome)
{
  const std::string& base = outcome.summary_base;
  std::cout << "registered " << outcome.attempted - outcome.count ("pending") << " scans in " << std::fixed
            << std::setprecision (1) << outcome.seconds << " s; " << outcome.count ("ok") << " ok, "
            << outcome.count ("failed") << " failed, " << outcome.count ("pending") << " pending; wrote " << base
            << ".csv and " << base << ".json" << std::defaultfloat << std::endl;
  if (interrupts.load () > 0) {
    std::cerr << "morphreg: interrupted; the finished scans' outputs are complete, rerun the command to resume\n";
    std::exit (130);
  }
  if (outcome.count ("failed") > 0)
    throw FitCheckFailure (std::to_string (outcome.count ("failed")) + " of " + std::to_string (outcome.rows.size ()) +
                           " scans failed (see " + base + ".csv)");
}
} // namespace

CLI::Option*
addBatchOptions (CLI::App* command, RegisterOptions& options, BatchOptions& batch)
{
  CLI::Option* scans = command->add_option (
      "--scans", options.scans,
      "batch mode: a folder of scans (each with <name>_landmarks.json/.pp/.csv/.pts if present) or a manifest CSV "
      "(rows scan[,landmarks[,id]])");
  command
      ->add_option ("--out-dir", batch.out_dir,
                    "batch mode: folder of the outputs <id>.ply, <id>.json and "
                    "summary.csv / summary.json")
      ->needs (scans);
  command
      ->add_option ("--jobs", batch.jobs,
                    "batch mode: scans registered at once (0: one per core this process may run on, its CPU "
                    "affinity; each fit gets cores/jobs threads)")
      ->check (inRange (0, 4096))
      ->needs (scans)
      ->capture_default_str ();
  command
      ->add_option ("--shard", batch.shard,
                    "batch mode: take share I of N of the scans (I/N, 0-based), or "
                    "auto from SLURM_ARRAY_TASK_ID and SLURM_ARRAY_TASK_COUNT")
      ->needs (scans);
  command->add_flag ("--retry-failed", batch.retry_failed, "batch mode: register again the scans that failed")
      ->needs (scans);
  return scans;
}

void
registerScanBatch (const RegisterOptions& options, const BatchOptions& batch)
{
  requireBatchOptions (options, batch);
  const BatchRegistrationSettings settings = batchSettings (options, batch);
  BatchRegistration registration (options.model, options.scans, batch.out_dir, settings);
  registration.setInputNames ("--model", "--scans");
  std::optional<BatchRegistrationOutcome> outcome;
  {
    ConsoleBatchObserver observer (settings.shard, options.quiet);
    registration.setObserver (&observer);
    registration.setCancellation (&cancel);
    std::signal (SIGTERM, onTerminate); // a cancelled run releases its lock
    outcome = registration.run ();
    observer.finish ();
  }
  concludeBatch (*outcome);
}

} // namespace tools
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
// `morphreg register --scans`: a study's scans registered to one model, loaded once, several at a time;
// resumable (a scan's report on disk, made from the same scan, landmarks, model, settings and version, means it is
// done), shardable over a job array (a lock per shard), summarised.
#include "option_checks.h"
#include "batch_provenance.h"
#include "batch_summary.h"
#include "batch_test_hold.h"
#include <morphreg/io/output_lock.h>
#include "pipeline.h"
#include "progress.h"
#include "provenance.h"

#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/io/scan_manifest.h>

#include <omp.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <mutex>
#include <sstream>
#include <thread>
#include <sched.h>
#include <unistd.h>

namespace morphreg
{
namespace tools
{
namespace
{
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/** Ctrl-C count: the first lets the scans in progress finish, the second exits at once. */
std::atomic<int> interrupts{0};

extern "C" void
onInterrupt (int)
{
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

struct Shard
{
  int index = 0, count = 1;

  std::string
  text () const
  {
    return std::to_string (index) + "/" + std::to_string (count);
  }

  /** "shard-I-of-N", or "all" for the whole study: names the share's files. */
  std::string
  tag () const
  {
    return count > 1 ? "shard-" + std::to_string (index) + "-of-" + std::to_string (count) : std::string ("all");
  }
};

int
environmentInteger (const char* name)
{
  const char* value = std::getenv (name);
  if (value == nullptr || *value == '\0')
    throw InvalidInputError (std::string ("--shard auto: the environment variable ") + name +
                             " is not set (run it as a Slurm job array: sbatch --array=0-(N-1))");
  char* end = nullptr;
  const long number = std::strtol (value, &end, 10);
  if (*end != '\0' || number < 0)
    throw InvalidInputError (std::string ("--shard auto: ") + name + "='" + value + "' is not a whole number");
  return static_cast<int> (number);
}

/** "I/N", or "auto": Slurm's array task id (less the array's first id) of its task count. */
Shard
parseShard (const std::string& text)
{
  if (text.empty ())
    return {};
  if (text == "auto") {
    const int first = std::getenv ("SLURM_ARRAY_TASK_MIN") ? environmentInteger ("SLURM_ARRAY_TASK_MIN") : 0;
    return {environmentInteger ("SLURM_ARRAY_TASK_ID") - first, environmentInteger ("SLURM_ARRAY_TASK_COUNT")};
  }
  Shard shard;
  char slash = 0, rest = 0;
  std::istringstream stream (text);
  if (!(stream >> shard.index >> slash >> shard.count) || slash != '/' || stream >> rest || shard.count < 1 ||
      shard.index < 0 || shard.index >= shard.count)
    throw InvalidInputError ("--shard '" + text + "': expected I/N with 0 <= I < N (e.g. 0/4), or auto");
  return shard;
}

/** One scan to register: its manifest entry and the options of its run. */
struct Task
{
  ScanEntry entry;
  RegisterOptions options;
};

/** The report of a finished attempt, or null if the scan has none (never run, or interrupted mid-fit). */
nlohmann::json
finishedReport (const std::string& path)
{
  std::error_code ec;
  if (!fs::is_regular_file (path, ec))
    return nullptr;
  try {
    return readJsonFile (path);
  }
  catch (const Error&) {
    return nullptr; // not written by us (reports are written atomically): redo the scan
  }
}

/** Counts, rate and ETA as the steps of a Progress, from any worker thread. */
class BatchProgress
{
public:
  BatchProgress (int total, bool quiet)
    : total_ (total), progress_ ("registering", total, quiet), start_ (Clock::now ())
  {}

  void
  done (bool ok)
  {
    std::lock_guard<std::mutex> lock (mutex_);
    ++(ok ? ok_ : failed_);
    const int finished = ok_ + failed_;
    const double minutes = std::chrono::duration<double> (Clock::now () - start_).count () / 60.0;
    const double rate = finished / std::max (minutes, 1e-9);
    const long eta = std::lround ((total_ - finished) / std::max (rate, 1e-9) * 60.0);
    std::ostringstream detail;
    detail << ' ' << ok_ << " ok, " << failed_ << " failed, " << std::fixed << std::setprecision (1) << rate
           << " scans/min, ETA " << eta / 3600 << ':' << std::setw (2) << std::setfill ('0') << eta / 60 % 60 << ':'
           << std::setw (2) << eta % 60;
    progress_.step (finished, detail.str ());
  }

  void
  finish () const
  {
    if (ok_ + failed_ > 0)
      progress_.finish (ok_ + failed_);
  }

private:
  int total_, ok_ = 0, failed_ = 0;
  const Progress progress_;
  Clock::time_point start_;
  std::mutex mutex_;
};

/** Runs \a tasks on \a jobs threads of \a threads_per_fit OpenMP threads each; stops taking new ones on Ctrl-C.
 *  Returns each task's report (null for one not started).
 */
std::vector<nlohmann::json>
runTasks (const std::vector<Task>& tasks, const MorphableModel::Ptr& model, int jobs, int threads_per_fit, bool quiet,
          const BatchTestHold& hold)
{
  std::vector<nlohmann::json> reports (tasks.size ());
  std::atomic<std::size_t> next{0};
  BatchProgress progress (static_cast<int> (tasks.size ()), quiet);
  std::vector<std::thread> workers;
  for (int j = 0; j < jobs; ++j)
    workers.emplace_back ([&] {
      omp_set_num_threads (threads_per_fit);
      for (std::size_t k; interrupts.load () == 0 && (k = next.fetch_add (1)) < tasks.size ();) {
        hold.atScan (k, interrupts);
        reports[k] = registerStudyScan (tasks[k].options, model);
        progress.done (reports[k].value ("status", "") == "ok");
      }
    });
  for (std::thread& worker : workers)
    worker.join ();
  progress.finish ();
  return reports;
}
} // namespace

namespace
{
/** The report of a scan that could not be registered: why, and what produced it. */
nlohmann::json
failureReport (const RegisterOptions& options, const std::string& why, Clock::time_point start)
{
  nlohmann::json failure = {{"status", "failed"},
                            {"failure", why},
                            {"scan", {{"file", options.scan}, {"landmarks", options.landmarks}}},
                            {"timings_s", {{"total", std::chrono::duration<double> (Clock::now () - start).count ()}}}};
  addProvenance (options, failure);
  return failure;
}
} // namespace

nlohmann::json
registerStudyScan (const RegisterOptions& options, const MorphableModel::Ptr& model, const FitFollowUp& follow_up,
                   const std::vector<std::string>& follow_up_outputs)
{
  const auto start = Clock::now ();
  std::vector<std::string> files = {options.out, reportPath (options)};
  files.insert (files.end (), follow_up_outputs.begin (), follow_up_outputs.end ());
  for (const std::string& output : files)
    std::remove (partialPath (output).c_str ()); // left by a run killed mid-write
  std::string why;
  {
    OutputTransaction outputs (files);
    std::ostringstream log; // per-scan chatter would interleave between threads
    try {
      nlohmann::json report = registerScan (options, model, nullptr, 0.0, log, log, follow_up);
      outputs.commit ();
      return report;
    }
    catch (const FitCheckFailure& e) {
      outputs.commit (); // written, and marked failed
      return e.report ();
    }
    catch (const std::exception& e) {
      why = e.what ();
    }
  } // the scan's outputs rolled back: its report records the failure alone
  const nlohmann::json failure = failureReport (options, why, start);
  writeReport (reportPath (options), failure);
  return failure;
}

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

namespace
{
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

/** The summary files' path without extension: summary, or summary.shard-I-of-N for one shard. */
std::string
summaryBase (const BatchOptions& batch, const Shard& shard)
{
  return (fs::path (batch.out_dir) / (shard.count > 1 ? "summary." + shard.tag () : std::string ("summary"))).string ();
}

/** Refuses an id that names the summaries' files (summary, summary.shard-I-of-N, ...): a scan's report would
 *  overwrite a summary, or a summary the report, in this run or a sharded one. */
void
requireOwnId (const ScanEntry& entry)
{
  if (entry.id == "summary" || entry.id.rfind ("summary.", 0) == 0)
    throw InvalidInputError (entry.where + ": the scan id '" + entry.id +
                             "' would name files of the run's summaries (summary.csv, summary.json, "
                             "summary.shard-I-of-N.*): give the scan another id (the manifest's third column)");
}

/** Every file the run reads and writes, for every scan of the study (whatever the shard), checked before any work
 *  (OutputPlan): no output on an input or in the folder of scans, no two scans' outputs on one file. */
OutputPlan
batchPlan (const RegisterOptions& options, const BatchOptions& batch, const ScanManifest& study, const Shard& shard)
{
  OutputPlan plan;
  plan.addInput (options.model, "--model");
  std::error_code ec;
  if (fs::is_directory (options.scans, ec))
    plan.addInputFolder (options.scans, "--scans");
  else
    plan.addInput (options.scans, "--scans");
  for (const ScanEntry& entry : study) {
    requireOwnId (entry);
    plan.addInput (entry.scan, "the scan of id '" + entry.id + "'");
    plan.addInput (entry.landmarks, "the landmarks of id '" + entry.id + "'");
  }
  for (const ScanEntry& entry : study) {
    const fs::path base = fs::path (batch.out_dir) / entry.id;
    plan.addOutput (base.string () + ".ply", "the fitted mesh of scan '" + entry.id + "'");
    plan.addOutput (base.string () + ".json", "the report of scan '" + entry.id + "'");
  }
  plan.addOutput (summaryBase (batch, shard) + ".csv", "the summary");
  plan.addOutput (summaryBase (batch, shard) + ".json", "the summary");
  return plan;
}

/** Creates the output folder and checks the run's plan there; a folder created for a run refused is removed. */
void
prepareOutputFolder (const OutputPlan& plan, const std::string& out_dir)
{
  std::error_code ec;
  const bool existed = fs::exists (out_dir, ec);
  fs::create_directories (out_dir, ec);
  if (!fs::is_directory (out_dir, ec))
    throw IoError (out_dir + ": cannot create the output folder");
  try {
    plan.check ();
  }
  catch (const Error&) {
    if (!existed)
      fs::remove (out_dir, ec);
    throw;
  }
}

/** What a run does with the scans of its share: those to register, the summary rows of those done, and why some
 *  done before are registered again. */
struct Plan
{
  std::vector<Task> tasks;
  std::vector<ScanSummary> done;
  std::vector<std::string> redone; ///< "id again: why" for each scan whose report's record does not match this run
};

/** The task of \a entry: its outputs in the output folder, and the record of what produces them. */
Task
scanTask (const ScanEntry& entry, const RegisterOptions& options, const BatchOptions& batch, const RunRecord& run)
{
  Task task{entry, options};
  task.options.scan = entry.scan;
  task.options.landmarks = entry.landmarks;
  task.options.out = (fs::path (batch.out_dir) / (entry.id + ".ply")).string ();
  task.options.quiet = true;
  task.options.provenance = scanRecord (run, entry);
  return task;
}

/** The scans still to register: no finished report, a report whose record of what produced it does not match
 *  this run (said in plan.redone), or a failed one with --retry-failed. */
Plan
planTasks (const ScanManifest& scans, const RegisterOptions& options, const BatchOptions& batch, const RunRecord& run)
{
  Plan plan;
  for (const ScanEntry& entry : scans) {
    const Task task = scanTask (entry, options, batch, run);
    const nlohmann::json report = finishedReport (reportPath (task.options));
    if (!report.is_object ()) {
      plan.tasks.push_back (task);
      continue;
    }
    const std::string mismatch =
        recordMismatch (task.options.provenance, report.value ("provenance", nlohmann::json ()));
    if (!mismatch.empty ())
      plan.redone.push_back (entry.id + " again: " + mismatch);
    if (!mismatch.empty () || (report.value ("status", "") != "ok" && batch.retry_failed))
      plan.tasks.push_back (task);
    else
      plan.done.push_back (summaryFromReport (entry.id, entry.scan, report));
  }
  return plan;
}

/** The closing line of a batch run; exits 130 after an interrupt, throws FitCheckFailure if a scan failed. */
void
concludeBatch (const std::vector<ScanSummary>& rows, std::size_t registered, double seconds, const std::string& base)
{
  const auto count = [&] (const char* status) {
    return std::count_if (rows.begin (), rows.end (), [&] (const ScanSummary& r) { return r.status == status; });
  };
  std::cout << "registered " << registered - count ("pending") << " scans in " << std::fixed << std::setprecision (1)
            << seconds << " s; " << count ("ok") << " ok, " << count ("failed") << " failed, " << count ("pending")
            << " pending; wrote " << base << ".csv and " << base << ".json" << std::defaultfloat << std::endl;
  if (interrupts.load () > 0) {
    releaseOutputLockNow (); // std::exit skips the lock's destructor
    std::cerr << "morphreg: interrupted; the finished scans' outputs are complete, rerun the command to resume\n";
    std::exit (130);
  }
  if (count ("failed") > 0)
    throw FitCheckFailure (std::to_string (count ("failed")) + " of " + std::to_string (rows.size ()) +
                           " scans failed (see " + base + ".csv)");
}
} // namespace

namespace
{
/** The cores this process may run on: its CPU affinity (what a Slurm task bound to its CPUs, or taskset, allows),
 *  not every core of the node, so that jobs x threads never oversubscribe a task's share of a node. */
int
usableCores ()
{
  cpu_set_t cpus;
  CPU_ZERO (&cpus);
  if (sched_getaffinity (0, sizeof (cpus), &cpus) == 0 && CPU_COUNT (&cpus) > 0)
    return CPU_COUNT (&cpus);
  return std::max (1, static_cast<int> (std::thread::hardware_concurrency ()));
}

/** The run's opening lines: the scans registered again and why, then the counts and the jobs. */
void
announcePlan (const Plan& plan, std::size_t scans, const Shard& shard, int jobs, int threads_per_fit)
{
  for (const std::string& redo : plan.redone)
    std::cout << "register: registering " << redo << std::endl;
  std::cout << "register: " << scans << " scans" << (shard.count > 1 ? " in shard " + shard.text () : "") << ", "
            << plan.done.size () << " already done (skipped), " << plan.tasks.size () << " to register";
  if (!plan.redone.empty ())
    std::cout << " (" << plan.redone.size () << " again: their records do not match this run)";
  std::cout << " with " << jobs << " jobs of " << threads_per_fit << " threads" << std::endl;
}

/** Registers the planned tasks with Ctrl-C handled; returns the summary rows of all the share's scans. */
std::vector<ScanSummary>
runPlan (Plan plan, const MorphableModel::Ptr& model, int jobs, int threads_per_fit, bool quiet, const Shard& shard)
{
  const BatchTestHold hold (shard.tag ());
  const auto previous_interrupt = std::signal (SIGINT, onInterrupt);
  const std::vector<nlohmann::json> reports = runTasks (plan.tasks, model, jobs, threads_per_fit, quiet, hold);
  std::signal (SIGINT, previous_interrupt);
  std::vector<ScanSummary> rows = std::move (plan.done);
  for (std::size_t k = 0; k < plan.tasks.size (); ++k) {
    ScanSummary row = summaryFromReport (plan.tasks[k].entry.id, plan.tasks[k].entry.scan, reports[k]);
    if (reports[k].is_null ())
      row.status = "pending";
    rows.push_back (row);
  }
  return rows;
}
} // namespace

void
registerScanBatch (const RegisterOptions& options, const BatchOptions& batch)
{
  requireBatchOptions (options, batch);
  const Shard shard = parseShard (batch.shard);
  const ScanManifest study = loadScanList (options.scans);
  const ScanManifest scans = manifestShard (study, shard.index, shard.count);
  prepareOutputFolder (batchPlan (options, batch, study, shard), batch.out_dir);
  const RunRecord run = runRecord (options, study);
  const OutputLock lock (batch.out_dir, shard.index, shard.count, run.fingerprint, std::cout);
  std::signal (SIGTERM, onTerminate); // from here on, a cancelled run releases its lock
  const Plan plan = planTasks (scans, options, batch, run);

  const auto start = Clock::now ();
  const MorphableModel::Ptr model = loadModelFile (options.model, std::cout);
  const int cores = usableCores ();
  const int jobs =
      std::max (1, std::min<int> (batch.jobs > 0 ? batch.jobs : cores, static_cast<int> (plan.tasks.size ())));
  const int threads_per_fit = std::max (1, cores / jobs);
  announcePlan (plan, scans.size (), shard, jobs, threads_per_fit);
  const std::vector<ScanSummary> rows = runPlan (plan, model, jobs, threads_per_fit, options.quiet, shard);
  const std::string base = summaryBase (batch, shard);
  OutputTransaction summary ({base + ".csv", base + ".json"});
  writeSummary (base, rows, shard.count > 1 ? shard.text () : "all", run.summary ());
  summary.commit ();
  concludeBatch (rows, plan.tasks.size (), std::chrono::duration<double> (Clock::now () - start).count (), base);
}

} // namespace tools
} // namespace morphreg

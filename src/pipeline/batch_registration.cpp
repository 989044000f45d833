// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/model_io.h>
#include <morphreg/io/output_lock.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/io/output_transaction.h>
#include <morphreg/pipeline/batch_registration.h>

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <mutex>
#include <sstream>
#include <thread>
#include <utility>
#include <sched.h>

namespace morphreg
{
namespace
{
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

/** Tells nobody: the observer of a run without one. */
BatchObserver&
silentObserver ()
{
  static BatchObserver silent;
  return silent;
}

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

/** The files of \a entry's registration into \a out_dir. */
ScanFiles
scanFiles (const ScanEntry& entry, const std::string& model_file, const std::string& out_dir)
{
  const std::string base = (fs::path (out_dir) / entry.id).string ();
  return {entry.scan, entry.landmarks, model_file, base + ".ply", base + ".json"};
}

/** Creates \a out_dir and checks \a plan there; a folder created for a run refused is removed. */
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

/** Says each line of \a text to \a observer. */
void
tellLines (const std::string& text, BatchObserver& observer)
{
  std::istringstream lines (text);
  for (std::string line; std::getline (lines, line);)
    observer.message (line);
}

/** Counts the finished scans and tells the observer, one scan at a time, from any worker thread. */
class FinishedScans
{
public:
  FinishedScans (BatchObserver& observer, int to_register) : observer_ (observer)
  {
    counts_.to_register = to_register;
  }

  void
  add (const ScanSummary& row)
  {
    std::lock_guard<std::mutex> lock (mutex_);
    ++(row.status == "ok" ? counts_.ok : counts_.failed);
    observer_.scanFinished (row, counts_);
  }

private:
  BatchObserver& observer_;
  BatchCounts counts_;
  std::mutex mutex_;
};
} // namespace

/** What a run does with the scans of its share: those to register (with the records of what produces them), the
 *  summary rows of those done, and why some done before are registered again. */
struct BatchRegistration::Plan
{
  std::vector<ScanEntry> tasks;
  std::vector<nlohmann::json> records; ///< the provenance of each task's outputs
  std::vector<ScanSummary> done;
  std::vector<std::string> redone;
  nlohmann::json report_fields; ///< the settings' report fields, or the version alone
  int jobs = 1, threads_per_fit = 1;
};

std::size_t
BatchRegistrationOutcome::count (const std::string& status) const
{
  return static_cast<std::size_t> (
      std::count_if (rows.begin (), rows.end (), [&] (const ScanSummary& row) { return row.status == status; }));
}

void
requireValidSettings (const BatchRegistrationSettings& settings)
{
  if (settings.jobs < 1)
    throw InvalidInputError ("batch registration: jobs " + std::to_string (settings.jobs) +
                             ": at least one scan must be registered at a time");
  if (settings.threads_per_fit < 0)
    throw InvalidInputError ("batch registration: threads_per_fit " + std::to_string (settings.threads_per_fit) +
                             ": must be 0 (the usable cores over the jobs) or more");
  const BatchShard& shard = settings.shard;
  if (shard.count < 1 || shard.index < 0 || shard.index >= shard.count)
    throw InvalidInputError ("batch registration: shard " + shard.text () +
                             ": expected index/count with 0 <= index < count");
  if (!settings.report_fields.is_object ())
    throw InvalidInputError ("batch registration: report_fields is not a JSON object");
  requireValidSettings (settings.scan);
}

int
usableCores ()
{
  cpu_set_t cpus;
  CPU_ZERO (&cpus);
  if (sched_getaffinity (0, sizeof (cpus), &cpus) == 0 && CPU_COUNT (&cpus) > 0)
    return CPU_COUNT (&cpus);
  return std::max (1, static_cast<int> (std::thread::hardware_concurrency ()));
}

BatchRegistration::BatchRegistration (std::string model_file, std::string scan_list, std::string out_dir,
                                      const BatchRegistrationSettings& settings)
  : model_file_ (std::move (model_file)), scan_list_ (std::move (scan_list)), out_dir_ (std::move (out_dir)),
    settings_ (settings)
{
  if (out_dir_.empty ())
    throw InvalidInputError ("batch registration of " + scan_list_ + ": no output folder given");
  requireValidSettings (settings_);
}

void
BatchRegistration::setObserver (BatchObserver* observer)
{
  observer_ = observer;
}

void
BatchRegistration::setInputNames (const std::string& model, const std::string& scan_list)
{
  model_name_ = model;
  scan_list_name_ = scan_list;
}

void
BatchRegistration::setCancellation (const std::atomic<bool>* cancel)
{
  cancel_ = cancel;
}

BatchObserver&
BatchRegistration::observer () const
{
  return observer_ ? *observer_ : silentObserver ();
}

bool
BatchRegistration::cancelled () const
{
  return cancel_ != nullptr && cancel_->load ();
}

std::string
BatchRegistration::summaryBase () const
{
  const BatchShard& shard = settings_.shard;
  return (fs::path (out_dir_) / (shard.count > 1 ? "summary." + shard.tag () : std::string ("summary"))).string ();
}

/** Every file the run reads and writes, for every scan of the study (whatever the shard), checked before any work
 *  (OutputPlan): no output on an input or in the folder of scans, no two scans' outputs on one file. */
void
BatchRegistration::checkOutputFolder (const ScanManifest& study) const
{
  OutputPlan plan;
  plan.addInput (model_file_, model_name_);
  std::error_code ec;
  const bool folder = fs::is_directory (scan_list_, ec);
  const std::string scan_list_name = !scan_list_name_.empty () ? scan_list_name_
                                     : folder                  ? "the folder of scans"
                                                               : "the list of scans";
  if (folder)
    plan.addInputFolder (scan_list_, scan_list_name);
  else
    plan.addInput (scan_list_, scan_list_name);
  for (const ScanEntry& entry : study) {
    requireOwnId (entry);
    plan.addInput (entry.scan, "the scan of id '" + entry.id + "'");
    plan.addInput (entry.landmarks, "the landmarks of id '" + entry.id + "'");
  }
  for (const ScanEntry& entry : study) {
    const ScanFiles files = scanFiles (entry, model_file_, out_dir_);
    plan.addOutput (files.fitted_mesh, "the fitted mesh of scan '" + entry.id + "'");
    plan.addOutput (files.report, "the report of scan '" + entry.id + "'");
  }
  plan.addOutput (summaryBase () + ".csv", "the summary");
  plan.addOutput (summaryBase () + ".json", "the summary");
  prepareOutputFolder (plan, out_dir_);
}

/** The scans still to register: no finished report, a report whose record of what produced it does not match
 *  this run (said in plan.redone), a failed one with retry_failed, or every scan without resume. */
BatchRegistration::Plan
BatchRegistration::planScans (const ScanManifest& scans, const RunRecord& run) const
{
  Plan plan;
  for (const ScanEntry& entry : scans) {
    nlohmann::json record = scanRecord (run, entry);
    const nlohmann::json report =
        settings_.resume ? finishedReport (scanFiles (entry, model_file_, out_dir_).report) : nlohmann::json ();
    std::string mismatch;
    if (report.is_object ()) {
      mismatch = recordMismatch (record, report.value ("provenance", nlohmann::json ()));
      if (!mismatch.empty ())
        plan.redone.push_back (entry.id + " again: " + mismatch);
    }
    if (!report.is_object () || !mismatch.empty () || (report.value ("status", "") != "ok" && settings_.retry_failed)) {
      plan.tasks.push_back (entry);
      plan.records.push_back (std::move (record));
    }
    else
      plan.done.push_back (summaryFromReport (entry.id, entry.scan, report));
  }
  return plan;
}

/** Registers the planned scans on plan.jobs threads of plan.threads_per_fit OpenMP threads each; stops taking new
 *  ones once cancelled. Returns each scan's report (null for one not started). */
std::vector<nlohmann::json>
BatchRegistration::registerScans (const Plan& plan, const MorphableModel::ConstPtr& model) const
{
  std::vector<nlohmann::json> reports (plan.tasks.size ());
  std::atomic<std::size_t> next{0};
  FinishedScans finished (observer (), static_cast<int> (plan.tasks.size ()));
  const auto work = [&] {
    omp_set_num_threads (plan.threads_per_fit);
    for (std::size_t k; !cancelled () && (k = next.fetch_add (1)) < plan.tasks.size ();) {
      const ScanEntry& entry = plan.tasks[k];
      observer ().scanStarting (k, entry.id);
      ScanFileRegistration registration (model, settings_.scan);
      nlohmann::json fields = plan.report_fields;
      fields["provenance"] = plan.records[k];
      registration.setReportFields (fields);
      reports[k] = registration.registerStudyScan (scanFiles (entry, model_file_, out_dir_));
      finished.add (summaryFromReport (entry.id, entry.scan, reports[k]));
    }
  };
  std::vector<std::thread> workers;
  for (int j = 0; j < plan.jobs; ++j)
    workers.emplace_back (work);
  for (std::thread& worker : workers)
    worker.join ();
  return reports;
}

BatchRegistrationOutcome
BatchRegistration::run () const
{
  const ScanManifest study = loadScanList (scan_list_);
  const ScanManifest scans = manifestShard (study, settings_.shard.index, settings_.shard.count);
  const RunRecord run = runRecord (model_file_, settings_.scan, study); // a missing model: no folder made
  checkOutputFolder (study);
  std::ostringstream lock_messages;
  const OutputLock lock (out_dir_, settings_.shard.index, settings_.shard.count, run.fingerprint, lock_messages);
  tellLines (lock_messages.str (), observer ());
  Plan plan = planScans (scans, run);
  plan.report_fields = settings_.report_fields.empty ()
                           ? nlohmann::json{{"morphreg", {{"version", run.shared["version"]}}}}
                           : settings_.report_fields;

  const auto start = Clock::now ();
  const MorphableModel::ConstPtr model = loadModel (model_file_);
  if (const std::string units = modelFileUnitsMessage (*model, model_file_); !units.empty ())
    observer ().message (units);
  const int cores = usableCores ();
  plan.jobs = std::max (1, std::min<int> (settings_.jobs, static_cast<int> (plan.tasks.size ())));
  plan.threads_per_fit = settings_.threads_per_fit > 0 ? settings_.threads_per_fit : std::max (1, cores / plan.jobs);
  observer ().planned ({settings_.shard, scans.size (), plan.done.size (), plan.tasks.size (), plan.redone, plan.jobs,
                        plan.threads_per_fit});
  const std::vector<nlohmann::json> reports = registerScans (plan, model);

  BatchRegistrationOutcome outcome;
  outcome.rows = std::move (plan.done);
  outcome.skipped = outcome.rows.size ();
  outcome.attempted = plan.tasks.size ();
  outcome.redone = plan.redone;
  for (std::size_t k = 0; k < plan.tasks.size (); ++k) {
    ScanSummary row = summaryFromReport (plan.tasks[k].id, plan.tasks[k].scan, reports[k]);
    if (reports[k].is_null ())
      row.status = "pending";
    outcome.rows.push_back (row);
  }
  outcome.cancelled = outcome.count ("pending") > 0;
  outcome.summary_base = summaryBase ();
  OutputTransaction summary ({outcome.summary_base + ".csv", outcome.summary_base + ".json"});
  outcome.summary =
      writeSummary (outcome.summary_base, outcome.rows, settings_.shard.count > 1 ? settings_.shard.text () : "all",
                    run.summary (), plan.report_fields);
  summary.commit ();
  std::sort (outcome.rows.begin (), outcome.rows.end (),
             [] (const ScanSummary& a, const ScanSummary& b) { return a.id < b.id; });
  outcome.seconds = std::chrono::duration<double> (Clock::now () - start).count ();
  return outcome;
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
// morphreg.register_study: the library's batch registration (pipeline/batch_registration.h) of a study's scans into
// an output folder, as `morphreg register --scans` runs it; the GIL released while it runs.
#include "bindings.h"
#include "json_objects.h"
#include "keyword_settings.h"

#include <morphreg/pipeline/batch_registration.h>
#include <morphreg/pipeline/batch_shard.h>
#include <morphreg/registration/registration_options.h>

#include <pybind11/stl.h>

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <exception>
#include <optional>
#include <string>
#include <thread>
#include <utility>

namespace morphreg
{
namespace python
{
namespace
{
/** The study's outcome as a dict: the summary (its "scans" rows and "counts") with what this run skipped and
 *  attempted, and why scans done before were registered again. */
py::object
outcomeDict (const BatchRegistrationOutcome& outcome)
{
  nlohmann::json result = outcome.summary;
  result["skipped"] = outcome.skipped;
  result["attempted"] = outcome.attempted;
  result["redone"] = outcome.redone;
  result["summary_files"] = {outcome.summary_base + ".csv", outcome.summary_base + ".json"};
  return toPython (result);
}

/** Runs \a batch on a thread of its own while this one, the interpreter's, waits with the GIL released and looks
 *  for Ctrl-C every 50 ms: the first stops the run taking new scans (those are "pending" in the summary, a rerun
 *  registers them) and is raised as KeyboardInterrupt once the scans in progress are done. */
BatchRegistrationOutcome
runInterruptibly (BatchRegistration& batch)
{
  std::atomic<bool> cancel{false}, finished{false};
  batch.setCancellation (&cancel);
  std::optional<BatchRegistrationOutcome> outcome;
  std::exception_ptr failure;
  std::thread runner ([&] {
    try {
      outcome = batch.run ();
    }
    catch (...) {
      failure = std::current_exception ();
    }
    finished = true;
  });
  bool interrupted = false;
  while (!finished) {
    {
      py::gil_scoped_release released;
      std::this_thread::sleep_for (std::chrono::milliseconds (50));
    }
    if (!interrupted && PyErr_CheckSignals () != 0) {
      PyErr_Clear ();
      interrupted = true;
      cancel = true;
    }
  }
  runner.join ();
  if (failure)
    std::rethrow_exception (failure);
  if (interrupted) {
    PyErr_SetNone (PyExc_KeyboardInterrupt);
    throw py::error_already_set ();
  }
  return std::move (*outcome);
}

/** register_study's shard: "I/N" or "auto" (a Slurm job array's task) as the command line takes them, or (i, n). */
BatchShard
shardArgument (const py::object& shard)
{
  if (py::isinstance<py::str> (shard))
    return parseBatchShard (shard.cast<std::string> ());
  try {
    const auto [index, count] = shard.cast<std::pair<int, int>> ();
    return {index, count};
  }
  catch (const py::cast_error&) {
    throw py::type_error ("register_study(): shard must be (i, n), \"I/N\" or \"auto\", got " +
                          std::string (py::repr (shard)));
  }
}

py::object
registerStudy (const std::string& model, const std::string& scans, const std::string& out_dir, int jobs,
               int threads_per_fit, const py::object& shard, bool resume, bool retry_failed, const std::string& colours,
               double colour_max, const py::kwargs& keywords)
{
  BatchRegistrationSettings settings;
  static_cast<RegistrationSettings&> (settings.scan) =
      settingsFromKeywords (keywords, registrationOptions (), "register_study");
  settings.scan.colours = colours;
  settings.scan.colour_max = colour_max;
  settings.jobs = jobs;
  settings.threads_per_fit = threads_per_fit;
  settings.shard = shardArgument (shard);
  settings.resume = resume;
  settings.retry_failed = retry_failed;
  BatchRegistration batch (model, scans, out_dir, settings);
  return outcomeDict (runInterruptibly (batch));
}

/** register_study's docstring: what it does, then one line per setting of the table. */
std::string
registerStudyDoc ()
{
  return keywordDoc (
      "Registers every scan of a study (a folder of scans or a manifest CSV, as `morphreg register --scans`) to the\n"
      "model file, writing <id>.ply, <id>.json and summary.csv / summary.json into out_dir: jobs scans at a time,\n"
      "shard=(i, n) or \"I/N\" for share i of n (\"auto\": this task of a Slurm job array), resumed from the reports "
      "whose records match (resume), failed ones again\n"
      "with retry_failed. A scan that cannot be registered is a failed row, not an error. Returns the summary as a\n"
      "dict (\"scans\": id, status, rms_mm, reason ...; \"counts\") with \"skipped\", \"attempted\" and \"redone\".\n"
      "Ctrl-C stops it taking new scans (KeyboardInterrupt once the scans in progress are done; a rerun resumes).\n"
      "The keyword settings are register's:\n",
      registrationOptions ());
}
} // namespace

void
bindBatch (py::module_& m)
{
  m.def ("register_study", &registerStudy, py::arg ("model"), py::arg ("scans"), py::arg ("out_dir"), py::kw_only (),
         py::arg ("jobs") = 1, py::arg ("threads_per_fit") = 0, py::arg ("shard") = std::make_pair (0, 1),
         py::arg ("resume") = true, py::arg ("retry_failed") = false, py::arg ("colours") = "auto",
         py::arg ("colour_max") = 0.0, registerStudyDoc ().c_str ());
}

} // namespace python
} // namespace morphreg

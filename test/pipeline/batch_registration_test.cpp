// SPDX-License-Identifier: BSD-3-Clause
// The library's batch registration (pipeline/batch_registration.h), the sequence `morphreg register --scans` runs:
// a small study of synthetic scans registered into a folder, its rows, counts and summary; a rerun that resumes, a
// changed setting that registers again, a bad scan that fails alone, a cancelled run, a shard, and bad settings
// named.
#include "registration/scan_protocol.h"
#include "support/expect_error.h"
#include "support/synthetic_heads.h"
#include "support/temp_directory.h"
#include "support/text_file.h"

#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/model_io.h>
#include <morphreg/pipeline/batch_registration.h>
#include <morphreg/pipeline/batch_summary_merge.h>

#include <gtest/gtest.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <random>
#include <string>
#include <vector>

namespace
{
using morphreg::BatchRegistration;
using morphreg::BatchRegistrationOutcome;
using morphreg::BatchRegistrationSettings;
using morphreg::test::expectErrorContaining;

/** What a run told, for the assertions. */
class RecordingObserver : public morphreg::BatchObserver
{
public:
  void
  planned (const morphreg::BatchPlan& batch_plan) override
  {
    plan = batch_plan;
  }
  void
  scanStarting (std::size_t, const std::string& id) override
  {
    std::lock_guard<std::mutex> lock (mutex);
    started.push_back (id);
  }
  void
  scanFinished (const morphreg::ScanSummary&, const morphreg::BatchCounts& counts) override
  {
    last = counts; // one call at a time
    ++finished;
  }

  morphreg::BatchPlan plan;
  std::vector<std::string> started;
  morphreg::BatchCounts last;
  int finished = 0;
  std::mutex mutex;
};

class BatchRegistrationTest : public ::testing::Test
{
protected:
  /** A small model (5 components) and a study of two synthetic scans and one that cannot be registered. */
  static void
  SetUpTestSuite ()
  {
    const morphreg::MorphableModel::Ptr model = morphreg::test::headModel (20, 5);
    study_ = new morphreg::test::TempDirectory ();
    morphreg::saveModel (study_->file ("model.h5"), *model);
    std::mt19937_64 rng (5);
    const auto selection = model->firstComponents (5);
    for (int k = 0; k < 2; ++k) {
      const morphreg::TriangleMesh head = model->generateMesh (model->sampleCoefficients (rng, selection), selection);
      morphreg::test::ProtocolSettings protocol;
      protocol.min_scale = protocol.max_scale = 1.0;
      const auto scan = morphreg::test::simulateProtocolScan (head, model->landmarks (), 20 + k, protocol);
      morphreg::saveCloud (study_->file ("head_" + std::to_string (k) + ".pcd"), *scan.cloud);
    }
    morphreg::test::writeText (study_->file ("manifest.csv"), "scan,landmarks,id\nhead_0.pcd\nhead_1.pcd\n"
                                                              "no_such_scan.pcd,,missing\n");
  }

  static void
  TearDownTestSuite ()
  {
    delete study_;
  }

  /** Settings quick enough for a unit test. */
  static BatchRegistrationSettings
  quickSettings ()
  {
    BatchRegistrationSettings settings;
    settings.scan.iterations = 15;
    settings.scan.colours = "residual";
    settings.jobs = 2;
    return settings;
  }

  /** A run of the study into \a out_dir with \a settings, told to \a observer. */
  static BatchRegistrationOutcome
  run (const std::string& out_dir, const BatchRegistrationSettings& settings, morphreg::BatchObserver* observer,
       const std::atomic<bool>* cancel = nullptr)
  {
    BatchRegistration batch (study_->file ("model.h5"), study_->file ("manifest.csv"), out_dir, settings);
    batch.setObserver (observer);
    batch.setCancellation (cancel);
    return batch.run ();
  }

  static const morphreg::ScanSummary&
  row (const BatchRegistrationOutcome& outcome, const std::string& id)
  {
    for (const morphreg::ScanSummary& row : outcome.rows)
      if (row.id == id)
        return row;
    throw std::runtime_error ("no row " + id);
  }

  static morphreg::test::TempDirectory* study_;
};

morphreg::test::TempDirectory* BatchRegistrationTest::study_ = nullptr;

TEST_F (BatchRegistrationTest, AStudyIsRegisteredSummarisedAndResumed)
{
  morphreg::test::TempDirectory out;
  RecordingObserver observer;
  const BatchRegistrationOutcome first = run (out.file ("fits"), quickSettings (), &observer);
  ASSERT_EQ (first.rows.size (), 3u);
  EXPECT_EQ (first.count ("ok"), 2u);
  EXPECT_EQ (first.count ("failed"), 1u);
  EXPECT_EQ (first.attempted, 3u);
  EXPECT_EQ (first.skipped, 0u);
  EXPECT_FALSE (first.cancelled);
  for (const char* id : {"head_0", "head_1"}) {
    EXPECT_EQ (row (first, id).status, "ok") << row (first, id).reason;
    EXPECT_LT (row (first, id).rms, 2.0) << id;
    EXPECT_TRUE (std::filesystem::exists (out.file (std::string ("fits/") + id + ".ply"))) << id;
  }
  // the bad scan fails alone, its reason naming the file; no mesh, a report saying why
  EXPECT_EQ (row (first, "missing").status, "failed");
  EXPECT_NE (row (first, "missing").reason.find ("no_such_scan.pcd"), std::string::npos)
      << row (first, "missing").reason;
  EXPECT_FALSE (std::filesystem::exists (out.file ("fits/missing.ply")));
  EXPECT_EQ (morphreg::readJsonFile (out.file ("fits/missing.json"))["status"], "failed");
  // the observer heard the plan and every scan; the summary is on disk with the counts
  EXPECT_EQ (observer.plan.to_register, 3u);
  EXPECT_EQ (observer.plan.jobs, 2);
  EXPECT_EQ (observer.finished, 3);
  EXPECT_EQ (observer.last.ok, 2);
  EXPECT_EQ (observer.last.failed, 1);
  EXPECT_EQ (first.summary_base, out.file ("fits/summary"));
  const nlohmann::json summary = morphreg::readJsonFile (out.file ("fits/summary.json"));
  EXPECT_EQ (summary["counts"]["ok"], 2);
  EXPECT_EQ (summary["counts"]["failed"], 1);
  EXPECT_EQ (summary["shard"], "all");
  EXPECT_TRUE (summary["morphreg"].contains ("version"));
  EXPECT_TRUE (std::filesystem::exists (out.file ("fits/summary.csv")));

  // a rerun resumes: every scan is done, the failed one too unless retried
  RecordingObserver again;
  const BatchRegistrationOutcome resumed = run (out.file ("fits"), quickSettings (), &again);
  EXPECT_EQ (resumed.skipped, 3u);
  EXPECT_EQ (resumed.attempted, 0u);
  EXPECT_EQ (again.plan.done, 3u);
  EXPECT_TRUE (again.started.empty ());
  EXPECT_EQ (resumed.count ("ok"), 2u);
  BatchRegistrationSettings retry = quickSettings ();
  retry.retry_failed = true;
  RecordingObserver retried;
  EXPECT_EQ (run (out.file ("fits"), retry, &retried).attempted, 1u);
  EXPECT_EQ (retried.started, std::vector<std::string> ({"missing"}));

  // a changed setting registers every scan again, saying why
  BatchRegistrationSettings changed = quickSettings ();
  changed.scan.shape_prior *= 2.0;
  const BatchRegistrationOutcome redone = run (out.file ("fits"), changed, nullptr);
  EXPECT_EQ (redone.attempted, 3u);
  ASSERT_EQ (redone.redone.size (), 3u);
  EXPECT_NE (redone.redone[0].find ("made with other settings: shape_prior"), std::string::npos) << redone.redone[0];
}

TEST_F (BatchRegistrationTest, ACancelledRunLeavesItsScansPending)
{
  morphreg::test::TempDirectory out;
  const std::atomic<bool> cancel{true};
  const BatchRegistrationOutcome outcome = run (out.file ("fits"), quickSettings (), nullptr, &cancel);
  EXPECT_TRUE (outcome.cancelled);
  EXPECT_EQ (outcome.count ("pending"), 3u);
  EXPECT_EQ (morphreg::readJsonFile (out.file ("fits/summary.json"))["counts"]["pending"], 3);
  EXPECT_FALSE (std::filesystem::exists (out.file ("fits/.morphreg.lock"))); // released
}

TEST_F (BatchRegistrationTest, ShardsRegisterTheirSharesAndMergeIntoTheStudy)
{
  morphreg::test::TempDirectory out;
  BatchRegistrationSettings settings = quickSettings ();
  settings.shard = {1, 2};
  settings.jobs = 1;
  RecordingObserver observer;
  const BatchRegistrationOutcome outcome = run (out.file ("fits"), settings, &observer);
  ASSERT_EQ (outcome.rows.size (), 1u); // the second of three: positions 1, 3, ...
  EXPECT_EQ (outcome.rows[0].id, "head_1");
  EXPECT_EQ (outcome.summary_base, out.file ("fits/summary.shard-1-of-2"));
  const nlohmann::json summary = morphreg::readJsonFile (out.file ("fits/summary.shard-1-of-2.json"));
  EXPECT_EQ (summary["shard"], "1/2");
  EXPECT_EQ (summary["total"], 1);
  EXPECT_FALSE (std::filesystem::exists (out.file ("fits/head_0.json"))); // another shard's
  // without resume, a done scan is registered again
  settings.resume = false;
  EXPECT_EQ (run (out.file ("fits"), settings, nullptr).attempted, 1u);
  settings.resume = true;
  // a missing shard is named; with both, the merge holds every scan of the study once
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] { morphreg::mergeShardSummaries (morphreg::shardSummariesIn (out.file ("fits"))); }, "shard 0/2 is missing");
  settings.shard = {0, 2};
  run (out.file ("fits"), settings, nullptr);
  const morphreg::MergedSummary merged = morphreg::mergeShardSummaries (morphreg::shardSummariesIn (out.file ("fits")));
  EXPECT_EQ (merged.shards, 2);
  EXPECT_EQ (merged.rows.size (), 3u);
  EXPECT_EQ (merged.run, summary["run"]);
  // a shard of another run (other settings) is refused, naming the setting
  settings.scan.shape_prior *= 2.0;
  run (out.file ("fits"), settings, nullptr);
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] { morphreg::mergeShardSummaries (morphreg::shardSummariesIn (out.file ("fits"))); }, "shape_prior");
}

TEST_F (BatchRegistrationTest, BadSettingsAreRefusedNamingTheSetting)
{
  morphreg::test::TempDirectory out;
  const std::string model = study_->file ("model.h5"), manifest = study_->file ("manifest.csv");
  BatchRegistrationSettings settings = quickSettings ();
  settings.jobs = 0;
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] { BatchRegistration (model, manifest, out.file ("fits"), settings); }, "jobs 0");
  settings = quickSettings ();
  settings.shard = {2, 2};
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] { BatchRegistration (model, manifest, out.file ("fits"), settings); }, "shard 2/2");
  settings = quickSettings ();
  settings.threads_per_fit = -1;
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] { BatchRegistration (model, manifest, out.file ("fits"), settings); }, "threads_per_fit -1");
  settings = quickSettings ();
  settings.scan.colours = "rainbow";
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] { BatchRegistration (model, manifest, out.file ("fits"), settings); }, "colours 'rainbow'");
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] { BatchRegistration (model, manifest, "", quickSettings ()); }, "no output folder");
  // bad input found when the run starts: a missing model is named, and no folder is left behind
  expectErrorContaining<morphreg::Error> (
      [&] { BatchRegistration (study_->file ("none.h5"), manifest, out.file ("refused"), quickSettings ()).run (); },
      "none.h5");
  EXPECT_FALSE (std::filesystem::exists (out.file ("refused")));
}

} // namespace

// SPDX-License-Identifier: BSD-3-Clause
// The library's model building (pipeline/model_building.h), the sequence `morphreg build-model` runs: a model from
// meshes in files or in memory, its inputs listed, bad sets of meshes refused naming the mesh; from scans, the scans
// that fail left out and said why.
#include "registration/scan_protocol.h"
#include "support/expect_error.h"
#include "support/synthetic_heads.h"
#include "support/temp_directory.h"

#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_annotations.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/pipeline/model_building.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace
{
using morphreg::ModelBuildingOutcome;
using morphreg::TriangleMesh;
using morphreg::test::expectErrorContaining;

constexpr int kResolution = 20;

/** A few synthetic heads of one topology. */
std::vector<TriangleMesh>
heads (int count)
{
  std::vector<TriangleMesh> meshes;
  for (auto& head : morphreg::test::headGenerator (kResolution).population (count, 7))
    meshes.push_back (std::move (head.mesh));
  return meshes;
}

/** The vertices' mean over \a meshes. */
Eigen::Matrix3Xd
meanVertices (const std::vector<TriangleMesh>& meshes)
{
  Eigen::Matrix3Xd mean = Eigen::Matrix3Xd::Zero (3, meshes.front ().numVertices ());
  for (const TriangleMesh& mesh : meshes)
    mean += mesh.vertices;
  return mean / static_cast<double> (meshes.size ());
}

/** Without Procrustes the model's mean is the meshes' mean. */
morphreg::ModelFromMeshesSettings
unaligned ()
{
  morphreg::ModelFromMeshesSettings settings;
  settings.builder.align = false;
  return settings;
}

/** Counts what the observer hears. */
class CountingObserver : public morphreg::ModelBuildingObserver
{
public:
  void
  stageStarted (const std::string& stage, int count) override
  {
    stages.push_back (stage + " " + std::to_string (count));
  }
  void
  inputDone (int, const std::string&) override
  {
    ++done;
  }
  void
  inputLeftOut (const morphreg::ModelInput& input) override
  {
    left_out.push_back (input.id + ": " + input.reason);
  }
  void
  inputsTried (const std::vector<morphreg::ModelInput>& inputs) override
  {
    tried = inputs.size ();
  }

  std::vector<std::string> stages, left_out;
  int done = 0;
  std::size_t tried = 0;
};

TEST (ModelBuildingTest, MeshFilesGiveAModelWhoseMeanIsTheirsAndListTheInputs)
{
  const std::vector<TriangleMesh> meshes = heads (4);
  morphreg::test::TempDirectory directory;
  morphreg::MeshFolder folder;
  for (std::size_t k = 0; k < meshes.size (); ++k) {
    folder.files.push_back (directory.file ("head_" + std::to_string (k) + ".ply"));
    morphreg::saveTriangleMesh (folder.files.back (), meshes[k]);
  }
  morphreg::ModelFromMeshesSettings settings = unaligned ();
  settings.landmark_vertices = directory.file ("landmark_vertices.json");
  morphreg::saveLandmarkVertices (settings.landmark_vertices, morphreg::test::headGenerator (kResolution).landmarks ());
  morphreg::ModelFromMeshes building (settings);
  CountingObserver observer;
  building.setObserver (&observer);
  const ModelBuildingOutcome built = building.build (folder);

  const Eigen::Matrix3Xd mean = built.model->meanMesh ().vertices;
  EXPECT_LT ((mean - meanVertices (meshes)).cwiseAbs ().maxCoeff (), 1e-3); // mm; PLY stores floats
  ASSERT_EQ (built.inputs.size (), meshes.size ());
  for (std::size_t k = 0; k < meshes.size (); ++k) {
    EXPECT_EQ (built.inputs[k].file, folder.files[k]);
    EXPECT_TRUE (built.inputs[k].included);
  }
  EXPECT_EQ (built.model->landmarks (), morphreg::test::headGenerator (kResolution).landmarks ());
  EXPECT_EQ (observer.stages, std::vector<std::string>{"loading meshes 4"});
  EXPECT_EQ (observer.done, 4);
  const nlohmann::json summary = built.summary (settings.builder);
  EXPECT_EQ (summary["source"]["meshes"], 4);
  EXPECT_EQ (summary["vertices"], meshes.front ().numVertices ());
  EXPECT_FALSE (summary["settings"]["procrustes"].get<bool> ());
}

TEST (ModelBuildingTest, MeshesInMemoryWithRegionsGiveTheirMeanPerRegion)
{
  const std::vector<TriangleMesh> meshes = heads (5);
  morphreg::test::TempDirectory directory;
  morphreg::ModelFromMeshesSettings settings = unaligned ();
  settings.regions = directory.file ("regions.json");
  morphreg::saveRegionLabels (settings.regions, morphreg::test::headGenerator (kResolution).regions ());
  const ModelBuildingOutcome built = morphreg::ModelFromMeshes (settings).build (meshes, {"a", "b", "c", "d", "e"}, {});
  EXPECT_LT ((built.model->meanMesh ().vertices - meanVertices (meshes)).cwiseAbs ().maxCoeff (), 1e-9);
  EXPECT_EQ (built.model->numRegions (), morphreg::test::headGenerator (kResolution).regions ().names.size ());
  EXPECT_EQ (built.inputs.back ().id, "e");
  EXPECT_EQ (built.inputs.back ().row ()["status"], "ok");
}

TEST (ModelBuildingTest, MeshesInMemoryTakeTheirRegionsLandmarksAndProfileLineInMemory)
{
  const std::vector<TriangleMesh> meshes = heads (5);
  const auto& generator = morphreg::test::headGenerator (kResolution);
  morphreg::MeshAnnotations annotations{generator.regions (), generator.landmarks (), generator.profileLine ()};
  const ModelBuildingOutcome built =
      morphreg::ModelFromMeshes (unaligned ()).build (meshes, {"a", "b", "c", "d", "e"}, annotations);
  EXPECT_EQ (built.model->numRegions (), generator.regions ().names.size ());
  EXPECT_EQ (built.model->landmarks (), generator.landmarks ());
  EXPECT_EQ (built.model->profileLine (), generator.profileLine ());
  EXPECT_EQ (built.source["profile_line_vertices"], generator.profileLine ().size ());
  annotations.landmarks["nose_tip"] = static_cast<int> (meshes.front ().numVertices ()) + 5;
  EXPECT_THROW (morphreg::ModelFromMeshes (unaligned ()).build (meshes, {"a", "b", "c", "d", "e"}, annotations),
                morphreg::InvalidInputError);
  morphreg::ModelFromMeshesSettings bad = unaligned ();
  bad.builder.explained_variance = 0.0;
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] {
        morphreg::ModelFromMeshes (bad).build (meshes, {"a", "b", "c", "d", "e"});
      },
      "model builder setting variance = 0 is out of range (above 0 to 1)");
}

TEST (ModelBuildingTest, MeshesOutOfCorrespondenceOrTooFewAreRefusedNamingTheMesh)
{
  std::vector<TriangleMesh> meshes = heads (3);
  meshes.push_back (morphreg::test::headGenerator (kResolution + 4).population (1, 3).front ().mesh);
  const morphreg::ModelFromMeshes building (unaligned ());
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] {
        building.build (meshes, {"a.ply", "b.ply", "c.ply", "finer.ply"});
      },
      "finer.ply");
  expectErrorContaining<morphreg::InvalidInputError> ([&] { building.build ({meshes.front ()}, {"only.ply"}); },
                                                      "at least two meshes");
  morphreg::test::TempDirectory directory;
  morphreg::MeshFolder folder;
  for (const char* name : {"a.ply", "finer.ply"})
    folder.files.push_back (directory.file (name));
  morphreg::saveTriangleMesh (folder.files[0], meshes[0]);
  morphreg::saveTriangleMesh (folder.files[1], meshes[3]);
  expectErrorContaining<morphreg::InvalidInputError> ([&] { building.build (folder); }, "finer.ply");
  folder.files.pop_back ();
  expectErrorContaining<morphreg::InvalidInputError> ([&] { building.build (folder); }, "1 mesh(es) given");
}

TEST (ModelBuildingTest, RegionFileOfAnotherTopologyIsRefusedNamingIt)
{
  morphreg::test::TempDirectory directory;
  morphreg::ModelFromMeshesSettings settings = unaligned ();
  settings.regions = directory.file ("coarse_regions.json");
  morphreg::saveRegionLabels (settings.regions, morphreg::test::headGenerator (kResolution + 4).regions ());
  expectErrorContaining<morphreg::FormatError> (
      [&] {
        morphreg::ModelFromMeshes (settings).build (heads (3), {"a", "b", "c"});
      },
      "coarse_regions.json");
}

/** A registering model of the synthetic heads. */
morphreg::MorphableModel::ConstPtr
registeringModel ()
{
  const auto& generator = morphreg::test::headGenerator (kResolution);
  auto model = morphreg::ModelBuilder ().build (heads (6), generator.regions ());
  model->setLandmarks (generator.landmarks ());
  return model;
}

TEST (ModelBuildingTest, ScansThatFailAreLeftOutAndTheModelIsBuiltFromTheRest)
{
  const morphreg::MorphableModel::ConstPtr registering = registeringModel ();
  const std::vector<TriangleMesh> meshes = heads (4);
  morphreg::ModelFromScansSettings settings;
  settings.builder.align = false;
  morphreg::ModelFromScans building (registering, settings);
  // A step that resamples scan k into meshes[k], except the one that "failed its checks".
  building.setScanStep ([&] (const morphreg::ScanEntry& entry) {
    const std::size_t k = std::stoul (entry.id);
    morphreg::ScanForModel done;
    done.report = {{"status", k == 2 ? "failed" : "ok"}, {"checks", {{"failures", {"too far from the scan"}}}}};
    done.mesh = meshes[k];
    return done;
  });
  CountingObserver observer;
  building.setObserver (&observer);
  morphreg::ScanManifest scans;
  for (const char* id : {"0", "1", "2", "3"})
    scans.push_back ({id, std::string ("scan_") + id + ".ply", "", "list.csv"});
  const ModelBuildingOutcome built = building.build (scans, "list.csv");

  const std::vector<TriangleMesh> included = {meshes[0], meshes[1], meshes[3]};
  EXPECT_LT ((built.model->meanMesh ().vertices - meanVertices (included)).cwiseAbs ().maxCoeff (), 1e-9);
  EXPECT_EQ (built.model->numRegions (), registering->numRegions ());
  EXPECT_EQ (built.model->landmarks (), registering->landmarks ());
  ASSERT_EQ (built.inputs.size (), 4u);
  EXPECT_FALSE (built.inputs[2].included);
  EXPECT_EQ (built.inputs[2].row ()["reason"], "too far from the scan");
  EXPECT_EQ (built.inputs[2].row ()["scan"], "scan_2.ply");
  EXPECT_EQ (observer.left_out, std::vector<std::string>{"2: too far from the scan"});
  EXPECT_EQ (observer.tried, 4u);
  EXPECT_EQ (built.source["included"], 3);
}

TEST (ModelBuildingTest, UnreadableScansAreReportedAndTooFewRemainingIsRefusedNamingTheStudy)
{
  morphreg::ModelFromScans building (registeringModel ());
  CountingObserver observer;
  building.setObserver (&observer);
  const morphreg::ScanManifest scans = {{"a", "no_such_scan_a.ply", "", "study.csv:1"},
                                        {"b", "no_such_scan_b.ply", "", "study.csv:2"}};
  expectErrorContaining<morphreg::InvalidInputError> ([&] { building.build (scans, "study.csv"); },
                                                      "study.csv: 0 of 2 scans registered and resampled");
  ASSERT_EQ (observer.left_out.size (), 2u);
  EXPECT_NE (observer.left_out[0].find ("no_such_scan_a.ply"), std::string::npos) << observer.left_out[0];
  EXPECT_THROW (morphreg::ModelFromScans (nullptr), morphreg::InvalidInputError);
}

/** Scans of the heads \a first.. of heads (9) (the registering model's are the first six) written into
 *  \a directory with their landmarks, and a missing scan last. */
morphreg::ScanManifest
simulatedScans (const morphreg::MorphableModel& registering, const morphreg::test::TempDirectory& directory,
                std::size_t first)
{
  morphreg::ScanManifest scans;
  morphreg::test::ProtocolSettings protocol;
  protocol.points = 15000;
  const std::vector<TriangleMesh> subjects = heads (9);
  for (std::size_t k = first; k < subjects.size (); ++k) {
    const auto scan = morphreg::test::simulateProtocolScan (subjects[k], registering.landmarks (), k, protocol);
    const std::string id = "subject_" + std::to_string (k);
    scans.push_back ({id, directory.file (id + ".pcd"), directory.file (id + "_landmarks.json"), "folder"});
    morphreg::saveCloud (scans.back ().scan, *scan.cloud);
    morphreg::saveLandmarks (scans.back ().landmarks, scan.landmarks);
  }
  scans.push_back ({"missing", directory.file ("missing.pcd"), "", "folder"});
  return scans;
}

/** ModelFromScans' settings with 5 components per region, so that the fits are quick. */
morphreg::ModelFromScansSettings
fiveComponents ()
{
  morphreg::ModelFromScansSettings settings;
  settings.registration.components = {5};
  return settings;
}

TEST (ModelBuildingTest, SimulatedScansAreRegisteredResampledAndBuiltIntoAModel)
{
  const morphreg::MorphableModel::ConstPtr registering = registeringModel ();
  morphreg::test::TempDirectory directory;
  const morphreg::ScanManifest scans = simulatedScans (*registering, directory, 6);
  const ModelBuildingOutcome built = morphreg::ModelFromScans (registering, fiveComponents ()).build (scans, "folder");

  ASSERT_EQ (built.inputs.size (), 4u);
  for (std::size_t k = 0; k < 3; ++k) {
    const nlohmann::json row = built.inputs[k].row ();
    EXPECT_TRUE (built.inputs[k].included) << built.inputs[k].reason;
    // the scans' noise (1 mm per axis: 1.7 mm RMS in 3D) dominates the distance to the fit
    EXPECT_LT (row["fit_rms_mm"].get<double> (), 3.0) << row.dump ();
    EXPECT_GT (row["coverage"].get<double> (), 0.5) << row.dump ();
    EXPECT_EQ (built.inputs[k].report["settings"]["components"][0], 5);
  }
  EXPECT_FALSE (built.inputs[3].included);
  EXPECT_NE (built.inputs[3].reason.find ("missing.pcd"), std::string::npos) << built.inputs[3].reason;
  EXPECT_EQ (built.model->numVertices (), registering->numVertices ());
  EXPECT_EQ (built.model->numRegions (), registering->numRegions ());
  EXPECT_EQ (built.source["included"], 3);
}

TEST (ModelBuildingTest, EachScansFitReportAndResampledMeshAndTheSummaryAreWrittenIntoTheFolder)
{
  const morphreg::MorphableModel::ConstPtr registering = registeringModel ();
  morphreg::test::TempDirectory directory;
  const morphreg::ScanManifest scans = simulatedScans (*registering, directory, 7);
  morphreg::ModelFromScans building (registering, fiveComponents ());
  const std::string folder = directory.file ("reports");
  std::filesystem::create_directory (folder);
  building.writeScanFilesInto (folder, "registering.h5", "residual", {{"made_by", "the test"}});
  CountingObserver observer;
  building.setObserver (&observer);
  const ModelBuildingOutcome built = building.build (scans, "folder");
  EXPECT_EQ (built.source["included"], 2);

  const auto outputs = morphreg::ModelFromScans::scanFolderOutputs (scans, folder);
  ASSERT_EQ (outputs.size (), 3 * scans.size () + 1);
  EXPECT_EQ (outputs.back ().first, folder + "/summary.json");
  EXPECT_EQ (outputs[1].second, "the fit of scan 'subject_7'");
  for (const auto& [file, what] : outputs) {
    if (file.find ("missing") == std::string::npos || file.find (".json") != std::string::npos)
      EXPECT_TRUE (std::filesystem::exists (file)) << what;
  }
  EXPECT_FALSE (std::filesystem::exists (folder + "/missing_fit.ply")) << "a failed scan has its report alone";
  const nlohmann::json report = morphreg::readJsonFile (folder + "/subject_7.json");
  EXPECT_EQ (report["status"], "ok");
  EXPECT_EQ (report["made_by"], "the test");
  EXPECT_EQ (report["resampled_mesh"], folder + "/subject_7.ply");
  EXPECT_EQ (report["settings"]["components"][0], 5);
  EXPECT_EQ (morphreg::readJsonFile (folder + "/missing.json")["status"], "failed");
  const nlohmann::json summary = morphreg::readJsonFile (folder + "/summary.json");
  EXPECT_EQ (summary["scans"], 3);
  EXPECT_EQ (summary["included"], 2);
  EXPECT_EQ (summary["model"], "registering.h5");
  EXPECT_EQ (summary["made_by"], "the test");
  EXPECT_EQ (summary["rows"][2]["report"], folder + "/missing.json");
  EXPECT_EQ (morphreg::loadTriangleMesh (folder + "/subject_8.ply").numVertices (), registering->numVertices ());
}

TEST (ModelBuildingTest, ScanDefaultsFitCloselyAsTheCommandLineDocuments)
{
  const morphreg::ModelFromScansSettings settings;
  EXPECT_EQ (settings.registration.components, std::vector<int>{60});
  EXPECT_DOUBLE_EQ (*settings.registration.refinement_prior, 0.2);
}
} // namespace

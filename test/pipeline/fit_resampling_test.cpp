// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/pipeline/fit_resampling.h>
#include <morphreg/pipeline/scan_units.h>
#include <morphreg/synthetic/scan_simulator.h>

#include "support/expect_error.h"
#include "support/synthetic_heads.h"
#include "support/temp_directory.h"

#include <pcl/conversions.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

using morphreg::TriangleMesh;

namespace
{
/** A simulated scan of a coarse head and, as its fit, the head posed into the scan's frame. */
struct ScannedHead
{
  morphreg::synthetic::SimulatedScan scan;
  TriangleMesh fitted;

  ScannedHead ()
  {
    const TriangleMesh head = morphreg::test::headGenerator (20).sample (4).mesh;
    scan = morphreg::synthetic::ScanSimulator ().scan (head, 2);
    fitted = head;
    fitted.vertices = scan.head_to_scan * head.vertices;
  }
};

const ScannedHead&
scanned ()
{
  static const ScannedHead instance;
  return instance;
}

nlohmann::json
fitReport (bool passed)
{
  return {{"checks", {{"passed", passed}}}, {"scan", {{"scale_to_mm", 1.0}}}};
}
} // namespace

TEST (FitResamplingTest, WritesTheMeshColouredByStateIntoTheReport)
{
  const morphreg::test::TempDirectory dir;
  const std::string out = dir.file ("resampled.ply");
  nlohmann::json report = fitReport (true);
  std::ostringstream warnings;
  const auto result = morphreg::writeResampledFit (*scanned ().scan.cloud, "scan.pcd", scanned ().fitted, {},
                                                   {out, "state"}, report, warnings);
  ASSERT_TRUE (result);
  EXPECT_EQ (report["resampled_mesh"], out);
  EXPECT_EQ (report["resampled_mesh_colours"], "state");
  EXPECT_EQ (report["resampling"]["status"], "ok");
  EXPECT_GT (result->statistics.observed, result->statistics.vertices / 2);
  pcl::PointCloud<pcl::PointXYZRGB> written;
  pcl::fromPCLPointCloud2 (morphreg::loadPolygonMesh (out).cloud, written);
  ASSERT_EQ (static_cast<Eigen::Index> (written.size ()), result->mesh.vertices.cols ());
  int grey = 0, orange = 0;
  for (std::size_t v = 0; v < written.size (); ++v) {
    EXPECT_LT ((written[v].getVector3fMap ().cast<double> () - result->mesh.vertices.col (v)).norm (), 1e-3);
    grey += written[v].r == 200 && written[v].g == 200 && written[v].b == 200;
    orange += written[v].r == 240 && written[v].g == 120 && written[v].b == 20;
  }
  EXPECT_EQ (grey, result->statistics.observed);
  EXPECT_EQ (orange, result->statistics.filled);
  EXPECT_TRUE (warnings.str ().empty ());
}

TEST (FitResamplingTest, AFailedFitIsNotResampled)
{
  const morphreg::test::TempDirectory dir;
  nlohmann::json report = fitReport (false);
  std::ostringstream warnings;
  EXPECT_FALSE (morphreg::writeResampledFit (*scanned ().scan.cloud, "scan.pcd", scanned ().fitted, {},
                                             {dir.file ("resampled.ply")}, report, warnings));
  EXPECT_TRUE (report["resampled_mesh"].is_null ());
  EXPECT_EQ (report["resampling"]["status"], "skipped");
  EXPECT_FALSE (std::filesystem::exists (dir.file ("resampled.ply")));
}

TEST (FitResamplingTest, ScanColoursOfAScanWithoutThemAreRefusedNamingIt)
{
  const morphreg::test::TempDirectory dir;
  const std::string scan_file = dir.file ("grey_scan.pcd");
  morphreg::saveCloud (scan_file, *scanned ().scan.cloud);
  nlohmann::json report = fitReport (true);
  std::ostringstream warnings;
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> (
      [&] {
        morphreg::writeResampledFit (*scanned ().scan.cloud, scan_file, scanned ().fitted, {},
                                     {dir.file ("resampled.ply"), "scan"}, report, warnings);
      },
      scan_file);
}

namespace
{
/** The scan of scanned () in \a unit_to_mm (1: mm, 1000: m) in \a directory, with its landmarks (mm); the files. */
morphreg::LandmarkResamplingFiles
landmarkResamplingFiles (const morphreg::test::TempDirectory& directory, double unit_to_mm)
{
  pcl::PointCloud<pcl::PointNormal> cloud = *scanned ().scan.cloud;
  for (auto& point : cloud)
    point.getVector3fMap () /= static_cast<float> (unit_to_mm);
  morphreg::LandmarkResamplingFiles files{directory.file ("scan.pcd"),
                                          "",
                                          directory.file ("landmarks.json"),
                                          directory.file ("reference.ply"),
                                          {directory.file ("resampled.ply")}};
  morphreg::saveCloud (files.scan, cloud);
  morphreg::LandmarkPositions landmarks;
  for (const auto& [id, vertex] : morphreg::test::headGenerator (20).landmarks ())
    landmarks[id] = scanned ().fitted.vertices.col (vertex);
  morphreg::saveLandmarks (files.landmarks, landmarks);
  return files;
}
} // namespace

TEST (FitResamplingTest, AScanIsResampledIntoTheMeanWarpedOntoItsLandmarksInItsUnit)
{
  const morphreg::MorphableModel::Ptr model = morphreg::test::headModel (6, 5);
  for (const double unit_to_mm : {1.0, 1000.0}) {
    const morphreg::test::TempDirectory dir;
    const morphreg::LandmarkResamplingFiles files = landmarkResamplingFiles (dir, unit_to_mm);
    std::ostringstream warnings;
    const morphreg::LandmarkResampling outcome = morphreg::resampleFromLandmarks (
        *model, files, unit_to_mm == 1.0 ? "auto" : "m", morphreg::ResamplingSettings (), warnings);
    ASSERT_TRUE (outcome.result);
    EXPECT_EQ (outcome.unit.scale_to_mm, unit_to_mm);
    EXPECT_EQ (morphreg::unitConversionMessage (outcome.unit).empty (), unit_to_mm == 1.0);
    EXPECT_EQ (outcome.report["status"], "ok");
    EXPECT_EQ (outcome.report["reference"]["method"], "landmarks");
    EXPECT_EQ (outcome.report["scan"]["units"], unit_to_mm == 1.0 ? "mm" : "m");
    EXPECT_EQ (outcome.report["resampled_mesh"], files.resampled.path);
    EXPECT_GT (outcome.result->statistics.observed, outcome.result->statistics.vertices / 2);
    const TriangleMesh reference = morphreg::loadTriangleMesh (files.reference);
    EXPECT_EQ (reference.numVertices (), model->numVertices ());
    // the mean warped onto the scan's landmarks lies on the scan, in mm
    EXPECT_LT ((reference.vertices.rowwise ().mean () - scanned ().fitted.vertices.rowwise ().mean ()).norm (), 10.0);
  }
}

TEST (FitResamplingTest, LandmarkResamplingRefusesMissingOrStrayLandmarksAndDepthImagesInOtherUnits)
{
  const morphreg::MorphableModel::Ptr model = morphreg::test::headModel (6, 5);
  const morphreg::test::TempDirectory dir;
  morphreg::LandmarkResamplingFiles files = landmarkResamplingFiles (dir, 1.0);
  std::ostringstream warnings;
  const auto resample = [&] (const std::string& units) {
    morphreg::resampleFromLandmarks (*model, files, units, morphreg::ResamplingSettings (), warnings);
  };
  morphreg::LandmarkPositions stray = morphreg::loadLandmarks (files.landmarks);
  stray.begin ()->second += Eigen::Vector3d (0.0, 0.0, 5000.0); // a landmark file in another frame or unit
  morphreg::saveLandmarks (files.landmarks, stray);
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> ([&] { resample ("auto"); },
                                                                      "mm outside the scan");
  files.landmarks.clear ();
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> ([&] { resample ("auto"); }, "no landmark file");
  files.landmarks = dir.file ("landmarks.json");
  files.intrinsics = dir.file ("camera.json");
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> ([&] { resample ("cm"); }, "holds mm, not cm");
  files.resampled.colours = "scan";
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> ([&] { resample ("auto"); }, "has no colours");
  EXPECT_FALSE (std::filesystem::exists (files.resampled.path));
}

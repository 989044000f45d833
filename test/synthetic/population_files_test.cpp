// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_annotations.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/pipeline/photo_registration.h>
#include <morphreg/synthetic/population_files.h>

#include "support/expect_error.h"
#include "support/synthetic_heads.h"
#include "support/temp_directory.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

using morphreg::synthetic::SyntheticHead;

namespace
{
const morphreg::synthetic::HeadGenerator&
generator ()
{
  return morphreg::test::headGenerator ();
}

const std::vector<SyntheticHead>&
heads ()
{
  static const std::vector<SyntheticHead> population = generator ().population (3, 5);
  return population;
}

/** The largest distance between corresponding vertices (the files hold floats). */
double
maxVertexDistance (const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b)
{
  EXPECT_EQ (a.cols (), b.cols ());
  return a.cols () == b.cols () ? (a - b).colwise ().norm ().maxCoeff () : 1e9;
}
} // namespace

TEST (PopulationFilesTest, HeadsAndAnnotationsReadBack)
{
  const morphreg::test::TempDirectory dir;
  const std::string folder = dir.file ("population");
  std::vector<std::size_t> told;
  const nlohmann::json manifest = morphreg::synthetic::writePopulationFiles (
      folder, generator (), heads (), 5, {{"version", "test"}}, [&told] (std::size_t done) { told.push_back (done); });
  EXPECT_EQ (told, (std::vector<std::size_t>{1, 2, 3}));
  for (std::size_t i = 0; i < heads ().size (); ++i) {
    const morphreg::TriangleMesh head =
        morphreg::loadTriangleMesh (folder + "/" + manifest["heads"][i]["file"].get<std::string> ());
    EXPECT_LT (maxVertexDistance (head.vertices, heads ()[i].mesh.vertices), 1e-3) << i;
    EXPECT_EQ (head.triangles, heads ()[i].mesh.triangles) << i;
  }
  const morphreg::LandmarkPositions landmarks = morphreg::loadLandmarks (folder + "/head_002_landmarks.json");
  ASSERT_EQ (landmarks.size (), generator ().landmarks ().size ());
  for (const auto& [id, vertex] : generator ().landmarks ())
    EXPECT_LT ((landmarks.at (id) - heads ()[2].mesh.vertices.col (vertex)).norm (), 1e-3) << id;
  const auto vertices = static_cast<Eigen::Index> (generator ().numVertices ());
  const morphreg::RegionLabels regions = morphreg::loadRegionLabels (folder + "/regions.json", vertices);
  EXPECT_EQ (regions.names, generator ().regions ().names);
  EXPECT_EQ (regions.labels, generator ().regions ().labels);
  EXPECT_EQ (morphreg::loadLandmarkVertices (folder + "/landmark_vertices.json", vertices), generator ().landmarks ());
  nlohmann::json written = morphreg::readJsonFile (folder + "/population.json");
  EXPECT_EQ (written["morphreg"]["version"], "test");
  EXPECT_EQ (written["heads"][2]["seed"], 7);
  written.erase ("morphreg");
  EXPECT_EQ (written, manifest);
}

TEST (PopulationFilesTest, PhotoTruthReadByPhotoRegistration)
{
  const morphreg::test::TempDirectory dir;
  const std::string folder = dir.file ("study");
  morphreg::synthetic::writePopulationFiles (folder, generator (), heads (), 5);
  const morphreg::synthetic::PhotoSimulator simulator;
  const morphreg::synthetic::SimulatedPhotos photos =
      simulator.photograph (heads ()[1].mesh.vertices, morphreg::frontalLandmarks (generator ().landmarks ()),
                            generator ().profileLine (), 9);
  const nlohmann::json files = morphreg::synthetic::writePhotoFiles (folder, "photo_1", photos, 1);
  const morphreg::PhotoTruth truth = morphreg::readPhotoTruth (folder + "/" + files["truth"].get<std::string> ());
  EXPECT_LT (maxVertexDistance (truth.head.vertices, heads ()[1].mesh.vertices), 1e-3);
  const Eigen::Matrix3d linear = truth.head_to_photo.topLeftCorner<3, 3> ();
  const Eigen::Vector3d translation = truth.head_to_photo.topRightCorner<3, 1> ();
  EXPECT_TRUE (linear.isApprox (photos.scale * photos.rotation, 1e-12));
  EXPECT_TRUE (translation.isApprox (photos.translation, 1e-12));
  EXPECT_EQ (morphreg::loadProfileView (folder + "/photo_1_profile.json").silhouette ().size (),
             photos.profile.silhouette ().size ());
}

TEST (PopulationFilesTest, ScanWithItsPosedTruth)
{
  const morphreg::test::TempDirectory dir;
  const morphreg::TriangleMesh& head = heads ()[0].mesh;
  const morphreg::synthetic::SimulatedScan scan = morphreg::synthetic::ScanSimulator ().scan (head, 3);
  morphreg::synthetic::writeScanFiles (dir.file ("scans"), "scan_0", scan, head, generator ().landmarks ());
  const auto cloud = morphreg::loadCloud<pcl::PointNormal> (dir.file ("scans/scan_0.pcd"));
  EXPECT_EQ (cloud->size (), scan.cloud->size ());
  const morphreg::TriangleMesh posed = morphreg::loadTriangleMesh (dir.file ("scans/scan_0_truth.ply"));
  EXPECT_LT (maxVertexDistance (posed.vertices, scan.head_to_scan * head.vertices), 1e-3);
  const nlohmann::json truth = morphreg::readJsonFile (dir.file ("scans/scan_0_truth.json"));
  EXPECT_EQ (truth["source_triangle"].get<std::vector<int>> (), scan.source_triangle);
  EXPECT_EQ (truth["num_outliers"], scan.num_outliers);
  const std::vector<double> pose = truth["head_to_scan"];
  EXPECT_TRUE (Eigen::Map<const Eigen::Matrix4d> (pose.data ()).isApprox (scan.head_to_scan.matrix (), 1e-12));
  EXPECT_FALSE (truth.contains ("morphreg"));
}

TEST (PopulationFilesTest, AStudyOfHeadsScansAndPhotosWithItsProgress)
{
  const morphreg::test::TempDirectory dir;
  const std::string folder = dir.file ("study");
  std::filesystem::create_directory (folder);
  morphreg::synthetic::SyntheticStudySettings settings;
  settings.count = 3;
  settings.resolution = 20;
  settings.scans = 2;
  settings.photos = 1;
  settings.scanner.angular_samples = 100;
  settings.scanner.row_spacing = 5.0;
  std::vector<std::string> told;
  morphreg::synthetic::writeSyntheticStudy (
      folder, settings, {{"by", "the test"}}, [&] (const std::string& stage, int done, int count) {
        told.push_back (stage + " " + std::to_string (done) + "/" + std::to_string (count));
      });
  EXPECT_EQ (told.back (), "scanning heads 2/2");
  EXPECT_NE (std::find (told.begin (), told.end (), "writing heads 3/3"), told.end ());
  for (const char* file : {"population.json", "scan_1.pcd", "scan_1_truth.ply", "photo_0_profile.json"})
    EXPECT_TRUE (std::filesystem::exists (folder + "/" + file)) << file;
  EXPECT_FALSE (std::filesystem::exists (folder + "/scan_2.pcd"));
  EXPECT_FALSE (std::filesystem::exists (folder + "/photo_1_profile.json"));

  settings.scans = 4;
  const std::string refused = dir.file ("refused");
  std::filesystem::create_directory (refused);
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> (
      [&] { morphreg::synthetic::writeSyntheticStudy (refused, settings); }, "4 scans and 1 photo pairs of 3 heads");
  settings.scans = 1;
  settings.scanner.noise_sigma = -1.0;
  EXPECT_THROW (morphreg::synthetic::writeSyntheticStudy (refused, settings), morphreg::InvalidInputError);
  EXPECT_TRUE (std::filesystem::is_empty (refused)) << "nothing written";
}

TEST (PopulationFilesTest, UnwritableFolderIsNamed)
{
  const morphreg::test::TempDirectory dir;
  std::ofstream (dir.file ("a_file")) << "not a folder";
  const std::string folder = dir.file ("a_file/population");
  morphreg::test::expectErrorContaining<morphreg::IoError> (
      [&] { morphreg::synthetic::writePopulationFiles (folder, generator (), heads (), 5); }, folder);
}

// SPDX-License-Identifier: BSD-3-Clause
// Importers of the real evaluation surfaces: MNE's fsaverage scalp with its fiducials (metres -> mm) and MediaPipe's
// canonical face (centimetres -> mm), and the errors for missing or malformed files.
#include <morphreg/common/error.h>
#include <morphreg/datasets/fsaverage_head.h>
#include <morphreg/datasets/mediapipe_face.h>
#include <morphreg/io/mesh_io.h>
#include "support/temp_directory.h"
#include "support/test_meshes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace
{
const std::string kData (MORPHREG_SHARED_DATA_DIR);
const std::string kFsaverage = kData + "/mne_fsaverage_head";
const std::string kMediaPipe = kData + "/mediapipe_canonical_face/canonical_face_model.obj";

/** True if \a call throws \a Exception whose message contains \a text. */
template <typename Exception, typename Call>
bool
throwsMentioning (Call call, const std::string& text)
{
  try {
    call ();
  }
  catch (const Exception& e) {
    return std::string (e.what ()).find (text) != std::string::npos;
  }
  return false;
}

TEST (RealDataImportTest, FsaverageHeadLoadsInMillimetres)
{
  if (!std::filesystem::exists (kFsaverage + "/fsaverage_head.ply"))
    GTEST_SKIP () << "fsaverage head not found in " << kFsaverage << " (../shared/data is absent)";
  const auto head = morphreg::loadFsaverageHead (kFsaverage);
  EXPECT_EQ (head.mesh.numVertices (), 2033);
  EXPECT_EQ (head.mesh.numTriangles (), 4062);
  // README: nasion at (0.0015, 0.0851, -0.0348) m; LPA / RPA at x = -0.0806 / +0.0844 m.
  EXPECT_TRUE (head.landmarks.at ("nasion").isApprox (Eigen::Vector3d (1.4676, 85.0672, -34.8361), 1e-4));
  EXPECT_NEAR (head.landmarks.at ("left_tragus").x (), -80.6, 0.1);
  EXPECT_NEAR (head.landmarks.at ("right_tragus").x (), 84.4, 0.1);
  const Eigen::Vector3d extent = head.mesh.vertices.rowwise ().maxCoeff () - head.mesh.vertices.rowwise ().minCoeff ();
  EXPECT_GT (extent.minCoeff (), 100.0) << "a head is more than 10 cm across in every direction";
  EXPECT_LT (extent.maxCoeff (), 300.0);
}

TEST (RealDataImportTest, MediaPipeFaceLoadsInMillimetresWithItsLandmarks)
{
  if (!std::filesystem::exists (kMediaPipe))
    GTEST_SKIP () << "MediaPipe canonical face not found at " << kMediaPipe << " (../shared/data is absent)";
  const auto face = morphreg::loadMediaPipeFace (kMediaPipe);
  EXPECT_EQ (face.mesh.numVertices (), 468);
  EXPECT_EQ (face.mesh.numTriangles (), 898);
  // README bounding box (cm): (-7.74, -9.40, -2.44) to (7.74, 8.26, 7.59).
  EXPECT_NEAR (face.mesh.vertices.row (0).maxCoeff (), 77.4, 0.1);
  EXPECT_NEAR (face.mesh.vertices.row (1).minCoeff (), -94.0, 0.1);
  Eigen::Index front = 0, lowest = 0;
  face.mesh.vertices.row (2).maxCoeff (&front);
  face.mesh.vertices.row (1).minCoeff (&lowest);
  EXPECT_EQ (face.landmarks.at ("nose_tip"), front);
  EXPECT_EQ (face.landmarks.at ("chin"), lowest);
  EXPECT_LT (face.mesh.vertices (0, face.landmarks.at ("right_eye_outer")), 0.0) << "the subject's right is -X";
  EXPECT_GT (face.mesh.vertices (0, face.landmarks.at ("left_mouth_corner")), 0.0);
}

TEST (RealDataImportTest, MissingOrMalformedFilesAreReported)
{
  const morphreg::test::TempDirectory folder;
  EXPECT_TRUE (throwsMentioning<morphreg::IoError> ([&] { morphreg::loadFsaverageHead (folder.file ("none")); },
                                                    "fsaverage_head.ply"));
  EXPECT_TRUE (throwsMentioning<morphreg::IoError> ([&] { morphreg::loadMediaPipeFace (folder.file ("none.obj")); },
                                                    "none.obj"));

  // A scalp file with landmarks that are malformed in several ways.
  morphreg::saveTriangleMesh (folder.file ("fsaverage_head.ply"), morphreg::test::makeCube ());
  const std::string json = folder.file ("fsaverage_head_landmarks.json");
  const auto expectFormatError = [&] (const std::string& content, const std::string& mention) {
    std::ofstream (json) << content;
    EXPECT_TRUE (
        throwsMentioning<morphreg::FormatError> ([&] { morphreg::loadFsaverageHead (folder.file ("")); }, mention))
        << content;
  };
  EXPECT_THROW (morphreg::loadFsaverageHead (folder.file ("")), morphreg::IoError) << "no landmarks file yet";
  expectFormatError ("not json", "fsaverage_head_landmarks.json");
  expectFormatError (R"({"units": "millimetres", "fiducials_xyz_m": {}})", "metres");
  expectFormatError (R"({"units": "metres"})", "fiducials_xyz_m");
  expectFormatError (R"({"units": "metres", "fiducials_xyz_m": {"nasion": [0, 0, 0], "LPA": [1, 0, 0]}})", "RPA");
  expectFormatError (R"({"units": "metres", "fiducials_xyz_m": {"nasion": [0, 0, "x"], "LPA": [1, 0, 0],
                         "RPA": [2, 0, 0]}})",
                     "nasion");
  std::ofstream (json) << R"({"units": "metres", "fiducials_xyz_m": {"nasion": [0, 0.1, 0], "LPA": [-0.08, 0, 0],
                              "RPA": [0.08, 0, 0]}})";
  const auto head = morphreg::loadFsaverageHead (folder.file (""));
  EXPECT_TRUE (head.landmarks.at ("nasion").isApprox (Eigen::Vector3d (0.0, 100.0, 0.0)));
  EXPECT_DOUBLE_EQ (head.mesh.vertices.maxCoeff (), 1000.0) << "a 2 m cube in metres is 2000 mm";

  // An OBJ that is not MediaPipe's face.
  morphreg::saveTriangleMesh (folder.file ("cube.obj"), morphreg::test::makeCube ());
  EXPECT_TRUE (throwsMentioning<morphreg::FormatError> ([&] { morphreg::loadMediaPipeFace (folder.file ("cube.obj")); },
                                                        "cube.obj"));
}

} // namespace

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/ict_facekit.h>
#include <morphreg/model/ict_region_model.h>
#include "support/temp_directory.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using morphreg::MorphableModel;

namespace
{
const std::string kIctDirectory = std::string (MORPHREG_SHARED_DATA_DIR) + "/ict_facekit";

#define REQUIRE_ICT()                                                                                                  \
  if (!std::filesystem::exists (kIctDirectory + "/ict_head_pca_basis.npy"))                                            \
  GTEST_SKIP () << "ICT-FaceKit data not found in " << kIctDirectory << " (../shared/data is absent)"

const MorphableModel&
ict ()
{
  static const MorphableModel::ConstPtr model = morphreg::loadIctFaceKit (kIctDirectory);
  return *model;
}

/** Index of each vertex's mirror image (x -> -x) on the mean mesh. */
std::vector<int>
mirrorPairs (const Eigen::Matrix3Xd& mean)
{
  std::vector<int> pairs (mean.cols ());
  for (Eigen::Index i = 0; i < mean.cols (); ++i) {
    const Eigen::Vector3d mirrored (-mean (0, i), mean (1, i), mean (2, i));
    Eigen::Index nearest = 0;
    (mean.colwise () - mirrored).colwise ().squaredNorm ().minCoeff (&nearest);
    pairs[i] = static_cast<int> (nearest);
  }
  return pairs;
}

/** RMS distance (mm) between a head and its mirror image. */
double
asymmetry (const Eigen::Matrix3Xd& head, const std::vector<int>& pairs)
{
  double sum = 0.0;
  for (Eigen::Index i = 0; i < head.cols (); ++i)
    sum += (Eigen::Vector3d (-head (0, i), head (1, i), head (2, i)) - head.col (pairs[i])).squaredNorm ();
  return std::sqrt (sum / static_cast<double> (head.cols ()));
}
} // namespace

TEST (ModelIoTest, IctFaceKitLoadsInMillimetresAndSamplesLookLikeHeads)
{
  REQUIRE_ICT ();
  const MorphableModel& model = ict ();
  ASSERT_EQ (model.numVertices (), 11248);
  ASSERT_EQ (model.triangles ().cols (), 22288);
  ASSERT_EQ (model.globalBasis ().cols (), 100);
  EXPECT_NEAR (model.globalVariances ()[0], 259591.47, 1.0); // 2595.9 cm^2 in mm^2
  const Eigen::MatrixXd gram = model.globalBasis ().transpose () * model.globalBasis ();
  EXPECT_LT ((gram - Eigen::MatrixXd::Identity (100, 100)).cwiseAbs ().maxCoeff (), 1e-4);
  EXPECT_EQ (model.landmarkVertex ("nose_tip"), 4857);
  EXPECT_EQ (model.landmarkVertex ("chin"), 966);
  EXPECT_EQ (model.landmarkVertex ("right_eye_outer"), 1507);
  EXPECT_EQ (model.landmarkVertex ("left_tragus"), 7321);
  EXPECT_EQ (model.landmarkVertex ("right_tragus"), 8048);
  EXPECT_EQ (model.landmarkVertex ("nasion"), 1358);
  EXPECT_NEAR (model.meanVertex (4857).z (), 130.69, 0.01);
  EXPECT_GT (model.meanVertex (model.landmarkVertex ("left_tragus")).x (), 0.0); // +X is the subject's left
  ASSERT_GE (model.profileLine ().size (), 100u);
  for (const int v : model.profileLine ())
    EXPECT_EQ (model.meanVertex (v).x (), 0.0);

  const Eigen::Map<const Eigen::Matrix3Xd> mean (model.mean ().data (), 3, model.numVertices ());
  const std::vector<int> pairs = mirrorPairs (mean);
  EXPECT_LT (asymmetry (mean, pairs), 0.01); // float32 centimetres
  const Eigen::Vector3d mean_extent = mean.rowwise ().maxCoeff () - mean.rowwise ().minCoeff ();
  EXPECT_NEAR (mean_extent.x (), 248.3, 0.5); // README bounding box, in mm
  std::mt19937_64 rng (17);
  for (int s = 0; s < 5; ++s) {
    const Eigen::Matrix3Xd head = model.generate (model.sampleCoefficients (rng, model.allComponents ()));
    const Eigen::Vector3d extent = head.rowwise ().maxCoeff () - head.rowwise ().minCoeff ();
    for (int a = 0; a < 3; ++a) {
      EXPECT_GT (extent[a], 0.75 * mean_extent[a]) << "sample " << s << " axis " << a;
      EXPECT_LT (extent[a], 1.3 * mean_extent[a]) << "sample " << s << " axis " << a;
    }
    EXPECT_LT (asymmetry (head, pairs), 0.05 * mean_extent.x ()) << "sample " << s;
    EXPECT_GT (head (2, model.landmarkVertex ("nose_tip")), head (2, model.landmarkVertex ("left_tragus")) + 50.0);
  }
}

TEST (ModelIoTest, IctFaceKitCorruptFilesGiveClearErrors)
{
  REQUIRE_ICT ();
  morphreg::test::TempDirectory directory;
  for (const char* name :
       {"ict_head_mean.ply", "ict_head_pca_basis.npy", "ict_head_pca_eigenvalues.npy", "ict_head_model.json"})
    std::filesystem::copy_file (kIctDirectory + "/" + name, directory.file (name));
  // Truncated basis.
  std::filesystem::resize_file (directory.file ("ict_head_pca_basis.npy"), 1000000);
  try {
    morphreg::loadIctFaceKit (directory.file (""));
    FAIL () << "expected a FormatError";
  }
  catch (const morphreg::FormatError& e) {
    EXPECT_NE (std::string (e.what ()).find ("ict_head_pca_basis.npy"), std::string::npos) << e.what ();
    EXPECT_NE (std::string (e.what ()).find ("truncated"), std::string::npos) << e.what ();
  }
  std::filesystem::copy_file (kIctDirectory + "/ict_head_pca_basis.npy", directory.file ("ict_head_pca_basis.npy"),
                              std::filesystem::copy_options::overwrite_existing);
  // A landmark index out of range.
  std::ofstream (directory.file ("ict_head_model.json"))
      << R"({"num_vertices": 11248, "landmarks": {"multipie68": [)" << 99999
      << std::string (67 * 3, ' ')
             .replace (0, 67 * 3,
                       [] {
                         std::string rest;
                         for (int k = 0; k < 67; ++k)
                           rest += ", 1";
                         return rest;
                       }())
      << "]}}";
  try {
    morphreg::loadIctFaceKit (directory.file (""));
    FAIL () << "expected a FormatError";
  }
  catch (const morphreg::FormatError& e) {
    EXPECT_NE (std::string (e.what ()).find ("99999"), std::string::npos) << e.what ();
  }
  std::filesystem::remove (directory.file ("ict_head_mean.ply"));
  EXPECT_THROW (morphreg::loadIctFaceKit (directory.file ("")), morphreg::IoError);
}

TEST (ModelBuilderTest, IctSevenRegionModelFromSamples)
{
  REQUIRE_ICT ();
  morphreg::ModelBuilderSettings settings;
  settings.max_components = 10;
  const MorphableModel::Ptr regional = morphreg::buildIctRegionModel (ict (), 40, 3, settings);
  ASSERT_EQ (regional->numRegions (), 7);
  const std::vector<std::string> names = {"eyes", "nose", "mouth", "ears", "chin", "cheeks", "skull_neck"};
  for (int j = 0; j < 7; ++j) {
    EXPECT_EQ (regional->region (j).name, names[j]);
    EXPECT_GT (regional->region (j).vertices.size (), 50u) << names[j];
    EXPECT_EQ (regional->region (j).basis.cols (), 10) << names[j];
  }
  EXPECT_FALSE (regional->gammaPairs ().empty ());
  EXPECT_EQ (regional->landmarkVertex ("nose_tip"), 4857);
  // The nose tip belongs to the nose region with full weight.
  const auto entries = regional->vertexEntries (4857);
  ASSERT_EQ (entries.size (), 1);
  EXPECT_EQ (entries.begin ()->region, 1);
  // The regional model reproduces a fresh ICT head better than its mean does.
  std::mt19937_64 rng (99);
  const Eigen::Matrix3Xd head = ict ().generate (ict ().sampleCoefficients (rng, ict ().allComponents ()));
  const auto projection = regional->project (head, regional->allComponents (), 1e-3);
  const Eigen::Map<const Eigen::VectorXd> flat (head.data (), head.size ());
  const double mean_error = std::sqrt ((flat - regional->mean ()).squaredNorm () / static_cast<double> (head.cols ()));
  EXPECT_LT (projection.rms_error, 0.75 * mean_error);
}

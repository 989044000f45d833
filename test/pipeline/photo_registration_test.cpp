// SPDX-License-Identifier: BSD-3-Clause
// PhotoRegistration, the photo fit every front end runs: photos read from their files, the fit, its report and
// warnings, the evaluation against a known head through its truth file, the texture, and bad input.
#include "photo/photo_test_model.h"

#include "support/expect_error.h"
#include "support/temp_directory.h"

#include <morphreg/common/error.h>
#include <morphreg/io/fitted_mesh_io.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/rgb_image_io.h>
#include <morphreg/pipeline/photo_registration.h>
#include <morphreg/synthetic/photo_simulator.h>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace
{
using morphreg::FormatError;
using morphreg::InvalidInputError;
using morphreg::PhotoRegistration;
using morphreg::PhotoRegistrationOutcome;
using morphreg::PhotoSet;
using morphreg::PhotoSetFiles;
using morphreg::test::expectErrorContaining;
using morphreg::test::TempDirectory;

constexpr std::uint64_t kUnseenSeed = 700000;

/** An unseen head, its photos as files (profile, frontal, truth) and the truth's similarity. */
struct PhotographedHead
{
  morphreg::TriangleMesh head;
  morphreg::synthetic::SimulatedPhotos photos;
  PhotoSetFiles files;
  std::string truth;
};

PhotographedHead
photographedHead (const TempDirectory& directory)
{
  const auto& generator = morphreg::test::headGenerator (morphreg::test::kPhotoResolution);
  morphreg::TriangleMesh mesh = generator.sample (kUnseenSeed).mesh;
  auto photos = morphreg::synthetic::PhotoSimulator ().photograph (mesh.vertices, morphreg::test::frontalLandmarks (),
                                                                   generator.profileLine (), kUnseenSeed);
  PhotographedHead result{std::move (mesh), std::move (photos), {}, directory.file ("truth.json")};
  result.files.profile = directory.file ("profile.json");
  result.files.frontal = directory.file ("frontal.json");
  morphreg::saveProfileView (result.files.profile, result.photos.profile);
  morphreg::saveFrontalView (result.files.frontal, result.photos.frontal);
  morphreg::saveTriangleMesh (directory.file ("head.ply"), result.head);
  Eigen::Matrix4d head_to_photo = Eigen::Matrix4d::Identity ();
  head_to_photo.topLeftCorner<3, 3> () = result.photos.scale * result.photos.rotation;
  head_to_photo.topRightCorner<3, 1> () = result.photos.translation;
  morphreg::writeJsonFile (
      result.truth, {{"head", "head.ply"},
                     {"head_to_photo", std::vector<double> (head_to_photo.data (), head_to_photo.data () + 16)}});
  return result;
}

/** Remembers what an observer hears. */
struct RecordingObserver : morphreg::PhotoRegistrationObserver
{
  std::string started;

  void
  fitStarted (const std::string& model, const std::string& sources, const std::string& approach) override
  {
    started = model + " | " + sources + " | " + approach;
  }
};

TEST (PhotoRegistrationTest, FitsThePairFromItsFilesEvaluatesItAgainstTheTruthFileAndTexturesIt)
{
  const TempDirectory directory;
  const PhotographedHead head = photographedHead (directory);
  PhotoRegistration registration (morphreg::test::photoTestModel ().model, "test model");
  RecordingObserver observer;
  registration.setObserver (&observer);
  PhotoSet photos = morphreg::readPhotoSet (head.files);
  ASSERT_EQ (photos.views.size (), 2u);
  const PhotoRegistrationOutcome outcome = registration.fit (photos);
  EXPECT_EQ (observer.started, "test model | " + head.files.profile + " and " + head.files.frontal + " | joint");
  EXPECT_EQ (outcome.report["status"], "ok");
  EXPECT_EQ (outcome.report["inputs"]["model"], "test model");
  EXPECT_EQ (outcome.report["settings"]["approach"], "joint");
  EXPECT_EQ (outcome.report["warnings"].size (), outcome.warnings.size ());

  // The truth file's evaluation equals the error computed from the known pose, and the fit beats the mean head.
  const morphreg::PhotoTruthErrors errors =
      morphreg::photoTruthErrors (morphreg::readPhotoTruth (head.truth), outcome.fit);
  const auto& p = head.photos;
  const Eigen::Matrix3Xd back =
      p.rotation.transpose () * (outcome.fit.image_mesh.vertices.colwise () - p.translation) / p.scale;
  const double rms = std::sqrt ((back - head.head.vertices).colwise ().squaredNorm ().mean ());
  EXPECT_NEAR (errors.json["truth_error_mm"]["rms"].get<double> (), rms, 1e-6);
  EXPECT_NEAR (errors.vertex_errors.norm () / std::sqrt (errors.vertex_errors.size ()), rms, 1e-6);
  EXPECT_NEAR (errors.json["truth_scale_ratio"].get<double> (), outcome.fit.scale / p.scale, 1e-12);
  const Eigen::Matrix3Xd& mean_head = morphreg::test::photoTestModel ().training_mean;
  const double mean_rms = std::sqrt ((mean_head - head.head.vertices).colwise ().squaredNorm ().mean ());
  std::cout << "unseen head from its photo files: vertex RMS " << rms << " mm (the mean head " << mean_rms << ")\n";
  EXPECT_LT (rms, mean_rms);

  // The mesh file: coloured by the truth's errors (also its quality), or plain without a truth or photo pixels.
  nlohmann::json report = outcome.report;
  EXPECT_EQ (morphreg::writePhotoFitMesh (directory.file ("truth.ply"), outcome.fit, photos, head.truth, 5.0, report),
             "error against the truth, 0-5.0 mm");
  EXPECT_NEAR (report["truth_error_mm"]["rms"].get<double> (), rms, 1e-6);
  const morphreg::FittedMeshFile written = morphreg::loadFittedMesh (directory.file ("truth.ply"));
  ASSERT_TRUE (written.residuals);
  EXPECT_LT ((*written.residuals - errors.vertex_errors).cwiseAbs ().maxCoeff (), 1e-4);
  EXPECT_EQ (morphreg::writePhotoFitMesh (directory.file ("plain.ply"), outcome.fit, photos, "", 5.0, report), "none");
  EXPECT_FALSE (morphreg::loadFittedMesh (directory.file ("plain.ply")).residuals);

  // The texture comes from the views that have pixels: none here, then a red frontal photo.
  EXPECT_FALSE (morphreg::photoTexture (outcome.fit, photos)) << "no view has pixels";

  morphreg::RgbImage& frontal = photos.images.back ();
  const auto& size = head.photos.frontal.normalisation ();
  frontal.width = size.width ();
  frontal.height = size.height ();
  frontal.data.assign (3 * static_cast<std::size_t> (frontal.width) * frontal.height, 0);
  for (std::size_t i = 0; i < frontal.data.size (); i += 3)
    frontal.data[i] = 200; // red everywhere
  const auto texture = morphreg::photoTexture (outcome.fit, photos);
  ASSERT_TRUE (texture);
  ASSERT_GT (texture->visibleCount (), 0);
  for (int v = 0; v < static_cast<int> (texture->visible.size ()); ++v)
    if (texture->visible[v]) {
      EXPECT_EQ (texture->colours.col (v).cast<int> (), Eigen::Vector3i (200, 0, 0)) << "vertex " << v;
      break;
    }
  EXPECT_EQ (morphreg::writePhotoFitMesh (directory.file ("photo.ply"), outcome.fit, photos, "", 5.0, report),
             "the photos, blended by angle (grey where unseen)");
  EXPECT_EQ (report["texture"]["photos"], 1);
  EXPECT_EQ (report["texture"]["visible_vertices"], texture->visibleCount ());
}

TEST (PhotoRegistrationTest, BadInputIsNamed)
{
  const TempDirectory directory;
  const PhotographedHead head = photographedHead (directory);
  PhotoSetFiles mixed = head.files;
  mixed.views.push_back ({directory.file ("view.png"), "", "", ""});
  expectErrorContaining<InvalidInputError> ([&] { morphreg::readPhotoSet (mixed); }, "cannot be fitted together");
  expectErrorContaining<InvalidInputError> ([&] { morphreg::readPhotoSet ({}); }, "no photos");
  PhotoSetFiles photo_alone{{}, head.files.profile, "", directory.file ("frontal.png")};
  expectErrorContaining<InvalidInputError> ([&] { morphreg::readPhotoSet (photo_alone); },
                                            directory.file ("frontal.png") + ": a frontal photo needs its frontal");

  morphreg::RgbImage small{4, 3, std::vector<unsigned char> (36, 128)};
  morphreg::saveRgbImage (directory.file ("small.png"), small);
  PhotoSetFiles wrong_size = head.files;
  wrong_size.photo = directory.file ("small.png");
  expectErrorContaining<InvalidInputError> ([&] { morphreg::readPhotoSet (wrong_size); },
                                            "small.png is 4 x 3 px, but " + head.files.frontal + " annotates a");

  auto no_profile = std::make_shared<morphreg::MorphableModel> (*morphreg::test::photoTestModel ().model);
  no_profile->setProfileLine ({});
  expectErrorContaining<InvalidInputError> (
      [&] { PhotoRegistration (no_profile, "plain.h5").fit (morphreg::readPhotoSet (head.files)); },
      "plain.h5: the model has no profile line");

  morphreg::writeJsonFile (directory.file ("bad_truth.json"), {{"head", "head.ply"}, {"head_to_photo", {1, 2}}});
  expectErrorContaining<FormatError> ([&] { morphreg::readPhotoTruth (directory.file ("bad_truth.json")); },
                                      "bad_truth.json: head_to_photo has 2 numbers, not 16");
  morphreg::PhotoTruth other = morphreg::readPhotoTruth (head.truth);
  other.head.vertices.conservativeResize (3, other.head.vertices.cols () - 1);
  other.source = "small_truth.json";
  morphreg::PhotoFit fit;
  fit.image_mesh = head.head;
  expectErrorContaining<InvalidInputError> ([&] { morphreg::photoTruthErrors (other, fit); },
                                            "small_truth.json: " + std::to_string (other.head.numVertices ()) +
                                                " vertices, expected");
}
} // namespace

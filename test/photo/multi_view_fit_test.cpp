// SPDX-License-Identifier: BSD-3-Clause
// PhotoFitting on perspective photos from any direction (issue 34, item 2): synthetic heads not in the model's
// training set, photographed by pinhole cameras 1 m away from the front and 30 degrees to either side, each photo
// marking the landmarks that face its camera with 1 px of noise; the fit (cameras given, or estimated from the
// landmarks) against the true head, and the bad views each names.
#include "photo_test_model.h"
#include "support/expect_error.h"
#include "support/accuracy_bound.h"

#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/photo/photo_fitting.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <iostream>
#include <random>

namespace
{
using morphreg::InvalidInputError;
using morphreg::PhotoCamera;
using morphreg::PhotoFit;
using morphreg::PhotoView;
using morphreg::test::expectErrorContaining;

constexpr int kWidth = 1200, kHeight = 1600;

/** A camera 1 m in front of the head's origin, turned \a degrees about Y, f 3000 px. */
PhotoCamera
cameraAt (double degrees)
{
  Eigen::Matrix3d K;
  K << 3000.0, 0.0, 600.0, 0.0, 3000.0, 800.0, 0.0, 0.0, 1.0;
  const Eigen::Matrix3d look = Eigen::Vector3d (1.0, -1.0, -1.0).asDiagonal (); // along -Z, image y down
  const Eigen::Matrix3d R = look * Eigen::AngleAxisd (degrees * M_PI / 180.0, Eigen::Vector3d::UnitY ()).matrix ();
  return PhotoCamera::perspective (K, R, Eigen::Vector3d (0.0, 0.0, 1000.0), "camera");
}

/** The photo of \a head by \a camera: the frontal landmarks whose vertex faces the camera (cosine above 0.3), with
 *  1 px of noise; the camera set when \a given. */
PhotoView
photograph (const Eigen::Matrix3Xd& head, const PhotoCamera& camera, bool given, std::uint64_t seed)
{
  const morphreg::TriangleMesh mesh{head, morphreg::test::photoTestModel ().model->triangles ()};
  const Eigen::Matrix3Xd normals = morphreg::vertexNormals (mesh);
  std::mt19937_64 rng (seed);
  std::normal_distribution<double> noise (0.0, 1.0);
  morphreg::LandmarkPixels pixels;
  for (const auto& [id, vertex] : morphreg::test::frontalLandmarks ())
    if (normals.col (vertex).dot (camera.towardsCamera (head.col (vertex))) > 0.3)
      pixels[id] = camera.project (head.col (vertex)) + Eigen::Vector2d (noise (rng), noise (rng));
  PhotoView view (kWidth, kHeight, pixels, "photo " + std::to_string (seed));
  if (given)
    view.setCamera (camera);
  return view;
}

std::vector<PhotoView>
photographs (const Eigen::Matrix3Xd& head, bool given, std::uint64_t seed)
{
  std::vector<PhotoView> views;
  for (const double degrees : {-30.0, 0.0, 30.0})
    views.push_back (photograph (head, cameraAt (degrees), given, seed++));
  return views;
}

morphreg::PhotoFitting
fitting ()
{
  morphreg::PhotoFitting fitting (morphreg::test::photoTestModel ().model);
  fitting.setOutlineLandmarks (morphreg::OutlineLandmarkMode::vertex); // the photos mark fixed vertices for them
  return fitting;
}

double
rms (const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b)
{
  return std::sqrt ((a - b).colwise ().squaredNorm ().mean ());
}

/** The mean head carried by \a fit's similarity (in the cameras' frame). */
Eigen::Matrix3Xd
meanHead (const PhotoFit& fit)
{
  const morphreg::MorphableModel& model = *morphreg::test::photoTestModel ().model;
  const Eigen::Map<const Eigen::Matrix3Xd> mean (model.mean ().data (), 3, model.numVertices ());
  return (fit.scale * fit.rotation * mean).colwise () + fit.translation;
}

/** \a vertices moved by the similarity that best aligns them to \a truth (Umeyama). */
Eigen::Matrix3Xd
aligned (const Eigen::Matrix3Xd& vertices, const Eigen::Matrix3Xd& truth)
{
  const Eigen::Matrix4d align = Eigen::umeyama (vertices, truth, true);
  return (align.topLeftCorner<3, 3> () * vertices).colwise () + align.topRightCorner<3, 1> ();
}

// Measured on 3 unseen heads: vertex RMS against the truth 2.40 mm with the cameras given (the mean head carried by
// the fit's similarity 5.59 mm); with the cameras estimated, the fit lives in the model's frame and is scored after
// the similarity that best aligns it to the truth, as is its no-op, the mean head: 3.50 mm against 4.39 mm (the
// focal lengths found range from 960 to 13900 px against the true 3000: a head 1 m away fixes them loosely).
TEST (MultiViewFitTest, PerspectivePhotosFromThreeDirectionsRecoverUnseenHeads)
{
  double given_rms = 0.0, estimated_rms = 0.0, mean_rms = 0.0, aligned_mean_rms = 0.0;
  const int heads = 3;
  const morphreg::MorphableModel& model = *morphreg::test::photoTestModel ().model;
  const Eigen::Map<const Eigen::Matrix3Xd> mean (model.mean ().data (), 3, model.numVertices ());
  for (int h = 0; h < heads; ++h) {
    const Eigen::Matrix3Xd truth =
        morphreg::test::headGenerator (morphreg::test::kPhotoResolution).sample (700000 + h).mesh.vertices;
    const PhotoFit given = fitting ().fit (photographs (truth, true, 10 * h), "joint");
    ASSERT_EQ (given.views.size (), 3u);
    EXPECT_FALSE (given.views[0].camera_estimated);
    const PhotoFit estimated = fitting ().fit (photographs (truth, false, 10 * h), "joint");
    EXPECT_TRUE (estimated.views[1].camera_estimated);
    const double head_given = rms (given.image_mesh.vertices, truth);
    const double head_estimated = rms (aligned (estimated.model_mesh.vertices, truth), truth);
    given_rms += head_given / heads;
    mean_rms += rms (meanHead (given), truth) / heads;
    estimated_rms += head_estimated / heads;
    aligned_mean_rms += rms (aligned (mean, truth), truth) / heads;
    std::cout << "head " << h << ": cameras given " << head_given << " mm, estimated (aligned) " << head_estimated
              << " mm; focal lengths estimated " << estimated.views[0].camera.intrinsics () (0, 0) << ", "
              << estimated.views[1].camera.intrinsics () (0, 0) << ", "
              << estimated.views[2].camera.intrinsics () (0, 0) << " px (true 3000)\n";
  }
  std::cout << "vertex RMS: cameras given " << given_rms << " mm (the mean head " << mean_rms << " mm), estimated "
            << estimated_rms << " mm (the aligned mean head " << aligned_mean_rms << " mm)\n";
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, given_rms, 2.9);
  EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, mean_rms, 2.9);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, estimated_rms, 4.2);
  EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, aligned_mean_rms, 4.2);
}

TEST (MultiViewFitTest, BadViewsAreNamed)
{
  const Eigen::Matrix3Xd truth =
      morphreg::test::headGenerator (morphreg::test::kPhotoResolution).sample (7).mesh.vertices;
  const PhotoView front = photograph (truth, cameraAt (0.0), true, 1);
  expectErrorContaining<InvalidInputError> ([] { fitting ().fit (std::vector<PhotoView> (), "joint"); },
                                            "no photo to fit");
  // A landmark the model does not have (an iBUG-68 id: the synthetic model has the ids of docs/landmarks.md only).
  morphreg::LandmarkPixels extra = front.landmarks ();
  extra["ibug68_30"] = Eigen::Vector2d (600.0, 800.0);
  expectErrorContaining<InvalidInputError> (
      [&] { fitting ().fit ({PhotoView (kWidth, kHeight, extra, "extra.pts")}, "joint"); },
      "extra.pts: landmark 'ibug68_30' is not a model landmark");
  // An unknown id, a non-finite pixel, a bad image size: named by the view.
  morphreg::LandmarkPixels unknown = front.landmarks ();
  unknown["left_ear_tip"] = Eigen::Vector2d (1.0, 1.0);
  expectErrorContaining<InvalidInputError> ([&] { PhotoView (kWidth, kHeight, unknown, "unknown.json"); },
                                            "unknown.json");
  morphreg::LandmarkPixels nan = front.landmarks ();
  nan.begin ()->second.x () = NAN;
  expectErrorContaining<InvalidInputError> ([&] { PhotoView (kWidth, kHeight, nan, "nan.json"); }, "nan.json");
  expectErrorContaining<InvalidInputError> ([&] { PhotoView (0, kHeight, front.landmarks (), "empty.jpg"); },
                                            "empty.jpg");
  // A camera given, but too few landmarks in its photo to place the head in its frame.
  morphreg::LandmarkPixels five;
  for (const auto& entry : front.landmarks ())
    if (five.size () < 5 && !morphreg::isOutlineLandmarkId (entry.first))
      five.insert (entry);
  PhotoView sparse (kWidth, kHeight, five, "sparse.jpg");
  sparse.setCamera (cameraAt (0.0));
  expectErrorContaining<InvalidInputError> ([&] { fitting ().fit ({sparse}, "joint"); },
                                            "sparse.jpg has a camera, but no photo with a camera");
  // No camera and too few landmarks to estimate one.
  expectErrorContaining<InvalidInputError> (
      [&] { fitting ().fit ({PhotoView (kWidth, kHeight, five, "five.jpg")}, "joint"); },
      "five.jpg: a camera is estimated from at least 6 landmarks");
  // A traced outline of too few points, and a hairline far from the outline.
  PhotoView outlined = front;
  expectErrorContaining<InvalidInputError> (
      [&] { outlined.setOutline (std::vector<Eigen::Vector2d> (3, Eigen::Vector2d (1.0, 2.0))); }, "photo 1");
  std::vector<Eigen::Vector2d> line;
  for (int k = 0; k < 20; ++k)
    line.emplace_back (500.0 + k, 400.0 + 20.0 * k);
  expectErrorContaining<InvalidInputError> ([&] { outlined.setOutline (line, Eigen::Vector2d (1100.0, 100.0)); },
                                            "hairline");
}
} // namespace

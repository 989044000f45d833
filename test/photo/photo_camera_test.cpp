// SPDX-License-Identifier: BSD-3-Clause
// The cameras of multi-view photo fits: pinhole and orthographic projection and their derivatives, K R t from a
// projection matrix, camera files (K, R, t or P; a list by image, as menpo3d_james's james_cameras.json), the EXIF
// focal length, the camera estimated from landmarks, and the bad cameras and files each names.
#include "photo_test_model.h"
#include "support/expect_error.h"
#include "support/temp_directory.h"

#include <morphreg/common/error.h>
#include <morphreg/io/json_file.h>
#include <morphreg/photo/camera_estimation.h>
#include <morphreg/photo/jpeg_exif.h>
#include <morphreg/photo/photo_camera.h>
#include <morphreg/photo/photo_camera_io.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <random>

namespace
{
using morphreg::CameraEstimate;
using morphreg::FocalRange;
using morphreg::FormatError;
using morphreg::InvalidInputError;
using morphreg::PhotoCamera;
using morphreg::test::expectErrorContaining;

/** A camera 1 m in front of the model's origin, turned \a degrees about Y (to the subject's side), f 3000 px on a
 *  1200 x 1600 px photo with a slightly off-centre principal point and a little skew. */
PhotoCamera
sideCamera (double degrees)
{
  Eigen::Matrix3d K;
  K << 3000.0, 1.5, 610.0, 0.0, 3010.0, 790.0, 0.0, 0.0, 1.0;
  // Camera axes: x right, y down, z forward; it looks along -Z of the head's frame (+Y up) turned about Y.
  const Eigen::Matrix3d look = Eigen::Vector3d (1.0, -1.0, -1.0).asDiagonal ();
  const Eigen::Matrix3d R = look * Eigen::AngleAxisd (degrees * M_PI / 180.0, Eigen::Vector3d::UnitY ()).matrix ();
  return PhotoCamera::perspective (K, R, Eigen::Vector3d (5.0, -20.0, 1000.0), "side camera");
}

TEST (PhotoCameraTest, ProjectionAndItsDerivativeAgreeWithFiniteDifferences)
{
  const PhotoCamera perspective = sideCamera (25.0);
  const PhotoCamera orthographic =
      PhotoCamera::orthographic (perspective.rotation (), 4.0, Eigen::Vector2d (600.0, 800.0));
  const Eigen::Vector3d point (30.0, 40.0, 80.0);
  for (const PhotoCamera* camera : {&perspective, &orthographic}) {
    Eigen::Matrix<double, 2, 3> numeric;
    for (int axis = 0; axis < 3; ++axis) {
      const Eigen::Vector3d step = 1e-4 * Eigen::Vector3d::Unit (axis);
      numeric.col (axis) = (camera->project (point + step) - camera->project (point - step)) / 2e-4;
    }
    EXPECT_LT ((camera->jacobian (point) - numeric).norm (), 1e-6 * numeric.norm ());
    EXPECT_NEAR (camera->towardsCamera (point).norm (), 1.0, 1e-12);
  }
  // The pinhole: (K c) / c_z, pixels per mm f / depth; the orthographic one the principal point at the origin.
  const Eigen::Vector3d c = perspective.toCamera (point), h = perspective.intrinsics () * c;
  EXPECT_LT ((perspective.project (point) - h.head<2> () / h.z ()).norm (), 1e-9);
  EXPECT_NEAR (perspective.pixelsPerUnit (point), std::sqrt (3000.0 * 3010.0) / c.z (), 1e-9);
  EXPECT_LT ((orthographic.project (Eigen::Vector3d::Zero ()) - Eigen::Vector2d (600.0, 800.0)).norm (), 1e-12);
  EXPECT_DOUBLE_EQ (orthographic.pixelsPerUnit (point), 4.0);
  // The camera centre projects nowhere: every other point lies along the ray towards it.
  EXPECT_LT ((perspective.towardsCamera (point) - (perspective.centre () - point).normalized ()).norm (), 1e-12);
}

TEST (PhotoCameraTest, ProjectionMatrixGivesBackKRt)
{
  const PhotoCamera camera = sideCamera (-25.0);
  Eigen::Matrix<double, 3, 4> P;
  P << camera.rotation (), camera.translation ();
  P = camera.intrinsics () * P;
  for (const double scale : {1.0, -3.7, 1e-3}) { // P is defined up to scale, sign included
    const PhotoCamera back = PhotoCamera::fromProjection (scale * P, "P");
    EXPECT_LT ((back.intrinsics () - camera.intrinsics ()).norm (), 1e-8 * camera.intrinsics ().norm ()) << scale;
    EXPECT_LT ((back.rotation () - camera.rotation ()).norm (), 1e-10) << scale;
    EXPECT_LT ((back.translation () - camera.translation ()).norm (), 1e-8) << scale;
  }
}

TEST (PhotoCameraTest, DegenerateCamerasAreNamed)
{
  const PhotoCamera camera = sideCamera (0.0);
  const Eigen::Matrix3d K = camera.intrinsics (), R = camera.rotation ();
  const Eigen::Vector3d t = camera.translation ();
  Eigen::Matrix3d zero_focal = K, lower = K, reflected = R, sheared = R;
  zero_focal (1, 1) = 0.0;
  lower (2, 0) = 0.1;
  reflected.row (2) *= -1.0;
  sheared (0, 1) += 0.01;
  expectErrorContaining<morphreg::Error> ([&] { PhotoCamera::perspective (zero_focal, R, t, "cam.json"); },
                                          "cam.json: K's focal lengths");
  expectErrorContaining<morphreg::Error> ([&] { PhotoCamera::perspective (lower, R, t, "cam.json"); },
                                          "cam.json: K must be finite, upper");
  expectErrorContaining<morphreg::Error> ([&] { PhotoCamera::perspective (K, reflected, t, "cam.json"); },
                                          "cam.json: R is not a rotation");
  expectErrorContaining<morphreg::Error> ([&] { PhotoCamera::perspective (K, sheared, t, "cam.json"); },
                                          "cam.json: R is not a rotation");
  expectErrorContaining<morphreg::Error> (
      [&] { PhotoCamera::perspective (K, R, Eigen::Vector3d (0, NAN, 0), "cam.json"); }, "t is not finite");
  Eigen::Matrix<double, 3, 4> P = Eigen::Matrix<double, 3, 4>::Zero ();
  P.block<2, 3> (0, 0) = K.topRows<2> (); // rank 2: every point on one line of sight
  expectErrorContaining<morphreg::Error> ([&] { PhotoCamera::fromProjection (P, "p.json"); },
                                          "p.json: P's left 3 x 3 block is singular");
  P (2, 3) = INFINITY;
  expectErrorContaining<morphreg::Error> ([&] { PhotoCamera::fromProjection (P, "p.json"); },
                                          "p.json: P is not finite");
  expectErrorContaining<morphreg::Error> ([&] { PhotoCamera::orthographic (R, 0.0, Eigen::Vector2d::Zero ()); },
                                          "scale must be finite and > 0");
}

/** A JSON matrix of \a matrix's rows. */
nlohmann::json
rows (const Eigen::MatrixXd& matrix)
{
  nlohmann::json json = nlohmann::json::array ();
  for (Eigen::Index r = 0; r < matrix.rows (); ++r) {
    nlohmann::json row = nlohmann::json::array ();
    for (Eigen::Index c = 0; c < matrix.cols (); ++c)
      row.push_back (matrix (r, c));
    json.push_back (row);
  }
  return json;
}

TEST (PhotoCameraTest, CameraFilesTakeKRtOrPAndPickTheCameraByImage)
{
  const morphreg::test::TempDirectory directory;
  const PhotoCamera left = sideCamera (25.0), right = sideCamera (-25.0);
  Eigen::Matrix<double, 3, 4> P;
  P << right.rotation (), right.translation ();
  P = 2.0 * right.intrinsics () * P;
  const nlohmann::json krt = {{"image", "a.jpg"},
                              {"width", 1200},
                              {"height", 1600},
                              {"K", rows (left.intrinsics ())},
                              {"R", rows (left.rotation ())},
                              {"t", {5.0, -20.0, 1000.0}}};
  const std::string file = directory.file ("cameras.json");
  morphreg::writeJsonFile (file, {{"cameras", {{"left", krt}, {"right", {{"image", "b.jpg"}, {"P", rows (P)}}}}}});
  const PhotoCamera a = morphreg::loadPhotoCamera (file, "/photos/a.jpg", 1200, 1600);
  const PhotoCamera b = morphreg::loadPhotoCamera (file, "b.jpg", 1200, 1600);
  const Eigen::Vector3d point (10.0, 20.0, 60.0);
  EXPECT_LT ((a.project (point) - left.project (point)).norm (), 1e-9);
  EXPECT_LT ((b.project (point) - right.project (point)).norm (), 1e-8);
  // A single camera is the document itself; it round-trips through photoCameraJson.
  const std::string single = directory.file ("single.json");
  morphreg::writeJsonFile (single, morphreg::photoCameraJson (left));
  EXPECT_LT ((morphreg::loadPhotoCamera (single, "x.png", 1200, 1600).project (point) - left.project (point)).norm (),
             1e-9);

  // Bad files: each error names the file, the camera and what is wrong.
  const auto expectFormat = [&] (const nlohmann::json& document, const std::string& image, const std::string& text) {
    morphreg::writeJsonFile (file, document);
    expectErrorContaining<morphreg::Error> ([&] { morphreg::loadPhotoCamera (file, image, 1200, 1600); }, text);
  };
  nlohmann::json no_t = krt;
  no_t.erase ("t");
  expectFormat (no_t, "a.jpg", "cameras.json (camera of a.jpg): missing \"t\"");
  nlohmann::json short_r = krt;
  short_r["R"] = rows (left.rotation ().topRows<2> ());
  expectFormat (short_r, "a.jpg", "\"R\" must be 3 x 3 numbers");
  nlohmann::json text_k = krt;
  text_k["K"][0][0] = "f";
  expectFormat (text_k, "a.jpg", "\"K\" must be 3 x 3 numbers");
  nlohmann::json wide = krt;
  wide["width"] = 1000;
  expectFormat (wide, "a.jpg", "the camera's width 1000 is not the photo's 1200 px");
  expectFormat ({{"cameras", {{"left", krt}, {"right", krt}}}}, "c.jpg", "none of its 2 cameras is for the image");
  expectFormat ({{"cameras", nlohmann::json::array ()}}, "a.jpg", "\"cameras\" must be a non-empty object");
  expectFormat (nlohmann::json::array (), "a.jpg", "expected a JSON object with K, R and t, P");
  expectFormat ({{"P", rows (Eigen::Matrix<double, 3, 4>::Zero ())}}, "a.jpg", "P's left 3 x 3 block is singular");
  nlohmann::json reflected = krt;
  reflected["R"] = rows (-left.rotation ());
  expectFormat (reflected, "a.jpg", "R is not a rotation");
  expectErrorContaining<morphreg::Error> (
      [&] { morphreg::loadPhotoCamera (directory.file ("absent.json"), "a.jpg", 1200, 1600); }, "absent.json");
}

TEST (PhotoCameraTest, JamesCamerasProjectTheScansLandmarksOntoThePhotos)
{
  const std::string dir = std::string (MORPHREG_SHARED_DATA_DIR) + "/real_head_scans/menpo3d_james/";
  if (!std::filesystem::exists (dir + "james_cameras.json"))
    GTEST_SKIP () << "menpo3d_james is not in " << MORPHREG_SHARED_DATA_DIR;
  const nlohmann::json landmarks = morphreg::readJsonFile (dir + "james_landmarks.json").at ("landmarks");
  for (const char* side : {"left", "right"}) {
    const std::string image = std::string ("james_photo_") + side + ".jpg";
    const PhotoCamera camera = morphreg::loadPhotoCamera (dir + "james_cameras.json", image, 1200, 1600);
    // Its K, R, t agree with its P: the same camera twice, read both ways.
    const nlohmann::json entry = morphreg::readJsonFile (dir + "james_cameras.json").at ("cameras").at (side);
    Eigen::Matrix<double, 3, 4> P;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c)
        P (r, c) = entry.at ("P")[r][c].get<double> ();
    const PhotoCamera from_p = PhotoCamera::fromProjection (P, "P");
    std::ifstream csv (dir + "james_photo_" + side + "_landmarks68.csv");
    std::string line;
    std::getline (csv, line); // the comment
    double worst = 0.0, worst_p = 0.0;
    for (const nlohmann::json& landmark : landmarks) {
      std::getline (csv, line);
      const Eigen::Vector2d pixel (std::stod (line), std::stod (line.substr (line.find (',') + 1)));
      const auto& xyz = landmark.at ("position");
      const Eigen::Vector3d point (xyz[0].get<double> (), xyz[1].get<double> (), xyz[2].get<double> ());
      worst = std::max (worst, (camera.project (point) - pixel).norm ());
      worst_p = std::max (worst_p, (from_p.project (point) - pixel).norm ());
    }
    std::cout << side << ": largest landmark reprojection " << worst << " px (K R t), " << worst_p << " px (P)\n";
    EXPECT_LT (worst, 0.05) << side; // the CSV holds these projections to 0.01 px
    EXPECT_LT (worst_p, 0.05) << side;
    Eigen::Matrix3d K;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 3; ++c)
        K (r, c) = entry.at ("K")[r][c].get<double> ();
    EXPECT_LT ((from_p.intrinsics () - K).norm (), 1e-6 * K.norm ()) << side;
    EXPECT_GT (K (0, 0), 6000.0); // about 6300 px (the README), the focal length the estimate has to find
    EXPECT_GT (camera.toCamera (camera.centre () + camera.rotation ().row (2).transpose ()).z (), 0.0);
  }
}

/** The photo test model's mean-head landmarks of the thesis's frontal set (mm). */
Eigen::Matrix3Xd
meanLandmarks ()
{
  const morphreg::MorphableModel& model = *morphreg::test::photoTestModel ().model;
  const morphreg::LandmarkVertices landmarks = morphreg::test::frontalLandmarks ();
  Eigen::Matrix3Xd points (3, static_cast<Eigen::Index> (landmarks.size ()));
  Eigen::Index k = 0;
  for (const auto& [id, vertex] : landmarks)
    points.col (k++) = model.meanVertex (vertex);
  return points;
}

Eigen::Matrix2Xd
projected (const PhotoCamera& camera, const Eigen::Matrix3Xd& points, double noise, std::uint64_t seed)
{
  std::mt19937_64 rng (seed);
  std::normal_distribution<double> gauss (0.0, noise);
  Eigen::Matrix2Xd pixels (2, points.cols ());
  for (Eigen::Index k = 0; k < points.cols (); ++k)
    pixels.col (k) = camera.project (points.col (k)) + Eigen::Vector2d (gauss (rng), gauss (rng));
  return pixels;
}

double
angleDegrees (const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
  return Eigen::AngleAxisd (a * b.transpose ()).angle () * 180.0 / M_PI;
}

TEST (CameraEstimationTest, FocalLengthAndPoseFromLandmarks)
{
  const Eigen::Matrix3Xd points = meanLandmarks ();
  ASSERT_GE (points.cols (), 20);
  for (const double degrees : {0.0, 25.0, -40.0}) {
    const PhotoCamera truth = sideCamera (degrees);
    const Eigen::Matrix2Xd pixels = projected (truth, points, 1.0, 7);
    const FocalRange range = FocalRange::forImage (1200, 1600, 0.0);
    const CameraEstimate estimate = morphreg::estimateCamera (points, pixels, 1200, 1600, range, "photo.jpg");
    const double focal = estimate.camera.intrinsics () (0, 0);
    const double depth = estimate.camera.toCamera (points.rowwise ().mean ()).z ();
    const double magnification = focal / depth / (3000.0 / truth.toCamera (points.rowwise ().mean ()).z ());
    const FocalRange exact{3000.0, 3000.0, "EXIF"};
    const CameraEstimate known = morphreg::estimateCamera (points, pixels, 1200, 1600, exact, "photo.jpg");
    std::cout << degrees << " deg: focal " << focal << " px (true 3000), depth " << depth << " mm, magnification "
              << magnification << ", rotation error " << angleDegrees (estimate.camera.rotation (), truth.rotation ())
              << " deg, RMS " << estimate.rms_pixels << " px; with the focal length known: rotation error "
              << angleDegrees (known.camera.rotation (), truth.rotation ()) << " deg, centre error "
              << (known.camera.centre () - truth.centre ()).norm () << " mm\n";
    // A head seen from 1 m fixes f / depth well and f itself loosely: measured within 3.1 %, 0.44 degrees, 1.33 px.
    EXPECT_NEAR (focal / 3000.0, 1.0, 0.04) << degrees;
    EXPECT_NEAR (magnification, 1.0, 0.01) << degrees;
    EXPECT_LT (angleDegrees (estimate.camera.rotation (), truth.rotation ()), 0.6) << degrees;
    EXPECT_LT (estimate.rms_pixels, 1.5) << degrees; // the 1 px noise, less what the 6 + 1 unknowns absorb
    // With the focal length known (EXIF), the pose is found closer.
    EXPECT_LT (angleDegrees (known.camera.rotation (), truth.rotation ()), 0.6) << degrees;
    EXPECT_LT ((known.camera.centre () - truth.centre ()).norm (), 15.0) << degrees;
  }
}

TEST (CameraEstimationTest, TooFewFlatOrMismatchedLandmarksAreNamed)
{
  const Eigen::Matrix3Xd points = meanLandmarks ();
  const PhotoCamera truth = sideCamera (10.0);
  const Eigen::Matrix2Xd pixels = projected (truth, points, 0.0, 1);
  const FocalRange range = FocalRange::forImage (1200, 1600, 0.0);
  expectErrorContaining<morphreg::Error> (
      [&] { morphreg::estimateCamera (points.leftCols (5), pixels.leftCols (5), 1200, 1600, range, "p.jpg"); },
      "p.jpg: a camera is estimated from at least 6 landmarks");
  expectErrorContaining<morphreg::Error> (
      [&] { morphreg::estimateCamera (points, pixels.leftCols (10), 1200, 1600, range, "p.jpg"); },
      "at least 6 landmarks");
  Eigen::Matrix3Xd flat = points;
  flat.row (2).setConstant (50.0);
  expectErrorContaining<morphreg::Error> ([&] { morphreg::estimateCamera (flat, pixels, 1200, 1600, range, "p.jpg"); },
                                          "lie on one plane");
  Eigen::Matrix2Xd bad = pixels;
  bad (0, 3) = NAN;
  expectErrorContaining<morphreg::Error> ([&] { morphreg::estimateCamera (points, bad, 1200, 1600, range, "p.jpg"); },
                                          "not finite");
  expectErrorContaining<morphreg::Error> ([&] { morphreg::estimateCamera (points, pixels, 0, 1600, range, "p.jpg"); },
                                          "image size");
  expectErrorContaining<morphreg::Error> (
      [&] {
        morphreg::estimateCamera (points, pixels, 1200, 1600, FocalRange{0.0, 10.0, ""}, "p.jpg");
      },
      "focal range");
}

TEST (CameraEstimationTest, ExifFocalLengthGivesTheRange)
{
  // EXIF's FocalLengthIn35mmFilm (0xA405) in the Exif IFD, in both byte orders; a 50 mm lens on a 3000 x 4000 px
  // photo is 50 / 43.27 * 5000 = 5778 px.
  for (const bool little : {true, false}) {
    const auto u16 = [little] (unsigned v) {
      return little ? std::string{char (v & 0xFF), char (v >> 8)} : std::string{char (v >> 8), char (v & 0xFF)};
    };
    const auto u32 = [&] (unsigned v) {
      return little ? u16 (v & 0xFFFF) + u16 (v >> 16) : u16 (v >> 16) + u16 (v & 0xFFFF);
    };
    std::string tiff = std::string (little ? "II" : "MM") + u16 (42) + u32 (8);
    tiff += u16 (1) + u16 (0x8769) + u16 (4) + u32 (1) + u32 (26) + u32 (0); // IFD0: the Exif IFD at 26
    tiff += u16 (1) + u16 (0xA405) + u16 (3) + u32 (1) + u16 (50) + u16 (0) + u32 (0);
    const std::string segment = std::string ("Exif\0\0", 6) + tiff;
    const std::string jpeg = std::string ("\xFF\xD8\xFF\xE1", 4) + char ((segment.size () + 2) >> 8) +
                             char ((segment.size () + 2) & 0xFF) + segment + std::string ("\xFF\xDA", 2);
    const auto focal = morphreg::jpegFocalLength35mmFromBytes (jpeg);
    ASSERT_TRUE (focal.has_value ()) << little;
    EXPECT_DOUBLE_EQ (*focal, 50.0);
    const FocalRange range = FocalRange::forImage (3000, 4000, *focal);
    EXPECT_NEAR (range.min, 50.0 / 43.2666 * 5000.0, 1e-6);
    EXPECT_EQ (range.min, range.max);
    // Truncated or foreign bytes have no focal length: no crash, no value.
    for (size_t cut = 0; cut + 2 < jpeg.size (); cut += 7)
      EXPECT_FALSE (morphreg::jpegFocalLength35mmFromBytes (jpeg.substr (0, cut)).has_value ()) << cut;
  }
  EXPECT_FALSE (morphreg::jpegFocalLength35mmFromBytes ("not a jpeg").has_value ());
  const FocalRange searched = FocalRange::forImage (1200, 1600, 0.0);
  EXPECT_NEAR (searched.min, 20.0 / 43.2666 * 2000.0, 1e-6);
  EXPECT_NEAR (searched.max, 300.0 / 43.2666 * 2000.0, 1e-6);
}
} // namespace

// SPDX-License-Identifier: BSD-3-Clause
// The annotated photos: the normalised frame, the views' validation, their JSON files, the silhouette polyline and
// the photo simulator's ground truth.
#include "photo_test_model.h"
#include "support/temp_directory.h"

#include <morphreg/common/error.h>
#include <morphreg/io/json_file.h>
#include <morphreg/photo/photo_view_io.h>
#include <morphreg/photo/polyline_2d.h>
#include <morphreg/synthetic/photo_simulator.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

namespace
{
using morphreg::FrontalView;
using morphreg::InvalidInputError;
using morphreg::LandmarkPixels;
using morphreg::ProfileView;

/** Runs \a f and expects an exception of type E whose message contains every one of \a texts. */
template <typename E, typename F>
void
expectError (F f, const std::vector<std::string>& texts)
{
  try {
    f ();
    ADD_FAILURE () << "no exception; expected one mentioning '" << texts.front () << "'";
  }
  catch (const E& e) {
    for (const std::string& text : texts)
      EXPECT_NE (std::string (e.what ()).find (text), std::string::npos) << e.what ();
  }
}

const double kNaN = std::nan ("");

TEST (PhotoViewTest, NormalisationDividesByTheLongerSideCentresOnTheNoseAndPointsYUp)
{
  const morphreg::PhotoNormalisation frame (800, 1000, Eigen::Vector2d (400.0, 500.0), "test");
  EXPECT_DOUBLE_EQ (frame.longerSide (), 1000.0);
  EXPECT_TRUE (frame.normalise (Eigen::Vector2d (400.0, 500.0)).isZero ());
  // 100 px right and 200 px up of the nose tip.
  EXPECT_TRUE (frame.normalise (Eigen::Vector2d (500.0, 300.0)).isApprox (Eigen::Vector2d (0.1, 0.2)));
  EXPECT_TRUE (frame.toPixel (Eigen::Vector2d (0.1, 0.2)).isApprox (Eigen::Vector2d (500.0, 300.0)));
  const morphreg::PhotoNormalisation wide (1200, 900, Eigen::Vector2d::Zero (), "test");
  EXPECT_TRUE (wide.normalise (Eigen::Vector2d (600.0, 300.0)).isApprox (Eigen::Vector2d (0.5, -0.25)));
}

/** 12 silhouette points of a profile facing right: (400, 300), (405, 335), ... (455, 685), all left of x = 500. */
std::vector<Eigen::Vector2d>
rightFacingLine ()
{
  std::vector<Eigen::Vector2d> line;
  for (int k = 0; k < 12; ++k)
    line.emplace_back (400.0 + 5.0 * k, 300.0 + 35.0 * k);
  return line;
}

TEST (PhotoViewTest, ProfileViewRejectsBadAnnotations)
{
  const Eigen::Vector2d nose (500.0, 500.0);
  const std::vector<Eigen::Vector2d> line = rightFacingLine ();
  expectError<InvalidInputError> ([&] { ProfileView (0, 1200, line, nose, "side.json"); },
                                  {"side.json", "image size 0 x 1200"});
  expectError<InvalidInputError> ([&] { ProfileView (1000, -5, line, nose); }, {"image size", "positive"});
  expectError<InvalidInputError> ([&] { ProfileView (1000, 1200, {}, nose, "side.json"); },
                                  {"side.json", "silhouette polyline has 0 points"});
  expectError<InvalidInputError> ([&] { ProfileView (1000, 1200, {nose}, nose); }, {"has 1 points"});
  expectError<InvalidInputError> (
      [&] { ProfileView (1000, 1200, std::vector<Eigen::Vector2d> (line.begin (), line.begin () + 9), nose); },
      {"has 9 points", "at least 10"});
  expectError<InvalidInputError> ([&] { ProfileView (1000, 1200, std::vector<Eigen::Vector2d> (12, nose), nose); },
                                  {"coincide"});
  std::vector<Eigen::Vector2d> mirrored = line;
  for (Eigen::Vector2d& point : mirrored)
    point.x () = 1000.0 - point.x ();
  expectError<InvalidInputError> ([&] { ProfileView (1000, 1200, mirrored, nose, "left.json"); },
                                  {"left.json", "the face looks left", "mirror the photo"});
  std::vector<Eigen::Vector2d> with_nan = line;
  with_nan[1].y () = kNaN;
  expectError<InvalidInputError> ([&] { ProfileView (1000, 1200, with_nan, nose); },
                                  {"silhouette point 1", "not finite"});
  expectError<InvalidInputError> ([&] { ProfileView (1000, 1200, line, Eigen::Vector2d (kNaN, 3.0)); },
                                  {"nose tip", "not finite"});
  const ProfileView view (1000, 1200, line, nose);
  // u towards the face (image right), v up, in units of the longer side.
  EXPECT_TRUE (view.normalisedSilhouette ().col (0).isApprox (Eigen::Vector2d (-100.0, 200.0) / 1200.0));
  EXPECT_TRUE (view.normalisedSilhouette ().col (1).isApprox (Eigen::Vector2d (-95.0, 165.0) / 1200.0));
}

TEST (PhotoViewTest, FrontalViewRejectsBadAnnotations)
{
  const LandmarkPixels marked = {
      {"nose_tip", {500.0, 600.0}}, {"left_eye_outer", {620.0, 480.0}}, {"right_eye_outer", {380.0, 480.0}}};
  expectError<InvalidInputError> ([&] { FrontalView (1000, 0, marked, "front.json"); }, {"front.json", "image size"});
  LandmarkPixels no_nose = marked;
  no_nose.erase ("nose_tip");
  expectError<InvalidInputError> ([&] { FrontalView (1000, 1200, no_nose, "front.json"); },
                                  {"front.json", "no nose tip (nose_tip, or iBUG-68's point 30"});
  LandmarkPixels with_nan = marked;
  with_nan["left_eye_outer"].x () = INFINITY;
  expectError<InvalidInputError> ([&] { FrontalView (1000, 1200, with_nan); }, {"'left_eye_outer'", "not finite"});
  LandmarkPixels unknown = marked;
  unknown["third_eye"] = {500.0, 400.0};
  expectError<InvalidInputError> ([&] { FrontalView (1000, 1200, unknown, "front.json"); },
                                  {"front.json", "unknown landmark id 'third_eye'"});
  const FrontalView view (1000, 1200, marked);
  // The subject's left eye is on the image's right: +X.
  EXPECT_TRUE (view.normalisedLandmarks ().at ("left_eye_outer").isApprox (Eigen::Vector2d (0.1, 0.1)));
  // iBUG-68 annotations (landmark tools' .pts) name the nose tip as their point 30: it centres the frame as well.
  const FrontalView ibug (1000, 1200, {{"ibug68_30", {500.0, 600.0}}, {"ibug68_45", {620.0, 480.0}}});
  EXPECT_TRUE (ibug.normalisedLandmarks ().at ("ibug68_30").isZero ());
  EXPECT_TRUE (ibug.normalisedLandmarks ().at ("ibug68_45").isApprox (Eigen::Vector2d (0.1, 0.1)));
}

TEST (PhotoViewTest, JsonFilesRoundTrip)
{
  const morphreg::test::TempDirectory directory;
  std::vector<Eigen::Vector2d> line = rightFacingLine ();
  line.front () = {400.25, 300.5};
  const ProfileView profile (1000, 1200, line, {510.5, 498.0});
  morphreg::saveProfileView (directory.file ("side.json"), profile);
  const ProfileView profile_read = morphreg::loadProfileView (directory.file ("side.json"));
  EXPECT_EQ (profile_read.normalisation ().width (), 1000);
  EXPECT_EQ (profile_read.normalisation ().height (), 1200);
  EXPECT_EQ (profile_read.normalisation ().noseTip (), profile.normalisation ().noseTip ());
  EXPECT_EQ (profile_read.silhouette (), profile.silhouette ());

  const FrontalView frontal (640, 480, {{"nose_tip", {320.0, 250.0}}, {"chin", {321.5, 400.25}}});
  morphreg::saveFrontalView (directory.file ("front.json"), frontal);
  const FrontalView frontal_read = morphreg::loadFrontalView (directory.file ("front.json"));
  EXPECT_EQ (frontal_read.normalisation ().width (), 640);
  EXPECT_EQ (frontal_read.normalisation ().height (), 480);
  EXPECT_EQ (frontal_read.landmarks (), frontal.landmarks ());
}

TEST (PhotoViewTest, ReadersNameTheFileAndTheProblem)
{
  const morphreg::test::TempDirectory directory;
  const auto write = [&] (const std::string& name, const std::string& text) {
    std::ofstream (directory.file (name)) << text;
    return directory.file (name);
  };
  expectError<morphreg::IoError> ([&] { morphreg::loadProfileView (directory.file ("missing.json")); },
                                  {"missing.json"});
  const std::string side = R"({"view": "profile", "image": {"width": 100, "height": 100}, "nose_tip": [50, 50], )";
  expectError<morphreg::FormatError> ([&] { morphreg::loadProfileView (write ("a.json", "{\"view\": ")); },
                                      {"a.json", "malformed JSON"});
  expectError<morphreg::FormatError> ([&] { morphreg::loadProfileView (write ("b.json", R"({"view": "frontal"})")); },
                                      {"b.json", "\"view\" is \"frontal\", expected \"profile\""});
  expectError<morphreg::FormatError> (
      [&] { morphreg::loadProfileView (write ("c.json", R"({"view": "profile", "nose_tip": [1, 2]})")); },
      {"c.json", "missing \"image\""});
  expectError<morphreg::FormatError> (
      [&] {
        morphreg::loadProfileView (write ("n.json", R"({"view": "profile", "image": {"width": 100, "height": 100},
                                                        "silhouette": [[1, 2], [3, 4]]})"));
      },
      {"n.json", "missing \"nose_tip\""});
  expectError<morphreg::FormatError> (
      [&] {
        morphreg::loadProfileView (
            write ("d.json", R"({"view": "profile", "image": {"width": 10.5, "height": 100}, "nose_tip": [1, 2]})"));
      },
      {"d.json", "image.width (10.5) is not an integer"});
  expectError<morphreg::FormatError> (
      [&] {
        morphreg::loadProfileView (write ("w.json", R"({"view": "profile", "image": {"width": 4294967396,
                                                        "height": 100}, "nose_tip": [1, 2]})"));
      },
      {"w.json", "image.width (4294967396) is not an integer pixel count"});
  expectError<morphreg::FormatError> (
      [&] { morphreg::loadProfileView (write ("e.json", side + R"("silhouette": [[1, 2], [3, "x"]]})")); },
      {"e.json", "silhouette[1]", "expected [x, y]"});
  expectError<InvalidInputError> ([&] { morphreg::loadProfileView (write ("f.json", side + R"("silhouette": []})")); },
                                  {"f.json", "0 points"});
  expectError<InvalidInputError> (
      [&] {
        morphreg::loadProfileView (
            write ("g.json", R"({"view": "profile", "image": {"width": 0, "height": 100}, "nose_tip": [1, 2],
                          "silhouette": [[1, 2], [3, 4]]})"));
      },
      {"g.json", "image size 0 x 100"});
  const std::string front = R"({"view": "frontal", "image": {"width": 100, "height": 100}, "units": "px", )";
  expectError<InvalidInputError> (
      [&] {
        morphreg::loadFrontalView (write ("h.json", front + R"("landmarks": [{"id": "nose_tip", "position": [1, 2]},
                                                          {"id": "third_eye", "position": [3, 4]}]})"));
      },
      {"h.json", "third_eye"});
  expectError<InvalidInputError> (
      [&] {
        morphreg::loadFrontalView (write ("i.json", front + R"("landmarks": [{"id": "chin", "position": [3, 4]}]})"));
      },
      {"i.json", "no nose tip"});
}

TEST (PhotoViewTest, PolylineClosestPointLiesOnTheNearestSegment)
{
  Eigen::Matrix2Xd points (2, 3);
  points << 0.0, 2.0, 2.0, 0.0, 0.0, 2.0;
  const morphreg::Polyline2d polyline (points);
  EXPECT_TRUE (polyline.closestPoint (Eigen::Vector2d (1.0, 0.5)).isApprox (Eigen::Vector2d (1.0, 0.0)));
  EXPECT_TRUE (polyline.closestPoint (Eigen::Vector2d (2.7, 1.2)).isApprox (Eigen::Vector2d (2.0, 1.2)));
  EXPECT_TRUE (polyline.closestPoint (Eigen::Vector2d (-1.0, -1.0)).isApprox (Eigen::Vector2d (0.0, 0.0)));
  EXPECT_TRUE (polyline.closestPoint (Eigen::Vector2d (3.0, 5.0)).isApprox (Eigen::Vector2d (2.0, 2.0)));
  EXPECT_THROW (morphreg::Polyline2d (Eigen::Matrix2Xd (2, 1)), InvalidInputError);
}

TEST (PhotoSimulatorTest, NoiseFreePhotosFollowTheKnownSimilarity)
{
  const auto& generator = morphreg::test::headGenerator (morphreg::test::kPhotoResolution);
  const Eigen::Matrix3Xd head = generator.sample (3).mesh.vertices;
  morphreg::synthetic::PhotoSimulator::Parameters camera;
  camera.rotation = Eigen::AngleAxisd (0.1, Eigen::Vector3d (1.0, 0.3, 0.2).normalized ()).toRotationMatrix ();
  camera.landmark_noise = 0.0;
  camera.silhouette_noise = 0.0;
  camera.silhouette_subdivisions = 0;
  const auto landmarks = morphreg::test::frontalLandmarks ();
  const auto photos =
      morphreg::synthetic::PhotoSimulator (camera).photograph (head, landmarks, generator.profileLine (), 1);
  const auto posed = [&] (int vertex) {
    return Eigen::Vector3d (photos.scale * photos.rotation * head.col (vertex) + photos.translation);
  };
  for (const auto& marked : photos.frontal.normalisedLandmarks ())
    EXPECT_LT ((marked.second - posed (landmarks.at (marked.first)).head<2> ()).norm (), 1e-12) << marked.first;
  const Eigen::Matrix2Xd silhouette = photos.profile.normalisedSilhouette ();
  ASSERT_EQ (silhouette.cols (), static_cast<Eigen::Index> (generator.profileLine ().size ()));
  for (Eigen::Index k = 0; k < silhouette.cols (); ++k) {
    const Eigen::Vector3d x = posed (generator.profileLine ()[k]);
    EXPECT_LT ((silhouette.col (k) - Eigen::Vector2d (x.z (), x.y ())).norm (), 1e-12);
  }
  EXPECT_THROW (morphreg::synthetic::PhotoSimulator ({0, 100}), InvalidInputError);
  EXPECT_THROW (
      morphreg::synthetic::PhotoSimulator (camera).photograph (head, {{"chin", 3}}, generator.profileLine (), 1),
      InvalidInputError);
}
} // namespace

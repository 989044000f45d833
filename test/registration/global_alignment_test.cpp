// SPDX-License-Identifier: BSD-3-Clause
// alignHeadGlobally and guessLengthUnit: bad input, and units recognised on a synthetic head in mm, cm and m.
#include "../support/synthetic_heads.h"

#include <morphreg/common/error.h>
#include <morphreg/common/length_unit.h>
#include <morphreg/registration/global_alignment.h>
#include <morphreg/synthetic/depth_camera_simulator.h>

#include <Eigen/Geometry>
#include "support/accuracy_bound.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace
{
using morphreg::InvalidInputError;

double
rmsRadius (const Eigen::Matrix3Xd& points)
{
  const Eigen::Vector3d centroid = points.rowwise ().mean ();
  return std::sqrt ((points.colwise () - centroid).colwise ().squaredNorm ().mean ());
}

TEST (GlobalAlignmentTest, RejectsBadInput)
{
  const morphreg::TriangleMesh head = morphreg::test::headGenerator (20).sample (1).mesh;
  const Eigen::Matrix3Xd few = head.vertices.leftCols (9);
  EXPECT_THROW (morphreg::alignHeadGlobally (head, few), InvalidInputError);
  Eigen::Matrix3Xd nan = head.vertices;
  nan (1, 3) = std::nan ("");
  EXPECT_THROW (morphreg::alignHeadGlobally (head, nan), InvalidInputError);
  EXPECT_THROW (morphreg::alignHeadGlobally (head, head.vertices, Eigen::Matrix3Xd::Zero (3, 5)), InvalidInputError);
  morphreg::GlobalAlignmentSettings bad;
  bad.max_radius_ratio = 0.5;
  EXPECT_THROW (morphreg::alignHeadGlobally (head, head.vertices, Eigen::Matrix3Xd (), bad), InvalidInputError);
}

TEST (GlobalAlignmentTest, FindsAHeadTurnedUpsideDown)
{
  const morphreg::TriangleMesh head = morphreg::test::headGenerator (24).sample (3).mesh;
  Eigen::Matrix4d pose = Eigen::Matrix4d::Identity ();
  pose.topLeftCorner<3, 3> () = 1.1 * Eigen::AngleAxisd (2.5, Eigen::Vector3d (1, 2, 0.5).normalized ()).matrix ();
  pose.topRightCorner<3, 1> () = Eigen::Vector3d (300, -200, 700);
  const Eigen::Matrix3Xd scan = (pose.topLeftCorner<3, 3> () * head.vertices).colwise () + pose.topRightCorner<3, 1> ();
  const morphreg::GlobalAlignment found = morphreg::alignHeadGlobally (head, scan);
  const Eigen::Matrix3Xd posed =
      (found.similarity.topLeftCorner<3, 3> () * head.vertices).colwise () + found.similarity.topRightCorner<3, 1> ();
  const double rms = std::sqrt ((posed - scan).colwise ().squaredNorm ().mean ());
  std::printf ("[ global ] upside-down head: vertex RMS %.2f mm, confidence %.2f\n  %s\n", rms, found.confidence,
               found.method.c_str ());
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, rms, 0.24) << "measured 0.189 mm";
  const double unaligned = std::sqrt ((head.vertices - scan).colwise ().squaredNorm ().mean ());
  EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, unaligned, 0.24) << "the head where it was, unaligned";
  EXPECT_GT (found.confidence, 0.3);
  EXPECT_LE (found.confidence, 1.0);
  EXPECT_FALSE (found.method.empty ());
}

/** The face and front of \a head (the triangles whose vertices lie in front of its centroid, +Z) as a Kinect-class
 *  depth camera 1 m away sees it from \a angle radians beside the nose (0: frontal), in mm: a face-only one-view
 *  scan, without a head sphere to find. */
Eigen::Matrix3Xd
faceSeenFrom (const morphreg::TriangleMesh& head, double angle, Eigen::Isometry3d& mesh_to_camera)
{
  const Eigen::Vector3d centre = head.vertices.rowwise ().mean ();
  const Eigen::Vector3d eye = centre + 1000.0 * Eigen::Vector3d (std::sin (angle), 0.1, std::cos (angle)).normalized ();
  mesh_to_camera = morphreg::synthetic::DepthCameraSimulator::lookAt (centre, eye);
  const morphreg::synthetic::DepthFrame frame =
      morphreg::synthetic::DepthCameraSimulator ().render (head, mesh_to_camera, 5);
  std::vector<Eigen::Vector3d> face;
  for (std::size_t pixel = 0; pixel < frame.depth.size (); ++pixel) {
    const int t = frame.source_triangle[pixel];
    if (t >= 0 && (head.vertices (2, head.triangles.col (t).array ()).array () > centre.z ()).all ())
      face.push_back (1000.0 * (*frame.cloud)[pixel].getVector3fMap ().cast<double> ());
  }
  Eigen::Matrix3Xd points (3, static_cast<Eigen::Index> (face.size ()));
  for (std::size_t i = 0; i < face.size (); ++i)
    points.col (static_cast<Eigen::Index> (i)) = face[i];
  return points;
}

TEST (GlobalAlignmentTest, FindsFacesSeenByADepthCameraFromTheFront)
{
  // Faces alone have no cranium to vote for a head sphere, and the model's centroid lies deep behind them: the
  // start lays the model's side facing the sensor onto the face (issue 31). Frontal and 20 degrees aside; from 30
  // degrees on, these smooth synthetic faces are found only at times (2 of 4 heads at 30 degrees), while the real
  // scans' depth crops from 45 degrees and in profile are in the real-scan zoo.
  const morphreg::synthetic::HeadGenerator& generator = morphreg::test::headGenerator (24);
  const morphreg::TriangleMesh mean = generator.generate (morphreg::synthetic::HeadParameters ());
  const int nose = generator.landmarks ().at ("nose_tip");
  std::vector<double> angles, nose_errors, unaligned_nose_errors;
  for (std::uint64_t seed = 1; seed <= 4; ++seed)
    for (const double view : {0.0, M_PI / 9.0}) {
      const morphreg::TriangleMesh head = generator.sample (seed).mesh;
      Eigen::Isometry3d mesh_to_camera;
      const Eigen::Matrix3Xd face = faceSeenFrom (head, view, mesh_to_camera);
      morphreg::GlobalAlignmentSettings settings;
      settings.viewpoint = Eigen::Vector3d::Zero ();
      const morphreg::GlobalAlignment found = morphreg::alignHeadGlobally (mean, face, Eigen::Matrix3Xd (), settings);
      const double scale = std::cbrt (found.similarity.topLeftCorner<3, 3> ().determinant ());
      const Eigen::Matrix3d rotation = found.similarity.topLeftCorner<3, 3> () / scale;
      angles.push_back (Eigen::AngleAxisd (rotation.transpose () * mesh_to_camera.linear ()).angle () * 180.0 / M_PI);
      const Eigen::Vector3d posed_nose =
          found.similarity.topLeftCorner<3, 3> () * mean.vertices.col (nose) + found.similarity.topRightCorner<3, 1> ();
      const Eigen::Vector3d true_nose = mesh_to_camera * head.vertices.col (nose);
      nose_errors.push_back ((posed_nose - true_nose).norm ());
      // The no-op: the mean's centroid on the face's, unturned.
      const Eigen::Vector3d shifted_nose =
          mean.vertices.col (nose) - mean.vertices.rowwise ().mean () + face.rowwise ().mean ();
      unaligned_nose_errors.push_back ((shifted_nose - true_nose).norm ());
      std::printf ("[ global ] head %d, view %.0f deg: %ld face points, rotation off by %.1f deg, nose tip %.1f mm\n",
                   static_cast<int> (seed), view * 180.0 / M_PI, static_cast<long> (face.cols ()), angles.back (),
                   nose_errors.back ());
    }
  const double worst_angle = *std::max_element (angles.begin (), angles.end ());
  const double worst_nose = *std::max_element (nose_errors.begin (), nose_errors.end ());
  // Before the one-view search every one of these 8 starts was 20 to 111 degrees off (nose tips 58 to 117 mm).
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, worst_angle, 4.5) << "measured 3.6 degrees";
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, worst_nose, 5.0) << "measured 4.1 mm";
  const double unaligned = *std::min_element (unaligned_nose_errors.begin (), unaligned_nose_errors.end ());
  EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, unaligned, 5.0)
      << "the mean on the face's centroid, unturned";
}

TEST (LengthUnitTest, GuessesMillimetresCentimetresAndMetres)
{
  const morphreg::TriangleMesh head = morphreg::test::headGenerator (20).sample (2).mesh;
  const double model_radius = rmsRadius (head.vertices);
  for (const morphreg::LengthUnit unit :
       {morphreg::LengthUnit::millimetre, morphreg::LengthUnit::centimetre, morphreg::LengthUnit::metre}) {
    const Eigen::Matrix3Xd scaled = head.vertices / morphreg::millimetresPer (unit);
    const morphreg::LengthUnitGuess guess = morphreg::guessLengthUnit (scaled, model_radius);
    EXPECT_EQ (guess.unit, unit) << guess.reason;
    EXPECT_NE (guess.reason.find (morphreg::toString (unit)), std::string::npos) << guess.reason;
  }
  const Eigen::Matrix3Xd inches = head.vertices / 25.4;
  EXPECT_EQ (morphreg::guessLengthUnit (inches, model_radius).unit, morphreg::LengthUnit::inch);
  const Eigen::Matrix3Xd huge = head.vertices * 1e6;
  const auto odd = morphreg::guessLengthUnit (huge, model_radius);
  EXPECT_EQ (odd.unit, morphreg::LengthUnit::millimetre);
  EXPECT_NE (odd.reason.find ("not head-sized"), std::string::npos) << odd.reason;
}

TEST (LengthUnitTest, ParsesSymbolsAndRejectsBadInput)
{
  for (const char* name : {"mm", "cm", "m", "in"})
    EXPECT_EQ (morphreg::toString (morphreg::parseLengthUnit (name)), name);
  try {
    morphreg::parseLengthUnit ("furlong");
    FAIL () << "no exception";
  }
  catch (const InvalidInputError& e) {
    EXPECT_NE (std::string (e.what ()).find ("furlong"), std::string::npos) << e.what ();
  }
  EXPECT_THROW (morphreg::guessLengthUnit (Eigen::Matrix3Xd::Zero (3, 3), 100.0), InvalidInputError);
  EXPECT_THROW (morphreg::guessLengthUnit (Eigen::Matrix3Xd::Random (3, 10), 0.0), InvalidInputError);
}

} // namespace

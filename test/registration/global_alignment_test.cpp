// SPDX-License-Identifier: BSD-3-Clause
// alignHeadGlobally and guessLengthUnit: bad input, and units recognised on a synthetic head in mm, cm and m.
#include "../support/synthetic_heads.h"

#include <morphreg/common/error.h>
#include <morphreg/common/length_unit.h>
#include <morphreg/registration/global_alignment.h>

#include <Eigen/Geometry>
#include "support/accuracy_bound.h"

#include <gtest/gtest.h>

#include <cstdio>

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

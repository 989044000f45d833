// SPDX-License-Identifier: BSD-3-Clause
// The checks around a registration: scans that cannot be registered, and fits that are not believable.
#include "../support/synthetic_heads.h"

#include <morphreg/common/error.h>
#include <morphreg/registration/fit_plausibility.h>
#include <morphreg/registration/scan_checks.h>

#include <gtest/gtest.h>

#include <string>

namespace
{
using morphreg::InvalidInputError;

/** The message of the InvalidInputError that requireRegistrableScan throws for \a points ("" if none). */
std::string
rejection (const Eigen::Matrix3Xd& points)
{
  try {
    morphreg::requireRegistrableScan (points, "scan.ply");
  }
  catch (const InvalidInputError& e) {
    return e.what ();
  }
  return "";
}

TEST (ScanChecksTest, RejectsScansThatCannotBeRegistered)
{
  const Eigen::Matrix3Xd head = morphreg::test::headGenerator (20).sample (1).mesh.vertices;
  EXPECT_EQ (rejection (head), "");
  EXPECT_NE (rejection (head.leftCols (99)).find ("scan.ply: 99 points, at least 100"), std::string::npos);
  Eigen::Matrix3Xd infinite = head;
  infinite (2, 17) = std::numeric_limits<double>::infinity ();
  EXPECT_NE (rejection (infinite).find ("scan.ply: point 17 is not finite"), std::string::npos);
  const Eigen::Matrix3Xd same = Eigen::Vector3d (1, 2, 3).replicate (1, 200);
  EXPECT_NE (rejection (same).find ("all 200 points are identical"), std::string::npos);
  Eigen::Matrix3Xd line (3, 200), flat = head.leftCols (200);
  for (Eigen::Index i = 0; i < 200; ++i)
    line.col (i) = Eigen::Vector3d (1, 2, 3) * static_cast<double> (i);
  flat.row (1).setConstant (5.0);
  EXPECT_NE (rejection (line).find ("collinear"), std::string::npos);
  EXPECT_NE (rejection (flat).find ("lie in a plane"), std::string::npos);
}

TEST (FitPlausibilityTest, NamesEveryFailedCheck)
{
  const morphreg::FitMeasures good;
  EXPECT_TRUE (morphreg::checkFitPlausibility (good).plausible);
  EXPECT_TRUE (morphreg::checkFitPlausibility (good).failures.empty ());

  morphreg::FitMeasures bad;
  bad.scale = 0.001;
  bad.correspondence_share = 0.1;
  bad.largest_sigma = 12.5;
  bad.thickness_ratio = 0.05;
  bad.median_residual = 12.0;
  bad.explained_share = 0.31;
  bad.scored_points = 17000;
  bad.folded_share = 0.2;
  bad.divergence = morphreg::IcpDivergence::unsolvable;
  bad.divergence_message = "the normal equations could not be solved";
  const auto verdict = morphreg::checkFitPlausibility (bad);
  EXPECT_FALSE (verdict.plausible);
  ASSERT_EQ (verdict.failures.size (), 8u);
  for (const char* text : {"scale 0.001", "10 % of the model has correspondences", "12.5 standard deviations",
                           "collapsed or flat", "12 mm from the scan", "explains 31 % of the 17000 scan points",
                           "folds over itself: 20 % of its area", "normal equations"}) {
    bool found = false;
    for (const std::string& failure : verdict.failures)
      found = found || failure.find (text) != std::string::npos;
    EXPECT_TRUE (found) << "no failure says '" << text << "'";
  }
  morphreg::FitMeasures settled;
  settled.divergence = morphreg::IcpDivergence::cost_rose;
  EXPECT_TRUE (morphreg::checkFitPlausibility (settled).plausible)
      << "a rising cost ends a settled fit: the best state is returned";
  settled.divergence = morphreg::IcpDivergence::prior_exceeded;
  EXPECT_TRUE (morphreg::checkFitPlausibility (settled).plausible)
      << "a coefficient leaving the prior ends the fit at its best state, which the other checks judge";
}

/** A flat sheet in the xy-plane, \a side x \a side squares of 10 mm split into triangles facing +z. */
morphreg::TriangleMesh
flatSheet (int side)
{
  morphreg::TriangleMesh sheet;
  sheet.vertices.resize (3, (side + 1) * (side + 1));
  for (int row = 0; row <= side; ++row)
    for (int column = 0; column <= side; ++column)
      sheet.vertices.col (row * (side + 1) + column) = Eigen::Vector3d (10.0 * column, 10.0 * row, 0.0);
  sheet.triangles.resize (3, 2 * side * side);
  for (int row = 0, t = 0; row < side; ++row)
    for (int column = 0; column < side; ++column, t += 2) {
      const int corner = row * (side + 1) + column;
      sheet.triangles.col (t) << corner, corner + 1, corner + side + 2;
      sheet.triangles.col (t + 1) << corner, corner + side + 2, corner + side + 1;
    }
  return sheet;
}

TEST (FitPlausibilityTest, MeasuresTheFoldedShareByArea)
{
  const morphreg::TriangleMesh sheet = flatSheet (8);
  const Eigen::VectorXd mean = Eigen::Map<const Eigen::VectorXd> (sheet.vertices.data (), sheet.vertices.size ());
  const auto model = morphreg::MorphableModel::fromGlobalPca (
      sheet.triangles, mean, Eigen::MatrixXd::Zero (mean.size (), 0), Eigen::VectorXd ());
  const Eigen::VectorXd residuals = Eigen::VectorXd::Constant (sheet.numVertices (), 0.5);
  auto foldedShare = [&] (const Eigen::Matrix3Xd& fitted) {
    const auto measures =
        morphreg::measureFit (*model, model->firstComponents (0), Eigen::VectorXd (), Eigen::Matrix4d::Identity (),
                              fitted, residuals, Eigen::Matrix3Xd (), morphreg::IcpReport (), 5);
    EXPECT_EQ (measures.explained_share, 1.0) << "no scan: nothing to explain";
    return measures.folded_share;
  };
  EXPECT_EQ (foldedShare (sheet.vertices), 0.0);
  // Mirrored in x, every triangle faces -z: all of the area is folded.
  Eigen::Matrix3Xd mirrored = sheet.vertices;
  mirrored.row (0) *= -1.0;
  EXPECT_DOUBLE_EQ (foldedShare (mirrored), 1.0);
  // Only the columns right of x = 40 mm folded back over the left half: half of the area.
  Eigen::Matrix3Xd half = sheet.vertices;
  for (Eigen::Index v = 0; v < half.cols (); ++v)
    half (0, v) = half (0, v) > 40.0 ? 80.0 - half (0, v) : half (0, v);
  EXPECT_NEAR (foldedShare (half), 0.5, 1e-9);
}

TEST (FitPlausibilityTest, MeasuresTheScanExplained)
{
  const morphreg::TriangleMesh head = morphreg::test::headGenerator (20).sample (1).mesh;
  const Eigen::VectorXd mean = Eigen::Map<const Eigen::VectorXd> (head.vertices.data (), head.vertices.size ());
  const auto model_pointer = morphreg::MorphableModel::fromGlobalPca (
      head.triangles, mean, Eigen::MatrixXd::Zero (mean.size (), 0), Eigen::VectorXd ());
  const morphreg::MorphableModel& model = *model_pointer;
  const Eigen::VectorXd residuals = Eigen::VectorXd::Constant (head.numVertices (), 0.5);
  const morphreg::IcpReport report;
  const morphreg::ComponentSelection none = model.firstComponents (0);
  // The scan: the head's own vertices, half of them pushed 20 mm outwards (unexplained).
  Eigen::Matrix3Xd scan = head.vertices;
  const Eigen::Vector3d centre = head.vertices.rowwise ().mean ();
  for (Eigen::Index i = 0; i < scan.cols (); i += 2)
    scan.col (i) += 20.0 * (scan.col (i) - centre).normalized ();
  const auto measures = morphreg::measureFit (model, none, Eigen::VectorXd (), Eigen::Matrix4d::Identity (),
                                              head.vertices, residuals, scan, report, 5);
  EXPECT_NEAR (measures.explained_share, 0.5, 0.03);
  ASSERT_EQ (measures.region_coverage.size (), 1u) << "one region, the whole head";
  EXPECT_EQ (measures.region_coverage.front ().second, 1.0) << "every vertex has a correspondence within 0.5 mm";
  EXPECT_GT (measures.scored_points, head.numVertices () / 2);
  EXPECT_EQ (measures.folded_share, 0.0);
  // The scan seen from the front only: the back half of the vertices without correspondences.
  Eigen::VectorXd front_only = residuals;
  for (Eigen::Index v = 0; v < head.numVertices (); ++v)
    if (head.vertices (2, v) < centre.z ())
      front_only[v] = std::nan ("");
  const double front_share = (head.vertices.row (2).array () >= centre.z ()).cast<double> ().mean ();
  const auto front = morphreg::measureFit (model, none, Eigen::VectorXd (), Eigen::Matrix4d::Identity (), head.vertices,
                                           front_only, scan, report, 5);
  EXPECT_DOUBLE_EQ (front.region_coverage.front ().second, front_share);
  EXPECT_THROW (morphreg::measureFit (model, none, Eigen::VectorXd (), Eigen::Matrix4d::Identity (), head.vertices,
                                      residuals.head (5), scan, report, 5),
                InvalidInputError);
}

TEST (ScanChecksTest, LandmarksOffTheScanAreRejectedNamingTheFileAndTheUnits)
{
  Eigen::Matrix3Xd scan (3, 8); // a 200 mm box
  for (int i = 0; i < 8; ++i)
    scan.col (i) = 100.0 * Eigen::Vector3d (i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
  const morphreg::LandmarkPositions on_scan = {{"nose_tip", {0.0, 30.0, 110.0}}, {"chin", {0.0, -40.0, 95.0}}};
  EXPECT_NO_THROW (morphreg::requireLandmarksOnScan (on_scan, scan, "landmarks.json"));
  // Millimetre values in a file that says metres: converted, they lie kilometres away.
  morphreg::LandmarkPositions in_metres = on_scan;
  for (auto& entry : in_metres)
    entry.second *= 1000.0;
  try {
    morphreg::requireLandmarksOnScan (in_metres, scan, "landmarks.json");
    ADD_FAILURE () << "landmarks 110 m away accepted";
  }
  catch (const InvalidInputError& e) {
    const std::string message = e.what ();
    EXPECT_NE (message.find ("landmarks.json: landmark "), std::string::npos) << message;
    EXPECT_NE (message.find ("units"), std::string::npos) << message;
  }
}
} // namespace

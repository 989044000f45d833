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
  const Eigen::Matrix3Xd head = morphreg::test::headGenerator (20).sample (1).mesh.vertices;
  const Eigen::VectorXd residuals = Eigen::VectorXd::Constant (head.cols (), 0.5);
  const Eigen::VectorXd coefficients = Eigen::VectorXd::Constant (10, 1.0);
  morphreg::IcpReport report;
  report.fitness_median = 0.5;
  const auto good = morphreg::checkFitPlausibility (1.0, head, residuals, coefficients, report);
  EXPECT_TRUE (good.plausible);
  EXPECT_TRUE (good.failures.empty ());

  Eigen::VectorXd sparse = Eigen::VectorXd::Constant (head.cols (), std::nan (""));
  sparse.head (head.cols () / 10).setConstant (0.5);
  Eigen::VectorXd wild = coefficients;
  wild[3] = -6.5;
  Eigen::Matrix3Xd flat = head;
  flat.row (2) *= 0.05;
  report.fitness_median = 12.0;
  report.divergence = morphreg::IcpDivergence::unsolvable;
  report.message = "the normal equations could not be solved";
  const auto bad = morphreg::checkFitPlausibility (0.001, flat, sparse, wild, report);
  EXPECT_FALSE (bad.plausible);
  ASSERT_EQ (bad.failures.size (), 6u);
  for (const char* text : {"scale 0.001", "% of the model has correspondences", "6.5 standard deviations",
                           "collapsed or flat", "12 mm from the scan", "normal equations"}) {
    bool found = false;
    for (const std::string& failure : bad.failures)
      found = found || failure.find (text) != std::string::npos;
    EXPECT_TRUE (found) << "no failure says '" << text << "'";
  }
  report = morphreg::IcpReport ();
  report.divergence = morphreg::IcpDivergence::cost_rose;
  EXPECT_TRUE (morphreg::checkFitPlausibility (1.0, head, residuals, coefficients, report).plausible)
      << "a rising cost ends a settled fit: the best state is returned";
  EXPECT_THROW (morphreg::checkFitPlausibility (1.0, head, residuals.head (5), coefficients, report),
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

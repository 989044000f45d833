// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/warp/thin_plate_spline.h>

#include "support/accuracy_bound.h"
#include "tps_test_support.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <limits>

using morphreg::InvalidInputError;
using morphreg::NumericalError;
using morphreg::ThinPlateSpline;
using morphreg::test::bend;
using morphreg::test::extent;
using morphreg::test::maxColumnDistance;
using morphreg::test::randomLandmarks;

namespace
{
/** sign * trace(W^T K W) computed from the public accessors, independently of the solver. */
template <int Dim>
double
directBendingEnergy (const ThinPlateSpline<double, Dim>& tps)
{
  const auto& p = tps.getLandmarks ();
  const auto& w = tps.getWeights ();
  double energy = 0.0;
  for (Eigen::Index i = 0; i < p.rows (); ++i)
    for (Eigen::Index j = 0; j < p.rows (); ++j) {
      const double r2 = (p.row (i) - p.row (j)).squaredNorm ();
      const double u = Dim == 3 ? std::sqrt (r2) : (r2 > 0 ? r2 * std::log (r2) : 0.0);
      energy += u * w.row (i).dot (w.row (j));
    }
  return Dim == 3 ? -energy : energy;
}

Eigen::Matrix3Xd
affineMap (const Eigen::Matrix3Xd& points, const Eigen::Matrix3d& linear, const Eigen::Vector3d& shift)
{
  return (linear * points).colwise () + shift;
}

const Eigen::Matrix3d kLinear = (Eigen::Matrix3d () << 1.1, 0.2, -0.1, 0.05, 0.9, 0.3, -0.2, 0.1, 1.3).finished ();
const Eigen::Vector3d kShift (12.0, -40.0, 7.5);
} // namespace

TEST (TpsTest, InterpolatesLandmarksExactly3D)
{
  const Eigen::Matrix3Xd source = randomLandmarks (120, 1, 300.0, 500.0); // away from the origin on purpose
  const Eigen::Matrix3Xd target = bend<3> (source);
  ThinPlateSpline<double, 3> tps;
  tps.fit (source, target);
  EXPECT_LE (maxColumnDistance (tps.evaluate (source), target), 1e-9 * extent (target));
  for (int j = 0; j < 5; ++j)
    EXPECT_LE ((tps.transformPoint (source.col (j)) - target.col (j)).norm (), 1e-9 * extent (target));
  EXPECT_GT (tps.bendingEnergy (), 0.0);
  EXPECT_NEAR (tps.bendingEnergy (), directBendingEnergy (tps), 1e-9 * tps.bendingEnergy ());
  EXPECT_GT (tps.conditionEstimate (), 1.0);
  EXPECT_EQ (tps.mergedLandmarks (), 0);
  // Between landmarks the warp follows the smooth bend closely.
  const Eigen::Matrix3Xd inside = randomLandmarks (200, 2, 200.0, 500.0);
  const Eigen::VectorXd errors = (tps.evaluate (inside) - bend<3> (inside)).colwise ().norm ();
  const Eigen::VectorXd identity = (inside - bend<3> (inside)).colwise ().norm (); // the no-op: points left in place
  std::cout << "between the landmarks: mean error " << errors.mean () << " mm (max " << errors.maxCoeff ()
            << "); the identity warp " << identity.mean () << " mm (max " << identity.maxCoeff () << ")\n";
  // Measured: mean 1.01 mm, max 3.31 mm; the identity 47.3 mm (max 59.7).
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, errors.mean (), 1.2);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, errors.maxCoeff (), 4.0);
  EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, identity.mean (), 1.2);
  EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, identity.maxCoeff (), 4.0);
}

TEST (TpsTest, InterpolatesLandmarksExactly2D)
{
  const Eigen::Matrix2Xd source = randomLandmarks<2> (80, 3, 100.0);
  const Eigen::Matrix2Xd target = bend<2> (source);
  ThinPlateSpline<double, 2> tps;
  tps.fit (source, target);
  EXPECT_LE (maxColumnDistance (tps.evaluate (source), target), 1e-9 * extent (target));
  EXPECT_GT (tps.bendingEnergy (), 0.0);
  EXPECT_NEAR (tps.bendingEnergy (), directBendingEnergy (tps), 1e-9 * tps.bendingEnergy ());
}

TEST (TpsTest, FloatSplineIsFittedInDoubleAndEvaluatesToFloatPrecision)
{
  const Eigen::Matrix3Xd source = randomLandmarks (60, 4);
  const Eigen::Matrix3Xd target = bend<3> (source);
  ThinPlateSpline<float, 3> tps;
  tps.fit (source.cast<float> (), target.cast<float> ());
  EXPECT_LE (maxColumnDistance (tps.evaluate (source.cast<float> ()).cast<double> (), target), 1e-4 * extent (target));
}

TEST (TpsTest, ReproducesAffineMapsWithZeroWeights)
{
  const Eigen::Matrix3Xd source = randomLandmarks (40, 5, 150.0, -80.0);
  ThinPlateSpline<double, 3> tps;
  tps.fit (source, affineMap (source, kLinear, kShift));
  const double scale = extent (source);
  EXPECT_LE (tps.getWeights ().cwiseAbs ().maxCoeff (), 1e-12 * scale);
  EXPECT_LE ((tps.getAffine ().row (0).transpose () - kShift).norm (), 1e-9 * scale);
  EXPECT_LE ((tps.getAffine ().bottomRows (3).transpose () - kLinear).norm (), 1e-12 * scale);
  EXPECT_LE (tps.bendingEnergy (), 1e-18 * scale);
  const Eigen::Matrix3Xd elsewhere = randomLandmarks (500, 6, 600.0);
  EXPECT_LE (maxColumnDistance (tps.evaluate (elsewhere), affineMap (elsewhere, kLinear, kShift)), 1e-9 * scale);
  EXPECT_LE ((tps.jacobian (elsewhere.col (0)) - kLinear).norm (), 1e-9);
}

// Four landmarks in 3D fix an affine map and leave the spline nothing to bend (the sanitizer run found the bending
// energy of that case computed from an empty triangular product).
TEST (TpsTest, FourLandmarksIn3DAreAnAffineMapWithoutBending)
{
  const Eigen::Matrix3Xd source = randomLandmarks (4, 7, 150.0);
  Eigen::Matrix3Xd target = affineMap (source, kLinear, kShift);
  target.col (3) += Eigen::Vector3d (1.0, -2.0, 0.5); // any four targets are an affine map of four free points
  ThinPlateSpline<double, 3> tps;
  tps.fit (source, target);
  EXPECT_EQ (tps.bendingEnergy (), 0.0);
  EXPECT_LE (maxColumnDistance (tps.evaluate (source), target), 1e-9 * extent (source));
}

TEST (TpsTest, ReproducesAffineMaps2D)
{
  const Eigen::Matrix2Xd source = randomLandmarks<2> (30, 7);
  const Eigen::Matrix2d linear = kLinear.topLeftCorner<2, 2> ();
  ThinPlateSpline<double, 2> tps;
  tps.fit (source, (linear * source).colwise () + kShift.head<2> ());
  EXPECT_LE (tps.getWeights ().cwiseAbs ().maxCoeff (), 1e-9);
  EXPECT_LE ((tps.getAffine ().bottomRows (2).transpose () - linear).norm (), 1e-9);
  EXPECT_LE (std::abs (tps.bendingEnergy ()), 1e-9);
}

TEST (TpsTest, JacobianMatchesFiniteDifferences)
{
  const Eigen::Matrix3Xd source = randomLandmarks (30, 8);
  ThinPlateSpline<double, 3> tps;
  tps.fit (source, bend<3> (source));
  const Eigen::Vector3d x (13.0, -27.0, 41.0);
  Eigen::Matrix3d numeric;
  const double h = 1e-5;
  for (int l = 0; l < 3; ++l)
    numeric.col (l) = (tps.transformPoint (x + h * Eigen::Vector3d::Unit (l)) -
                       tps.transformPoint (x - h * Eigen::Vector3d::Unit (l))) /
                      (2 * h);
  EXPECT_LE ((tps.jacobian (x) - numeric).norm (), 1e-6);
}

TEST (TpsTest, RegularisationTradesFidelityForSmoothness)
{
  const Eigen::Matrix3Xd source = randomLandmarks (100, 9);
  Eigen::Matrix3Xd target = bend<3> (source);
  target += randomLandmarks (100, 10, 4.0); // +-2 mm of noise
  double previous_energy = std::numeric_limits<double>::infinity (), previous_residual = -1.0;
  for (const double lambda : {0.0, 1.0, 10.0, 100.0, 1000.0, 1e4}) {
    ThinPlateSpline<double, 3> tps;
    tps.setRegularization (lambda);
    tps.fit (source, target);
    const Eigen::Matrix3Xd fitted = tps.evaluate (source);
    // The regularised normal equations: q_i - f(p_i) = -lambda w_i (3D, U = +r).
    EXPECT_LE (maxColumnDistance (target - fitted, -lambda * tps.getWeights ().transpose ()), 1e-9 * extent (target))
        << lambda;
    const double residual = (target - fitted).norm ();
    EXPECT_LT (tps.bendingEnergy (), previous_energy) << lambda;
    EXPECT_GT (residual, previous_residual) << lambda;
    previous_energy = tps.bendingEnergy ();
    previous_residual = residual;
  }
  // Very strong smoothing tends to the least-squares affine map.
  ThinPlateSpline<double, 3> smooth;
  smooth.setRegularization (1e9);
  smooth.fit (source, target);
  Eigen::MatrixXd p (100, 4);
  p << Eigen::VectorXd::Ones (100), source.transpose ();
  const Eigen::MatrixXd least_squares = p.colPivHouseholderQr ().solve (target.transpose ());
  EXPECT_LE ((smooth.getAffine () - least_squares).norm (), 1e-3);
}

TEST (TpsTest, MergesCoincidentLandmarkPairs)
{
  const Eigen::Matrix3Xd source = randomLandmarks (20, 11);
  const Eigen::Matrix3Xd target = bend<3> (source);
  Eigen::Matrix3Xd source_dup (3, 23), target_dup (3, 23);
  source_dup << source, source.col (4), source.col (0), source.col (4);
  target_dup << target, target.col (4), target.col (0), target.col (4);
  ThinPlateSpline<double, 3> reference, merged;
  reference.fit (source, target);
  merged.fit (source_dup, target_dup);
  EXPECT_EQ (merged.mergedLandmarks (), 3);
  EXPECT_EQ (merged.getLandmarks ().rows (), 20);
  const Eigen::Matrix3Xd queries = randomLandmarks (50, 12);
  EXPECT_LE (maxColumnDistance (merged.evaluate (queries), reference.evaluate (queries)), 1e-9 * extent (target));
}

TEST (TpsTest, RejectsTooFewLandmarks)
{
  ThinPlateSpline<double, 3> tps;
  const Eigen::Matrix3Xd three = randomLandmarks (3, 13);
  EXPECT_THROW (tps.fit (three, three), InvalidInputError);
  // Four given, but two coincide: three distinct are too few.
  Eigen::Matrix3Xd four (3, 4);
  four << three, three.col (1);
  try {
    tps.fit (four, four);
    FAIL () << "expected InvalidInputError";
  }
  catch (const InvalidInputError& e) {
    EXPECT_NE (std::string (e.what ()).find ("only 3 distinct"), std::string::npos) << e.what ();
  }
  EXPECT_FALSE (tps.isFitted ());
  ThinPlateSpline<double, 2> tps2;
  const Eigen::Matrix2Xd two = randomLandmarks<2> (2, 14);
  EXPECT_THROW (tps2.fit (two, two), InvalidInputError);
  EXPECT_THROW (tps.fit (Eigen::Matrix3Xd (3, 0), Eigen::Matrix3Xd (3, 0)), InvalidInputError);
}

TEST (TpsTest, RejectsCoplanarAndCollinearLandmarks)
{
  ThinPlateSpline<double, 3> tps;
  Eigen::Matrix3Xd planar = randomLandmarks (30, 15);
  planar.row (2) = 0.3 * planar.row (0) - 0.2 * planar.row (1) + Eigen::RowVectorXd::Constant (30, 5.0);
  try {
    tps.fit (planar, bend<3> (planar));
    FAIL () << "expected InvalidInputError";
  }
  catch (const InvalidInputError& e) {
    EXPECT_NE (std::string (e.what ()).find ("coplanar"), std::string::npos) << e.what ();
  }
  Eigen::Matrix3Xd line (3, 10);
  for (int j = 0; j < 10; ++j)
    line.col (j) = Eigen::Vector3d (1, 2, 3) * j + Eigen::Vector3d (4, 5, 6);
  try {
    tps.fit (line, line);
    FAIL () << "expected InvalidInputError";
  }
  catch (const InvalidInputError& e) {
    EXPECT_NE (std::string (e.what ()).find ("collinear"), std::string::npos) << e.what ();
  }
  ThinPlateSpline<double, 2> tps2;
  EXPECT_THROW (tps2.fit (line.topRows<2> (), line.topRows<2> ()), InvalidInputError);
}

TEST (TpsTest, RejectsCoincidentSourcesWithDifferentTargets)
{
  Eigen::Matrix3Xd source = randomLandmarks (10, 16), target = bend<3> (source);
  source.col (7) = source.col (2);
  target.col (7) = target.col (2) + Eigen::Vector3d (1.0, 0.0, 0.0);
  ThinPlateSpline<double, 3> tps;
  try {
    tps.fit (source, target);
    FAIL () << "expected InvalidInputError";
  }
  catch (const InvalidInputError& e) {
    EXPECT_NE (std::string (e.what ()).find ("source landmarks 2 and 7 coincide"), std::string::npos) << e.what ();
  }
}

TEST (TpsTest, RejectsNonFiniteAndMismatchedLandmarks)
{
  const Eigen::Matrix3Xd source = randomLandmarks (10, 17), target = bend<3> (source);
  ThinPlateSpline<double, 3> tps;
  Eigen::Matrix3Xd bad = source;
  bad (1, 3) = std::numeric_limits<double>::quiet_NaN ();
  EXPECT_THROW (tps.fit (bad, target), InvalidInputError);
  bad = target;
  bad (0, 5) = std::numeric_limits<double>::infinity ();
  try {
    tps.fit (source, bad);
    FAIL () << "expected InvalidInputError";
  }
  catch (const InvalidInputError& e) {
    EXPECT_NE (std::string (e.what ()).find ("target landmark 5 is not finite"), std::string::npos) << e.what ();
  }
  try {
    tps.fit (source, target.leftCols (9));
    FAIL () << "expected InvalidInputError";
  }
  catch (const InvalidInputError& e) {
    EXPECT_NE (std::string (e.what ()).find ("mismatched landmark counts"), std::string::npos) << e.what ();
  }
}

TEST (TpsTest, RejectsBadParametersAndUseBeforeFit)
{
  ThinPlateSpline<double, 3> tps;
  EXPECT_THROW (tps.setRegularization (-1.0), InvalidInputError);
  EXPECT_THROW (tps.setRegularization (std::numeric_limits<double>::quiet_NaN ()), InvalidInputError);
  EXPECT_THROW (tps.setMaxConditionNumber (0.5), InvalidInputError);
  EXPECT_THROW (tps.transformPoint (Eigen::Vector3d::Zero ()), InvalidInputError);
  EXPECT_THROW (tps.evaluate (Eigen::Matrix3Xd::Zero (3, 4)), InvalidInputError);
  EXPECT_THROW (tps.getWeights (), InvalidInputError);
  EXPECT_THROW (tps.bendingEnergy (), InvalidInputError);
}

TEST (TpsTest, ReportsIllConditionedSystems)
{
  // Two landmarks 3e-11 of the extent apart with different targets: solvable in exact arithmetic, but the
  // weights would be mostly round-off. The limit is configurable.
  Eigen::Matrix3Xd source = randomLandmarks (30, 18), target = bend<3> (source);
  source.col (29) = source.col (3) + Eigen::Vector3d (1e-8, 0.0, 0.0);
  target.col (29) = target.col (3) + Eigen::Vector3d (0.0, 5.0, 0.0);
  ThinPlateSpline<double, 3> tps;
  try {
    tps.fit (source, target);
    FAIL () << "expected NumericalError";
  }
  catch (const NumericalError& e) {
    EXPECT_NE (std::string (e.what ()).find ("condition estimate"), std::string::npos) << e.what ();
  }
  EXPECT_FALSE (tps.isFitted ());
  // The same landmarks pass with a well separated pair.
  source.col (29) = source.col (3) + Eigen::Vector3d (20.0, 0.0, 0.0);
  tps.fit (source, target);
  EXPECT_LT (tps.conditionEstimate (), (ThinPlateSpline<double, 3>::kDefaultMaxConditionNumber));
  tps.setMaxConditionNumber (0.5 * tps.conditionEstimate ());
  EXPECT_THROW (tps.fit (source, target), NumericalError);
}

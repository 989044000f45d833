// SPDX-License-Identifier: BSD-3-Clause
// The robust kernels (robust_kernel.h, kernels/): every registered kernel made by name, weighs as its formula says,
// has the tuning constant of 95 % Gaussian efficiency, and its automatic or fixed width.
#include "support/expect_error.h"

#include <morphreg/common/error.h>
#include <morphreg/registration/robust_kernel.h>

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

namespace
{
/** The asymptotic efficiency under N(0, 1) residuals of the M-estimator with psi(r) = r * weight (r / c):
 *  E[psi']^2 / E[psi^2], integrated on a fine grid. */
double
gaussianEfficiency (const morphreg::RobustKernel& kernel, double c)
{
  const auto psi = [&] (double r) { return r * kernel.weightAt (std::abs (r) / c); };
  constexpr int kSteps = 40000;
  constexpr double kEnd = 12.0, kDerivativeStep = 1e-5;
  const double h = 2.0 * kEnd / kSteps;
  double slope = 0.0, square = 0.0;
  for (int i = 0; i <= kSteps; ++i) {
    const double r = -kEnd + i * h;
    const double density = std::exp (-0.5 * r * r) / std::sqrt (2.0 * M_PI);
    slope += (psi (r + kDerivativeStep) - psi (r - kDerivativeStep)) / (2.0 * kDerivativeStep) * density * h;
    square += psi (r) * psi (r) * density * h;
  }
  return slope * slope / square;
}

TEST (RobustKernelTest, EveryRegisteredKernelIsMadeByItsName)
{
  ASSERT_GE (morphreg::robustKernelNames ().size (), 5u);
  for (const std::string& name : morphreg::robustKernelNames ()) {
    const auto kernel = morphreg::makeRobustKernel (name, 2.5);
    EXPECT_EQ (kernel->name (), name);
    EXPECT_EQ (kernel->getScale (), 2.5);
  }
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> (
      [] { morphreg::makeRobustKernel ("bisquare"); }, "robust kernel \"bisquare\" is none of none, huber, tukey");
}

TEST (RobustKernelTest, WeightsFollowTheirFormulas)
{
  const std::map<std::string, double> at_two{
      {"none", 1.0}, {"huber", 0.5}, {"tukey", 0.0}, {"cauchy", 0.2}, {"geman_mcclure", 0.04}};
  for (const auto& [name, expected] : at_two)
    EXPECT_NEAR (morphreg::makeRobustKernel (name)->weight (2.0, 1.0), expected, 1e-12) << name;
  for (const std::string& name : morphreg::robustKernelNames ()) {
    const auto kernel = morphreg::makeRobustKernel (name);
    EXPECT_EQ (kernel->weightAt (0.0), 1.0) << name;
    double previous = 1.0;
    for (double u = 0.0; u < 10.0; u += 0.01) { // in [0, 1], never rising with the distance
      const double w = kernel->weightAt (u);
      EXPECT_TRUE (w >= 0.0 && w <= previous + 1e-15) << name << " at " << u << ": " << w;
      previous = w;
    }
  }
}

TEST (RobustKernelTest, TuningConstantsGiveNinetyFivePercentEfficiency)
{
  for (const std::string& name : morphreg::robustKernelNames ()) {
    if (name == "none")
      continue; // least squares is fully efficient at any width
    const auto kernel = morphreg::makeRobustKernel (name);
    const double efficiency = gaussianEfficiency (*kernel, kernel->tuningConstant ());
    std::printf ("[ kernels ] %s: c = %.4f, Gaussian efficiency %.4f\n", name.c_str (), kernel->tuningConstant (),
                 efficiency);
    EXPECT_NEAR (efficiency, 0.95, 0.001) << name;
  }
}

TEST (RobustKernelTest, WidthsAreAutomaticOrFixed)
{
  const auto tukey = morphreg::makeRobustKernel ("tukey");
  EXPECT_DOUBLE_EQ (tukey->width ({1.0, 1.0, 1.0}), 4.685 * 1.4826);
  EXPECT_DOUBLE_EQ (tukey->width ({}), 4.685 * 1e-6);
  EXPECT_DOUBLE_EQ (morphreg::makeRobustKernel ("huber", 3.0)->width ({1.0}), 3.0);
  EXPECT_EQ (morphreg::makeRobustKernel ("huber", -1.0)->getScale (), 0.0); // <= 0: automatic
}

TEST (RobustKernelTest, RedescendingKernelsStartGraduatedFitsWithHuber)
{
  for (const std::string& name : morphreg::robustKernelNames ()) {
    const auto kernel = morphreg::makeRobustKernel (name, 4.0);
    const bool redescending = kernel->weightAt (100.0) < 1.0 / 100.0; // falls faster than Huber's 1/u
    const auto start = kernel->graduatedStart ();
    EXPECT_EQ (start != nullptr, redescending) << name;
    if (start) {
      EXPECT_EQ (start->name (), "huber") << name;
      EXPECT_EQ (start->getScale (), 4.0) << name;
    }
  }
}
} // namespace

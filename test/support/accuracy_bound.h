// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Accuracy bounds that fail when the result they guard is broken: a figure must meet its bound, and the bound must
// stay within kBoundSlack of the figure, so that a bound far above what the code achieves (one that a no-op or a
// broken result would also meet) is itself a failure.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace morphreg
{
namespace test
{
/** How far a bound may lie beyond the figure it guards: 1.3 x an error, or 1.3 x the shortfall of a share. */
constexpr double kBoundSlack = 1.3;

/** Whether the suites run capped (MORPHREG_TEST_SAMPLES, the sanitizer run): their aggregates are then taken over
 *  fewer samples and may lie further below their bounds, which still hold; only the slack is not checked. */
inline bool
samplesCapped ()
{
  return std::getenv ("MORPHREG_TEST_SAMPLES") != nullptr;
}

/** \brief What a capped run does with a figure taken over the suite's samples: it prints the figure beside its bound
 *  and asserts nothing, as its few samples are not the suite. */
inline ::testing::AssertionResult
printedForTheSamplesRun (const char* figure_text, const char* bound_text, double figure, double bound)
{
  std::printf ("[ samples ] %s = %g over the samples run (bound %s = %g, asserted on the whole suite only)\n",
               figure_text, figure, bound_text, bound);
  return ::testing::AssertionSuccess ();
}

/** \brief A figure taken over the suite's samples (a model's generalisation) lies within \a tolerance of a reference
 *  figure over the same samples; asserted on the whole suite only, as suiteMedianUpperBound. */
inline ::testing::AssertionResult
suiteFigureNear (const char* figure_text, const char* reference_text, const char* tolerance_text, double figure,
                 double reference, double tolerance)
{
  if (samplesCapped ())
    return printedForTheSamplesRun (figure_text, reference_text, figure, reference);
  if (std::abs (figure - reference) <= tolerance)
    return ::testing::AssertionSuccess ();
  return ::testing::AssertionFailure () << figure_text << " = " << figure << " is further than " << tolerance_text
                                        << " = " << tolerance << " from " << reference_text << " = " << reference;
}

/** \brief An error figure (lower is better, e.g. an RMS in mm) meets \a bound, and \a bound is at most kBoundSlack
 *  times the figure. Use as EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, rms, 1.2). */
inline ::testing::AssertionResult
tightUpperBound (const char* figure_text, const char* bound_text, double figure, double bound)
{
  std::ostringstream why;
  if (!(figure <= bound))
    why << figure_text << " = " << figure << " exceeds its bound " << bound_text << " = " << bound;
  else if (bound > kBoundSlack * figure && !samplesCapped ())
    why << figure_text << " = " << figure << " meets its bound " << bound_text << " = " << bound
        << ", but the bound is " << bound / figure
        << " x the figure: a broken result could pass it; tighten it to at most " << kBoundSlack * figure;
  else
    return ::testing::AssertionSuccess ();
  return ::testing::AssertionFailure () << why.str ();
}

/** \brief tightUpperBound for a figure taken over the suite's samples (a median of its heads): a capped run's few
 *  samples are not the suite, and their median may be one outlier's, so there the figure is printed, not asserted
 *  (the per-sample bounds and the worst case, which hold for any subset, are). */
inline ::testing::AssertionResult
suiteMedianUpperBound (const char* figure_text, const char* bound_text, double figure, double bound)
{
  if (!samplesCapped ())
    return tightUpperBound (figure_text, bound_text, figure, bound);
  return printedForTheSamplesRun (figure_text, bound_text, figure, bound);
}

/** \brief A share (higher is better, in [0, 1], e.g. a coverage) meets \a bound, and the shortfall the bound allows,
 *  1 - bound, is at most kBoundSlack times the figure's own, 1 - figure. */
inline ::testing::AssertionResult
tightLowerBound (const char* figure_text, const char* bound_text, double figure, double bound)
{
  std::ostringstream why;
  if (!(figure >= bound))
    why << figure_text << " = " << figure << " is below its bound " << bound_text << " = " << bound;
  else if (1.0 - bound > kBoundSlack * (1.0 - figure) && !samplesCapped ())
    why << figure_text << " = " << figure << " meets its bound " << bound_text << " = " << bound
        << ", but the bound allows a shortfall " << (1.0 - bound) / (1.0 - figure)
        << " x the figure's: tighten it to at least " << 1.0 - kBoundSlack * (1.0 - figure);
  else
    return ::testing::AssertionSuccess ();
  return ::testing::AssertionFailure () << why.str ();
}

/** \brief tightLowerBound for a share taken over the suite's samples (a median coverage): asserted on the whole
 *  suite only, as suiteMedianUpperBound. */
inline ::testing::AssertionResult
suiteMedianLowerBound (const char* figure_text, const char* bound_text, double figure, double bound)
{
  if (!samplesCapped ())
    return tightLowerBound (figure_text, bound_text, figure, bound);
  return printedForTheSamplesRun (figure_text, bound_text, figure, bound);
}

/** \brief What a no-op (the mean head, the identity warp, the unfitted model) scores fails the bound that the real
 *  result meets: the bound tells a result from its absence. */
inline ::testing::AssertionResult
noOpFailsUpperBound (const char* figure_text, const char* bound_text, double no_op_figure, double bound)
{
  if (no_op_figure > bound)
    return ::testing::AssertionSuccess ();
  return ::testing::AssertionFailure () << "the no-op's " << figure_text << " = " << no_op_figure << " meets the bound "
                                        << bound_text << " = " << bound << ": the test cannot tell a fit from none";
}
} // namespace test
} // namespace morphreg

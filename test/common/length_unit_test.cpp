// SPDX-License-Identifier: BSD-3-Clause
// guessLengthUnit on head-sized point sets in every unit, the sizes each unit is recognised over, and the unit
// symbols; the scan checks and the fit's plausibility checks are in test/registration/scan_checks_test.cpp.
#include <morphreg/common/error.h>
#include <morphreg/common/head_scale_unit.h>
#include <morphreg/common/length_unit.h>

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
using morphreg::LengthUnit;

constexpr LengthUnit kUnits[] = {LengthUnit::millimetre, LengthUnit::centimetre, LengthUnit::metre, LengthUnit::inch};

/** \a count points spread evenly over an ellipsoid of radii 80 (x, ear to ear), 100 (y, up) and 90 mm (z, front):
 *  a bald head's size. */
Eigen::Matrix3Xd
ellipsoidHead (int count)
{
  Eigen::Matrix3Xd points (3, count);
  const double golden_angle = M_PI * (3.0 - std::sqrt (5.0));
  for (int i = 0; i < count; ++i) {
    const double y = 1.0 - 2.0 * (i + 0.5) / count;
    const double ring = std::sqrt (1.0 - y * y);
    points.col (i) = Eigen::Vector3d (80.0 * ring * std::cos (golden_angle * i), 100.0 * y,
                                      90.0 * ring * std::sin (golden_angle * i));
  }
  return points;
}

/** The head on a wider slab of shoulders below it (the top of a 400 x 120 mm slab, 100 mm under the chin), as a
 *  head-and-shoulders scan sees it. */
Eigen::Matrix3Xd
headAndShoulders ()
{
  const Eigen::Matrix3Xd head = ellipsoidHead (3000);
  std::vector<Eigen::Vector3d> shoulders;
  for (double x = -200.0; x <= 200.0; x += 5.0)
    for (double z = -60.0; z <= 60.0; z += 5.0)
      shoulders.emplace_back (x, -200.0 - 0.002 * x * x, z);
  Eigen::Matrix3Xd points (3, head.cols () + static_cast<Eigen::Index> (shoulders.size ()));
  points << head,
      Eigen::Map<const Eigen::Matrix3Xd> (shoulders.front ().data (), 3, static_cast<Eigen::Index> (shoulders.size ()));
  return points;
}

/** The RMS distance of the ellipsoid head from its centre: the model mean's radius in these tests. */
double
modelRadius ()
{
  return std::sqrt (ellipsoidHead (3000).colwise ().squaredNorm ().mean ());
}

TEST (UnitGuessTest, HeadAloneIsRecognisedInEveryUnit)
{
  const Eigen::Matrix3Xd head = ellipsoidHead (3000);
  for (const LengthUnit unit : kUnits) {
    const morphreg::LengthUnitGuess guess =
        morphreg::guessLengthUnit (head / morphreg::millimetresPer (unit), modelRadius ());
    EXPECT_EQ (guess.unit, unit) << guess.reason;
    EXPECT_NEAR (guess.size_ratio * morphreg::millimetresPer (unit), 0.95, 0.1) << guess.reason;
  }
}

TEST (UnitGuessTest, HeadWithShouldersIsRecognisedInEveryUnit)
{
  const Eigen::Matrix3Xd scan = headAndShoulders ();
  for (const LengthUnit unit : kUnits) {
    const morphreg::LengthUnitGuess guess =
        morphreg::guessLengthUnit (scan / morphreg::millimetresPer (unit), modelRadius ());
    EXPECT_EQ (guess.unit, unit) << guess.reason;
    EXPECT_NEAR (guess.size_ratio * morphreg::millimetresPer (unit), 1.5, 0.2) << guess.reason;
  }
}

TEST (UnitGuessTest, FarOutliersDoNotChangeTheGuess)
{
  Eigen::Matrix3Xd scan = ellipsoidHead (3000) / 1000.0; // metres
  for (Eigen::Index i = 0; i < scan.cols (); i += 40)    // 2.5 % of the points 50 m away
    scan.col (i) = Eigen::Vector3d (50.0, -30.0, 20.0);
  const morphreg::LengthUnitGuess guess = morphreg::guessLengthUnit (scan, modelRadius ());
  EXPECT_EQ (guess.unit, LengthUnit::metre) << guess.reason;
  EXPECT_NEAR (guess.size_ratio * 1000.0, 0.95, 0.1) << guess.reason;
}

TEST (UnitGuessTest, EachUnitIsRecognisedOverItsDocumentedSizes)
{
  // length_unit.h: the sizes (scan over model, in the scan's true unit) each unit is recognised over.
  const std::vector<std::pair<LengthUnit, std::pair<double, double>>> ranges = {{LengthUnit::millimetre, {0.45, 9.9}},
                                                                                {LengthUnit::centimetre, {0.75, 4.4}},
                                                                                {LengthUnit::metre, {0.31, 9.9}},
                                                                                {LengthUnit::inch, {0.31, 1.87}}};
  const Eigen::Matrix3Xd head = ellipsoidHead (1000);
  const double head_radius = morphreg::guessLengthUnit (head, 1.0).size_ratio; // its robust radius, mm
  for (const auto& [unit, range] : ranges)
    for (int step = 0; step <= 20; ++step) {
      const double size = range.first * std::pow (range.second / range.first, step / 20.0);
      const morphreg::LengthUnitGuess guess =
          morphreg::guessLengthUnit (head / morphreg::millimetresPer (unit), head_radius / size);
      EXPECT_EQ (guess.unit, unit) << "size " << size << ": " << guess.reason;
    }
  // Beyond them: a face alone (half the model) in cm reads as inches, a scan 20 times the model as nothing.
  EXPECT_EQ (morphreg::guessLengthUnit (head / 10.0, head_radius / 0.5).unit, LengthUnit::inch);
  const morphreg::LengthUnitGuess huge = morphreg::guessLengthUnit (head, head_radius / 20.0);
  EXPECT_EQ (huge.unit, LengthUnit::millimetre);
  EXPECT_NE (huge.reason.find ("not head-sized in any unit"), std::string::npos) << huge.reason;
}

TEST (UnitGuessTest, ReasonGivesTheSizesAndTheUnit)
{
  const morphreg::LengthUnitGuess guess = morphreg::guessLengthUnit (headAndShoulders () / 1000.0, modelRadius ());
  ASSERT_EQ (guess.unit, LengthUnit::metre);
  EXPECT_NE (guess.reason.find ("the scan's RMS radius is 0.1"), std::string::npos) << guess.reason;
  EXPECT_NE (guess.reason.find ("against the model's 90."), std::string::npos) << guess.reason;
  EXPECT_NE (guess.reason.find ("taken as m (x1000 to mm), it is 1."), std::string::npos) << guess.reason;
}

TEST (UnitGuessTest, BadInputIsReported)
{
  const auto message = [] (const Eigen::Matrix3Xd& points, double model_radius) -> std::string {
    try {
      morphreg::guessLengthUnit (points, model_radius);
    }
    catch (const morphreg::InvalidInputError& e) {
      return e.what ();
    }
    return "";
  };
  EXPECT_NE (message (ellipsoidHead (3), 90.0).find ("at least 4 finite points, got 3"), std::string::npos);
  Eigen::Matrix3Xd broken = ellipsoidHead (100);
  broken (1, 50) = std::nan ("");
  EXPECT_NE (message (broken, 90.0).find ("non-finite"), std::string::npos);
  EXPECT_NE (message (ellipsoidHead (100), 0.0).find ("model radius must be positive"), std::string::npos);
  EXPECT_NE (message (ellipsoidHead (100), std::nan ("")).find ("model radius"), std::string::npos);
}

/** What a fit finds at \a tried's scale of a head-and-shoulders scan whose unit is \a true_mm_per_unit and whose head
 *  is \a head_scale times the model: the head at tried.scale_to_mm / true_mm_per_unit times its true size. */
morphreg::LengthUnitGuess
unitAfterFit (const morphreg::LengthUnitGuess& tried, double true_mm_per_unit, double head_scale)
{
  return morphreg::unitFromHeadScale (tried, head_scale * tried.scale_to_mm / true_mm_per_unit, 0.75, 1.33);
}

// Units that are no units (head_scale_unit.h): 0.1 m, 0.37 mm, 7 mm and 0.093 mm per unit. The size guess reads 0.1 m
// per unit as inches (0.39 times the true size), 0.37 mm per unit as mm (2.7 times too large), 7 mm per unit as cm
// (1.43 times too large) and 0.093 mm per unit as nothing; the fit at the suggested unit finds the head at a scale no
// head has, so the provisional scale brings each to 1.1 times the model, and the head's fitted scale then gives the
// unit's true mm.
TEST (HeadScaleUnitTest, ArbitraryUnitsAreEstimatedFromTheHead)
{
  const Eigen::Matrix3Xd scan = headAndShoulders ();
  for (const auto& [mm_per_unit, size_guess] :
       std::vector<std::pair<double, bool>>{{100.0, true}, {0.37, true}, {7.0, true}, {0.093, false}}) {
    const morphreg::LengthUnitGuess guess = morphreg::guessLengthUnit (scan / mm_per_unit, modelRadius ());
    EXPECT_EQ (guess.recognised, size_guess) << mm_per_unit << ": " << guess.reason;
    const morphreg::LengthUnitGuess provisional = morphreg::provisionalHeadScale (guess);
    EXPECT_TRUE (provisional.estimated);
    EXPECT_NEAR (provisional.scale_to_mm * guess.size_ratio, morphreg::kProvisionalHeadRatio, 1e-12);
    const morphreg::LengthUnitGuess unit = unitAfterFit (provisional, mm_per_unit, 1.0);
    EXPECT_TRUE (unit.estimated && !unit.recognised) << unit.reason;
    EXPECT_NEAR (unit.scale_to_mm / mm_per_unit, 1.0, 1e-12) << unit.reason;
    EXPECT_NE (unit.reason.find ("estimated from the head"), std::string::npos) << unit.reason;
    // a head 10 % larger than the model is taken at the model's size: the unit comes out 10 % small
    EXPECT_NEAR (unitAfterFit (provisional, mm_per_unit, 1.1).scale_to_mm / mm_per_unit, 1.0 / 1.1, 1e-12);
  }
}

// A known unit is kept whenever it puts the head at a plausible scale (0.75-1.33): a large head in cm (1.28, as Lee
// Perry-Smith's read at 7.3 mm per unit), a small one in inches, a scan in metres brought to 1.1 times the model.
TEST (HeadScaleUnitTest, KnownUnitIsPreferredWhenPlausible)
{
  morphreg::LengthUnitGuess tried;
  tried.size_ratio = 0.01;
  tried.scale_to_mm = 10.0;
  const morphreg::LengthUnitGuess large_in_cm = morphreg::unitFromHeadScale (tried, 1.28, 0.75, 1.33);
  EXPECT_EQ (large_in_cm.unit, LengthUnit::centimetre);
  EXPECT_TRUE (large_in_cm.recognised && !large_in_cm.estimated) << large_in_cm.reason;
  EXPECT_EQ (large_in_cm.scale_to_mm, 10.0);
  EXPECT_NE (large_in_cm.reason.find ("taken as cm (x10 to mm), it is 1.28 times the model"), std::string::npos)
      << large_in_cm.reason;
  tried.scale_to_mm = 30.0;
  EXPECT_EQ (morphreg::unitFromHeadScale (tried, 1.0, 0.75, 1.33).unit, LengthUnit::inch); // a head of 0.85
  tried.scale_to_mm = 1100.0;
  EXPECT_EQ (morphreg::unitFromHeadScale (tried, 1.05, 0.75, 1.33).unit, LengthUnit::metre);
  EXPECT_TRUE (morphreg::unitFromHeadScale (tried, 1.6, 0.75, 1.33).estimated); // 0.6 in metres: no unit
}

TEST (HeadScaleUnitTest, BadInputIsReported)
{
  morphreg::LengthUnitGuess tried;
  EXPECT_THROW (morphreg::provisionalHeadScale (tried), morphreg::InvalidInputError); // no size ratio
  tried.size_ratio = std::nan ("");
  EXPECT_THROW (morphreg::provisionalHeadScale (tried), morphreg::InvalidInputError);
  tried.size_ratio = 1.0;
  EXPECT_THROW (morphreg::unitFromHeadScale (tried, 0.0, 0.75, 1.33), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::unitFromHeadScale (tried, std::nan (""), 0.75, 1.33), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::unitFromHeadScale (tried, 1.0, -1.0, 1.33), morphreg::InvalidInputError);
  tried.scale_to_mm = 0.0;
  EXPECT_THROW (morphreg::unitFromHeadScale (tried, 1.0, 0.75, 1.33), morphreg::InvalidInputError);
}

// A model's mean in the unit its file does not state: a head (ellipsoid, RMS radius 90 mm), a face alone and a body
// recognised in mm, cm and m as documented; a body in cm is taken for mm; micrometres fit no unit.
TEST (ModelUnitGuessTest, HeadsFacesAndBodiesAreRecognisedWhereDocumented)
{
  const Eigen::Matrix3Xd head = ellipsoidHead (500);
  for (const LengthUnit unit : {LengthUnit::millimetre, LengthUnit::centimetre, LengthUnit::metre}) {
    for (const double size : {0.6, 1.0, 5.5}) { // a face alone, a head, a body (RMS radius about 500 mm)
      const morphreg::LengthUnitGuess guess = morphreg::guessModelUnit (size * head / morphreg::millimetresPer (unit));
      const bool body_in_cm = size > 5.0 && unit == LengthUnit::centimetre;
      EXPECT_EQ (guess.unit, body_in_cm ? LengthUnit::millimetre : unit) << morphreg::toString (unit) << " " << size;
      EXPECT_TRUE (guess.recognised) << guess.reason;
    }
  }
  const morphreg::LengthUnitGuess metres = morphreg::guessModelUnit (head / 1000.0);
  EXPECT_NE (metres.reason.find ("the mean's RMS radius is 0.09"), std::string::npos) << metres.reason;
  EXPECT_NE (metres.reason.find ("taken as m (x1000 to mm), it is 0.9"), std::string::npos) << metres.reason;
  const morphreg::LengthUnitGuess micrometres = morphreg::guessModelUnit (head * 1000.0);
  EXPECT_FALSE (micrometres.recognised);
  EXPECT_EQ (micrometres.unit, LengthUnit::millimetre);
  EXPECT_NE (micrometres.reason.find ("no head, face or body in mm, cm or m"), std::string::npos) << micrometres.reason;
  EXPECT_THROW (morphreg::guessModelUnit (head.leftCols (2)), morphreg::InvalidInputError);
}

TEST (LengthUnitSymbolTest, SymbolsRoundTripAndFactorsAreMillimetres)
{
  const std::vector<std::pair<std::string, double>> expected = {
      {"mm", 1.0}, {"cm", 10.0}, {"dm", 100.0}, {"m", 1000.0}, {"in", 25.4}};
  for (const auto& [symbol, millimetres] : expected) {
    const LengthUnit unit = morphreg::parseLengthUnit (symbol);
    EXPECT_EQ (morphreg::toString (unit), symbol);
    EXPECT_EQ (morphreg::millimetresPer (unit), millimetres);
  }
}

TEST (LengthUnitSymbolTest, UnknownSymbolsNameTheTextAndTheChoices)
{
  for (const std::string bad : {"inch", "MM", "", "furlong"}) {
    try {
      morphreg::parseLengthUnit (bad);
      ADD_FAILURE () << "'" << bad << "' was accepted";
    }
    catch (const morphreg::InvalidInputError& e) {
      const std::string text = e.what ();
      EXPECT_NE (text.find ("'" + bad + "'"), std::string::npos) << text;
      EXPECT_NE (text.find ("mm, cm, dm, m or in"), std::string::npos) << text;
    }
  }
}

} // namespace

#pragma once
/** \file length_unit.h
 *  \brief Length units of scans (mm, cm, m, inches) and a guess of a scan's unit from its size against a head model.
 */
#include <Eigen/Core>

#include <string>

namespace morphreg
{
/** \brief The length units scans arrive in. */
enum class LengthUnit
{
  millimetre,
  centimetre,
  metre,
  inch
};

/** \brief Millimetres per \a unit: 1, 10, 1000 or 25.4. */
double
millimetresPer (LengthUnit unit);

/** \brief The unit's symbol: "mm", "cm", "m" or "in". */
std::string
toString (LengthUnit unit);

/** \brief The unit of a symbol ("mm", "cm", "m", "in"); InvalidInputError naming the text and the choices. */
LengthUnit
parseLengthUnit (const std::string& name);

/** \brief A guessed unit, the scan's size over the model's as given (ratio) and a sentence saying why. */
struct LengthUnitGuess
{
  LengthUnit unit = LengthUnit::millimetre;
  double size_ratio = 0.0;
  std::string reason;
};

/** \brief Guesses the unit of \a points (3 x N) from their size against a head model's, \a model_radius_mm (the RMS
 *  distance of the model mean's vertices from their centroid). The size is the RMS distance from the centroid of
 *  the 90 % of points nearest to the coordinate-wise median; in each unit it is compared with the model's, and the
 *  unit making the scan closest to the model's size (in log scale) wins, inches paying a 0.15 decade handicap (cm
 *  and inches differ by only 2.54; metric scans are far more common). A head alone is about 1x the model, a head
 *  with shoulders 1.5-2x, a face 0.5x: each lands on its true metric unit; a head with shoulders in inches is taken
 *  for cm (give the unit). A scan that is not within 0.3-10x the model in any unit is taken as mm, and the reason
 *  says so. Throws InvalidInputError for fewer than 4 or non-finite points, or a non-positive model radius.
 */
LengthUnitGuess
guessLengthUnit (const Eigen::Matrix3Xd& points, double model_radius_mm);

} // namespace morphreg

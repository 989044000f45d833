// SPDX-License-Identifier: BSD-3-Clause
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
  millimetre, ///< mm, the library's own unit
  centimetre, ///< cm
  decimetre,  ///< dm (MakeHuman's unit; never guessed)
  metre,      ///< m
  inch        ///< in, 25.4 mm
};

/** \brief Millimetres per \a unit: 1, 10, 100, 1000 or 25.4.
 *  \param[in] unit the unit
 *  \return the length of one \a unit in mm
 */
double
millimetresPer (LengthUnit unit);

/** \brief The unit's symbol: "mm", "cm", "dm", "m" or "in".
 *  \param[in] unit the unit
 *  \return its symbol
 */
std::string
toString (LengthUnit unit);

/** \brief The unit of a symbol ("mm", "cm", "dm", "m", "in"); InvalidInputError naming the text and the choices.
 *  \param[in] name the symbol, e.g. from a command line option
 *  \return the unit it names
 */
LengthUnit
parseLengthUnit (const std::string& name);

/** \brief A guessed unit, the scan's size over the model's as given (ratio) and a sentence saying why. */
struct LengthUnitGuess
{
  LengthUnit unit = LengthUnit::millimetre; ///< the unit the scan is taken to be in
  double size_ratio = 0.0;                  ///< the scan's size over the model's, both as given
  std::string reason;                       ///< one sentence with the numbers behind the choice
  bool recognised = true;                   ///< false when no unit gives the expected size (the unit is then mm)
  /** mm per scan unit: millimetresPer (unit), or when \a estimated a factor found from the head itself */
  double scale_to_mm = 1.0;
  bool estimated = false; ///< true when scale_to_mm is no unit's but estimated (see head_scale_unit.h)
};

/** \brief Guesses the unit of \a points (3 x N) from their size against a head model's, \a model_radius_mm (the RMS
 *  distance of the model mean's vertices from their centroid, mm).
 *
 *  The scan's size is the RMS distance from their centroid of the 90 % of points nearest to the coordinate-wise
 *  median (a few far outliers do not count); r = size / model_radius_mm. Read in unit u, the scan is
 *  r * millimetresPer (u) times the model's size; the unit whose reading is closest in log10 to 1.4 wins (a head with
 *  some neck or shoulders is about 1.4 times the model's RMS radius), inches paying 0.15 decades more (metric scans
 *  are far more common, and cm and inches are only 2.54 apart). If even the best unit puts the scan outside 0.3-10
 *  times the model, it is taken as mm and the reason says it is not head-sized in any unit.
 *
 *  Sizes recognised (the scan over the model in its true unit): mm 0.44-10, cm 0.74-4.4, inches 0.3-1.88, m 0.3-10.
 *  Heads alone (0.7-1.1) and heads with neck and shoulders (about 1.5, e.g. the real 82k-point scan 1.55) are
 *  recognised in every unit; a wider head-and-shoulders scan (over 1.88) in inches is taken for cm, and a face alone
 *  (about 0.5) is recognised in mm and m but taken for inches in cm: give the unit in those cases.
 *
 *  A depth camera's view (\a one_view: an organised cloud) is read in mm or m only (depth images hold mm, PCL's
 *  grabbers deliver metres) and may be up to 40 times the model (the room around the person).
 *
 *  \param[in] points the scan's points, 3 x N, in their file's unit
 *  \param[in] model_radius_mm the model's RMS radius in mm
 *  \param[in] one_view whether the scan is one depth camera's view

 *  \return the unit, r and one sentence with the numbers, e.g. "the scan's RMS radius is 0.128 against the model's
 *  104 mm: taken as m (x1000 to mm), it is 1.23 times the model".
 *  Throws InvalidInputError for fewer than 4 or non-finite points, or a non-positive model radius.
 */
LengthUnitGuess
guessLengthUnit (const Eigen::Matrix3Xd& points, double model_radius_mm, bool one_view = false);

/** \brief A head model's RMS radius in mm (the distance of its mean's vertices from their centroid): the size
 *  guessModelUnit expects. ICT-FaceKit's head and neck have 95 mm, the synthetic heads about 90 mm. */
constexpr double kHeadModelRadiusMm = 100.0;

/** \brief Guesses the unit of a shape model's mean (3 x N) that does not state it (a statismo file), from its RMS
 *  radius r in the file's numbers: read in mm, cm or m, the reading closest in log10 to a head model's
 *  kHeadModelRadiusMm wins, so r above 31.6 is mm, 1 to 31.6 cm and below 1 m. Heads (about 100 mm), faces alone
 *  (about 60 mm) and whole bodies in mm or m (about 500 mm) are recognised; a body in cm (r about 50) is taken for mm,
 *  so such a model must state its unit. When even the best unit puts the model outside 0.1-30 times a head model's
 *  radius (r below 0.01 or above 3000, e.g. micrometres), it is not recognised.
 *  \param[in] mean the model's mean vertices, 3 x N, in their file's unit
 *  \return the unit, r over kHeadModelRadiusMm, one sentence with the numbers (e.g. "the mean's RMS radius is 0.0951:
 *  taken as m (x1000 to mm), it is 0.951 times a head model's 100 mm"), and whether it was recognised.
 *  Throws InvalidInputError for fewer than 3 or non-finite vertices.
 */
LengthUnitGuess
guessModelUnit (const Eigen::Matrix3Xd& mean);

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include "number_text.h"

#include <morphreg/common/error.h>
#include <morphreg/common/length_unit.h>
#include <morphreg/common/order_statistics.h>

#include <algorithm>
#include <cmath>
#include <vector>

namespace morphreg
{
namespace
{
using detail::numberText;

/** The units a scan may be guessed in; decimetres (MakeHuman's unit, no scanner's) are only taken when given. */
constexpr LengthUnit kUnits[] = {LengthUnit::millimetre, LengthUnit::centimetre, LengthUnit::metre, LengthUnit::inch};

/** A head with some neck or shoulders over the model's RMS radius: the size a scan is expected to have. */
constexpr double kExpectedSizeRatio = 1.4;
/** Decades added to the inch's distance: metric scans are far more common, and cm and inches are only 2.54 apart. */
constexpr double kInchHandicap = 0.15;
/** Scans outside this size against the model in their best unit do not look like a head in any unit. */
constexpr double kMinHeadRatio = 0.3;
constexpr double kMaxHeadRatio = 10.0;

/** RMS distance from the centroid of the 90 % of \a points nearest to their coordinate-wise median. */
double
robustRadius (const Eigen::Matrix3Xd& points)
{
  const Eigen::Matrix3Xd kept = pointsNearMedian (points, 0.9, 4);
  const Eigen::Vector3d centroid = kept.rowwise ().mean ();
  return std::sqrt ((kept.colwise () - centroid).colwise ().squaredNorm ().mean ());
}

/** How far (decades, with the inch's handicap) reading the scan in \a unit puts it from the expected head size;
 *  \a size_ratio is the scan's size over the model's in the scan's own numbers. */
double
distanceFromHeadSize (double size_ratio, LengthUnit unit)
{
  return std::abs (std::log10 (size_ratio * millimetresPer (unit) / kExpectedSizeRatio)) +
         (unit == LengthUnit::inch ? kInchHandicap : 0.0);
}

/** The units a depth camera's view may be in. */
constexpr LengthUnit kViewUnits[] = {LengthUnit::millimetre, LengthUnit::metre};

/** A depth camera's view may hold the room around the person: up to this size against the model. */
constexpr double kMaxViewRatio = 40.0;

/** The unit of \a candidates whose reading puts the scan closest to the expected head size. */
template <typename Units>
LengthUnit
closestUnit (double size_ratio, const Units& candidates)
{
  LengthUnit best = LengthUnit::millimetre;
  for (LengthUnit unit : candidates)
    if (distanceFromHeadSize (size_ratio, unit) < distanceFromHeadSize (size_ratio, best))
      best = unit;
  return best;
}

/** The units a model may be guessed in: the metric ones modelling tools write (statismo, scalismo, BFM: mm; MNE,
 *  Open3D, Blender exports: m; ICT-FaceKit: cm). */
constexpr LengthUnit kModelUnits[] = {LengthUnit::millimetre, LengthUnit::centimetre, LengthUnit::metre};
/** A model outside this size against a head model's in its best unit is no head, face or body in any unit. */
constexpr double kMinModelRatio = 0.1;
constexpr double kMaxModelRatio = 30.0;

void
requireFinitePoints (const Eigen::Matrix3Xd& points, Eigen::Index minimum, const std::string& who)
{
  if (points.cols () < minimum || !points.allFinite ())
    throw InvalidInputError (who + ": need at least " + std::to_string (minimum) + " finite points, got " +
                             std::to_string (points.cols ()) +
                             (points.allFinite () ? "" : " with non-finite coordinates"));
}

/** The guess's one sentence: the scan's size, the model's, and what the chosen \a unit makes of it. */
std::string
explainGuess (double radius, double model_radius_mm, LengthUnit unit, double relative, bool head_sized)
{
  const std::string sizes = "the scan's RMS radius is " + numberText (radius) + " against the model's " +
                            numberText (model_radius_mm) + " mm: ";
  if (!head_sized)
    return sizes + "it is not head-sized in any unit, so it is taken as mm";
  return sizes + "taken as " + toString (unit) + " (x" + numberText (millimetresPer (unit), 6) + " to mm), it is " +
         numberText (relative) + " times the model";
}
} // namespace

double
millimetresPer (LengthUnit unit)
{
  switch (unit) {
  case LengthUnit::centimetre:
    return 10.0;
  case LengthUnit::decimetre:
    return 100.0;
  case LengthUnit::metre:
    return 1000.0;
  case LengthUnit::inch:
    return 25.4;
  case LengthUnit::millimetre:
    break;
  }
  return 1.0;
}

std::string
toString (LengthUnit unit)
{
  switch (unit) {
  case LengthUnit::centimetre:
    return "cm";
  case LengthUnit::decimetre:
    return "dm";
  case LengthUnit::metre:
    return "m";
  case LengthUnit::inch:
    return "in";
  case LengthUnit::millimetre:
    break;
  }
  return "mm";
}

LengthUnit
parseLengthUnit (const std::string& name)
{
  for (LengthUnit unit : kUnits)
    if (toString (unit) == name)
      return unit;
  if (name == toString (LengthUnit::decimetre))
    return LengthUnit::decimetre;
  throw InvalidInputError ("unknown length unit '" + name + "': choose mm, cm, dm, m or in");
}

LengthUnitGuess
guessLengthUnit (const Eigen::Matrix3Xd& points, double model_radius_mm, bool one_view)
{
  requireFinitePoints (points, 4, "guessLengthUnit");
  if (!(model_radius_mm > 0.0) || !std::isfinite (model_radius_mm))
    throw InvalidInputError ("guessLengthUnit: the model radius must be positive and finite, got " +
                             std::to_string (model_radius_mm));
  const double radius = robustRadius (points);
  LengthUnitGuess guess;
  guess.size_ratio = radius / model_radius_mm;
  guess.unit = one_view ? closestUnit (guess.size_ratio, kViewUnits) : closestUnit (guess.size_ratio, kUnits);
  const double relative = guess.size_ratio * millimetresPer (guess.unit);
  const bool head_sized = relative >= kMinHeadRatio && relative <= (one_view ? kMaxViewRatio : kMaxHeadRatio);
  guess.reason = explainGuess (radius, model_radius_mm, guess.unit, relative, head_sized);
  guess.recognised = head_sized;
  if (!head_sized)
    guess.unit = LengthUnit::millimetre;
  guess.scale_to_mm = millimetresPer (guess.unit);
  return guess;
}

LengthUnitGuess
guessModelUnit (const Eigen::Matrix3Xd& mean)
{
  requireFinitePoints (mean, 3, "guessModelUnit");
  const double radius = std::sqrt ((mean.colwise () - mean.rowwise ().mean ()).colwise ().squaredNorm ().mean ());
  LengthUnitGuess guess;
  guess.size_ratio = radius / kHeadModelRadiusMm;
  const auto distance = [&] (LengthUnit unit) {
    return std::abs (std::log10 (guess.size_ratio * millimetresPer (unit)));
  };
  for (LengthUnit unit : kModelUnits)
    if (distance (unit) < distance (guess.unit))
      guess.unit = unit;
  const double relative = guess.size_ratio * millimetresPer (guess.unit);
  guess.recognised = relative >= kMinModelRatio && relative <= kMaxModelRatio;
  const std::string size = "the mean's RMS radius is " + numberText (radius) + ": ";
  guess.reason = guess.recognised
                     ? size + "taken as " + toString (guess.unit) + " (x" +
                           numberText (millimetresPer (guess.unit), 6) + " to mm), it is " + numberText (relative) +
                           " times a head model's " + numberText (kHeadModelRadiusMm) + " mm"
                     : size + "no head, face or body in mm, cm or m (a head model's is " +
                           numberText (kHeadModelRadiusMm) + " mm)";
  if (!guess.recognised)
    guess.unit = LengthUnit::millimetre;
  guess.scale_to_mm = millimetresPer (guess.unit);
  return guess;
}

} // namespace morphreg

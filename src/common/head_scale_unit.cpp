// SPDX-License-Identifier: BSD-3-Clause
#include "number_text.h"

#include <morphreg/common/error.h>
#include <morphreg/common/head_scale_unit.h>

#include <cmath>
#include <optional>

namespace morphreg
{
namespace
{
using detail::numberText;

/** The known units a head's scale may point to (decimetres, MakeHuman's, only when given). */
constexpr LengthUnit kKnownUnits[] = {LengthUnit::millimetre, LengthUnit::centimetre, LengthUnit::metre,
                                      LengthUnit::inch};

void
requirePositive (double value, const char* what)
{
  if (!(value > 0.0) || !std::isfinite (value))
    throw InvalidInputError (std::string ("unitFromHeadScale: ") + what + " must be positive and finite, got " +
                             numberText (value));
}

/** The head's scale against the model when the scan is read in \a unit, the head saying \a estimate mm per unit. */
double
headScaleIn (LengthUnit unit, double estimate)
{
  return millimetresPer (unit) / estimate;
}

/** "mm 9.3, cm 93, m 9.3e+03, in 24": the head's scale in each known unit. */
std::string
scalesInKnownUnits (double estimate)
{
  std::string text;
  for (LengthUnit unit : kKnownUnits)
    text += (text.empty () ? "" : ", ") + toString (unit) + " " + numberText (headScaleIn (unit, estimate));
  return text;
}
} // namespace

LengthUnitGuess
provisionalHeadScale (const LengthUnitGuess& guess)
{
  if (!(guess.size_ratio > 0.0) || !std::isfinite (guess.size_ratio))
    throw InvalidInputError ("provisionalHeadScale: the scan's size ratio must be positive and finite, got " +
                             numberText (guess.size_ratio));
  LengthUnitGuess provisional = guess;
  provisional.scale_to_mm = kProvisionalHeadRatio / guess.size_ratio;
  provisional.estimated = true;
  provisional.recognised = false;
  provisional.unit = LengthUnit::millimetre;
  provisional.reason = guess.reason + "; brought provisionally to " + numberText (kProvisionalHeadRatio) +
                       " times the model's size (x" + numberText (provisional.scale_to_mm) +
                       " to mm) to find the head and its scale";
  return provisional;
}

LengthUnitGuess
unitFromHeadScale (const LengthUnitGuess& tried, double fitted_scale, double min_scale, double max_scale)
{
  requirePositive (tried.scale_to_mm, "the scale tried");
  requirePositive (fitted_scale, "the fitted scale");
  requirePositive (min_scale, "the smallest head scale");
  requirePositive (max_scale, "the largest head scale");
  const double estimate = tried.scale_to_mm / fitted_scale;
  std::optional<LengthUnit> best; // the known unit that puts the head closest to the model's size, if plausible
  for (LengthUnit known : kKnownUnits) {
    const double scale = headScaleIn (known, estimate);
    if (scale >= min_scale && scale <= max_scale &&
        (!best || std::abs (std::log (scale)) < std::abs (std::log (headScaleIn (*best, estimate)))))
      best = known;
  }
  LengthUnitGuess unit = tried;
  unit.recognised = best.has_value ();
  unit.estimated = !best;
  unit.unit = best.value_or (LengthUnit::millimetre);
  unit.scale_to_mm = best ? millimetresPer (*best) : estimate;
  const std::string found = "the head, fitted at x" + numberText (tried.scale_to_mm) + " to mm, is " +
                            numberText (fitted_scale) + " times the model's size: ";
  unit.reason = unit.estimated
                    ? found + "no unit puts it within " + numberText (min_scale) + "-" + numberText (max_scale) +
                          " times the model (" + scalesInKnownUnits (estimate) +
                          "), so its scale is estimated from the head at the model's size: x" +
                          numberText (estimate, 4) + " to mm"
                    : found + "taken as " + toString (unit.unit) + " (x" + numberText (unit.scale_to_mm, 6) +
                          " to mm), it is " + numberText (headScaleIn (unit.unit, estimate)) + " times the model";
  return unit;
}

} // namespace morphreg

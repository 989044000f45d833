// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file head_scale_unit.h
 *  \brief A scan's unit estimated from the head itself, for scans whose size is a head in no known unit (phone and
 *  photogrammetry captures in an arbitrary scene unit): a provisional scale brings the scan to a head's size, a
 *  fit's similarity scale then says how large the head is, and that gives the mm per scan unit.
 */
#include <morphreg/common/length_unit.h>

namespace morphreg
{
/** \brief The scan's size over the model's RMS radius that provisionalHeadScale brings a scan to: between a head
 *  alone (0.7-1.1) and a head with neck and shoulders (about 1.55), so that either lands within the 0.6-1.6 head
 *  scales the global alignment searches. */
constexpr double kProvisionalHeadRatio = 1.1;

/** \brief \a guess (guessLengthUnit's) with a provisional scale: the factor (mm per scan unit) that makes the scan's
 *  robust size kProvisionalHeadRatio times the model's, marked estimated, and a reason saying so. A fit at this
 *  scale finds the head and measures it (unitFromHeadScale).
 *  Throws InvalidInputError when \a guess has no positive, finite size ratio.
 *  \param[in] guess the guess from the scan's size (its size_ratio is used)
 *  \return the provisional guess: scale_to_mm = kProvisionalHeadRatio / size_ratio, estimated
 */
LengthUnitGuess
provisionalHeadScale (const LengthUnitGuess& guess);

/** \brief The scan's unit after a fit at \a tried's scale_to_mm found the head at similarity scale \a fitted_scale
 *  (model to scan): the head says the scan has scale_to_mm / fitted_scale mm per unit (the head taken at the
 *  model's size). A known unit (mm, cm, m, in) is preferred when its reading puts the head within \a min_scale to
 *  \a max_scale of the model (the fit's plausible sizes), the one closest to the estimate if two do; otherwise the
 *  estimate is the scale (estimated, not recognised). The reason gives the numbers.
 *  Throws InvalidInputError for a non-positive or non-finite scale or bounds.
 *  \param[in] tried the scale the fit ran at (its scale_to_mm) and the scan's size (size_ratio)
 *  \param[in] fitted_scale the fit's similarity scale at that scale
 *  \param[in] min_scale the smallest plausible head scale against the model (e.g. FitPlausibilitySettings's 0.75)
 *  \param[in] max_scale the largest (e.g. 1.33)
 *  \return the known unit, or the estimated factor
 */
LengthUnitGuess
unitFromHeadScale (const LengthUnitGuess& tried, double fitted_scale, double min_scale, double max_scale);

} // namespace morphreg

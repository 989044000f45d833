// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file scan_units.h
 *  \brief A scan brought to millimetres before a registration: its unit given or guessed from its size against the
 *  model's, and scans that are no head in any unit refused.
 */
#include <morphreg/common/length_unit.h>
#include <morphreg/model/model_radius.h>
#include <morphreg/model/morphable_model.h>
#include <morphreg/pipeline/scan_input.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace morphreg
{
/** \brief The unit of \a scan as convertScanToMillimetres finds it, without converting it.
 *  \param[in] scan the scan's points
 *  \param[in] units the scan's unit, or "auto"
 *  \param[in] model the model it will be registered to (mm)
 *  \param[in] scan_name the scan's name for messages
 *  \param[in] one_view whether the scan is one depth camera's view
 *  \return the unit, the size ratio and why */
LengthUnitGuess
scanUnit (const pcl::PointCloud<pcl::PointNormal>& scan, const std::string& units, const MorphableModel& model,
          const std::string& scan_name, bool one_view = false);

/** \brief Converts \a scan to mm in place. \a units is "mm", "cm", "m", "in", or "auto": guessed by guessLengthUnit
 *  against the RMS radius of \a model's mean, and an InvalidInputError naming \a scan_name when the scan is more than
 *  1e4 times or less than 1e-5 times the model's size (no head in any unit: a corrupt file or not a scan).
 *  \param[in,out] scan the scan's points (and normals, which keep their direction)
 *  \param[in] units the scan's unit, or "auto"
 *  \param[in] model the model it will be registered to (mm)
 *  \param[in] scan_name the scan's name for messages (its file)
 *  \param[in] one_view whether the scan is one depth camera's view (see guessLengthUnit); an organised \a scan is
 *  one in any case
 *  \return the unit used, the size ratio and why
 */
LengthUnitGuess
convertScanToMillimetres (pcl::PointCloud<pcl::PointNormal>& scan, const std::string& units,
                          const MorphableModel& model, const std::string& scan_name, bool one_view = false);

/** \brief The unit of a scan as read: the one its source fixes (a depth image holds mm), else \a units given or
 *  guessed as scanUnit does (a scan with a viewpoint is one sensor's view).
 *  \param[in] scan the scan as read
 *  \param[in] units the scan's unit, or "auto"
 *  \param[in] model the model it will be registered to (mm)
 *  \return the unit, the size ratio and why */
LengthUnitGuess
scanInputUnit (const ScanInput& scan, const std::string& units, const MorphableModel& model);

/** \brief A copy of \a scan with its points and viewpoint times \a factor (normals keep their direction).
 *  \param[in] scan the scan
 *  \param[in] factor the scale, e.g. LengthUnitGuess::scale_to_mm
 *  \return the scaled copy */
ScanInput
scaledScan (const ScanInput& scan, double factor);

/** \brief What a front end says of a scan that was not in mm: "units: the scan's unit is m (why); rescaled to mm".
 *  \param[in] unit the scan's unit
 *  \return the sentence, or empty for a scan in mm */
std::string
unitConversionMessage (const LengthUnitGuess& unit);

} // namespace morphreg

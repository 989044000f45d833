// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file scan_units.h
 *  \brief A scan brought to millimetres before a registration: its unit given or guessed from its size against the
 *  model's, and scans that are no head in any unit refused.
 */
#include <morphreg/common/length_unit.h>
#include <morphreg/model/model_radius.h>
#include <morphreg/model/morphable_model.h>

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

} // namespace morphreg

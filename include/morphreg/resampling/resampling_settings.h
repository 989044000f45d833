// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file resampling_settings.h
 *  \brief The settings of ScanResampler by their command-line names (`morphreg resample --ray-distance ...`), with
 *  their one table of help texts and ranges, which the command line, the Python module and ScanResampler's setters
 *  read.
 */
#include <morphreg/common/setting_options.h>

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <vector>

namespace morphreg
{
/** \brief ScanResampler's settings; the defaults are the command line's and the resampler's. */
struct ResamplingSettings
{
  double ray_distance = 5.0;      ///< farthest a vertex moves along its normal onto the scan (mm)
  double normal_agreement = 60.0; ///< largest angle between a vertex normal and the scan's at the hit (degrees)
  int ring_width = 3;             ///< rings of observed vertices around a hole that its fill interpolates
  double max_hole_fraction = 0.5; ///< largest share of the reference's surface one hole may cover
  double fill_smoothing = 1.0;    ///< thin plate spline smoothing of the fills (mm)
  int passes = 3;                 ///< resampling passes
  int neighbours = 24;            ///< scan points a point cloud's local plane is weighted over
  double max_jump = 1.0;          ///< largest displacement difference from the neighbours' median (mm)
};

/** \brief One setting of ResamplingSettings as users set it. */
using ResamplingOption = SettingOption<ResamplingSettings>;

/** \brief Every user setting of a resampling.
 *  \return the table, in the order --help lists it */
const std::vector<ResamplingOption>&
resamplingOptions ();

/** \brief Throws InvalidInputError naming the first setting ("resampling setting NAME") outside its range.
 *  \param[in] settings the settings to check
 */
void
requireValidSettings (const ResamplingSettings& settings);

/** \brief The settings as the JSON object of resampling reports (keys with their units, e.g. "ray_distance_mm").
 *  \param[in] settings the settings
 *  \return the JSON object
 */
nlohmann::json
toJson (const ResamplingSettings& settings);

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file resampling_report.h
 *  \brief A resampling's statistics as the JSON object of reports (`morphreg resample`, morphreg.resample).
 */
#include <morphreg/resampling/scan_resampler.h>

#include <nlohmann/json_fwd.hpp>

namespace morphreg
{
/** \brief \a statistics as JSON: vertices observed and filled, coverage, area shares, folds, the median
 *  displacement, each hole (vertices, area_mm2, ring_vertices, max_fill_mm, folded_triangles) and the timings.
 *  \param[in] statistics a resampling's statistics
 *  \return the JSON object
 */
nlohmann::json
toJson (const ResamplingStatistics& statistics);

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file fit_resampling.h
 *  \brief A registered scan resampled into its fit's topology (the step after ScanRegistration of `morphreg
 *  resample` and `build-model --from-scans`): skipped for a fit that failed its checks, refused naming the scan when
 *  the resampler cannot use it, and reported.
 */
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/resampling/resampling_settings.h>
#include <morphreg/resampling/scan_resampler.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace morphreg
{
/** \brief The outcome of resampleFit. */
struct FitResampling
{
  std::optional<ResamplingResult> result; ///< the resampled mesh; none when the fit failed its checks
  /** "status" ("ok" or "skipped" with its "reason"), the statistics (resampling_report.h), "settings" and
   *  "timings_s" with the "total" time. */
  nlohmann::json report;
};

/** \brief Resamples \a scan into the topology of \a fitted with \a settings, unless \a fit_passed is false (the fit
 *  failed its checks: skipped, the report says why). Throws InvalidInputError naming \a scan_name when the resampler
 *  refuses the scan (no overlap, another unit, too large a hole).
 *  \param[in] scan the scan in mm, in the fit's frame (ScanRegistrationOutcome::scan)
 *  \param[in] scan_name the scan's name for messages
 *  \param[in] fitted the fitted mesh (ScanRegistrationOutcome::fittedMesh)
 *  \param[in] fit_passed whether the fit passed its checks
 *  \param[in] settings the resampling settings
 *  \return the resampled mesh and the report
 */
FitResampling
resampleFit (const pcl::PointCloud<pcl::PointNormal>& scan, const std::string& scan_name, const TriangleMesh& fitted,
             bool fit_passed, const ResamplingSettings& settings);

} // namespace morphreg

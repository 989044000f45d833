// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file fit_resampling.h
 *  \brief A registered scan resampled into its fit's topology (the step after ScanRegistration of `morphreg
 *  resample` and `build-model --from-scans`): skipped for a fit that failed its checks, refused naming the scan when
 *  the resampler cannot use it, and reported; writeResampledFit() writes the mesh and adds it to the fit's report.
 */
#include <morphreg/common/length_unit.h>
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/model/morphable_model.h>
#include <morphreg/resampling/resampling_settings.h>
#include <morphreg/resampling/scan_resampler.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <nlohmann/json.hpp>

#include <optional>
#include <ostream>
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

/** \brief The file writeResampledFit() writes the resampled mesh to, and its vertex colours. */
struct ResampledMeshFile
{
  std::string path;              ///< the mesh file (PLY)
  std::string colours = "state"; ///< "scan" or "auto" (the scan's, see scanColoursAt()), else "state"
};

/** \brief resampleFit() of a registration whose report is \a report (its "checks" "passed" decides whether to
 *  resample, its "scan" "scale_to_mm" scales the scan's colours), the mesh written to \a file with vertex colours:
 *  the scan's as scanColoursAt() gives them, else grey observed and orange filled vertices. Adds "resampling",
 *  "resampled_mesh" (the file, null when skipped) and "resampled_mesh_colours" ("scan" or "state") to \a report.
 *  Throws as resampleFit(), InvalidInputError for scan colours asked of a scan without them, and IoError naming a
 *  file that cannot be written.
 *  \param[in] scan the scan in mm, in the fit's frame
 *  \param[in] scan_file the scan's file (its colours, and its name for messages)
 *  \param[in] fitted the fitted mesh
 *  \param[in] settings the resampling settings
 *  \param[in] file where to write the mesh and how to colour it
 *  \param[in,out] report the fit's report
 *  \param[out] warnings where scan colours that cannot be read are said ("auto")
 *  \return the resampled mesh; none when the fit failed its checks
 */
std::optional<ResamplingResult>
writeResampledFit (const pcl::PointCloud<pcl::PointNormal>& scan, const std::string& scan_file,
                   const TriangleMesh& fitted, const ResamplingSettings& settings, const ResampledMeshFile& file,
                   nlohmann::json& report, std::ostream& warnings);

/** \brief The files of a resampling whose reference is the model's mean warped onto landmarks marked on the scan. */
struct LandmarkResamplingFiles
{
  std::string scan;            ///< the scan file, or a depth image (with intrinsics)
  std::string intrinsics;      ///< the depth image's camera (JSON), or empty for a scan file
  std::string landmarks;       ///< the landmarks marked on the scan (mm, as every landmark file)
  std::string reference;       ///< the warped mean head to write (the reference, in the scan's frame, mm)
  ResampledMeshFile resampled; ///< the resampled mesh to write
};

/** \brief What resampleFromLandmarks did. */
struct LandmarkResampling
{
  std::optional<ResamplingResult> result; ///< the resampled mesh
  LengthUnitGuess unit;                   ///< the scan's unit, given or guessed
  /** "status", "checks", "units", "scan" (file, points, unit), "reference" (method, landmarks, mesh) and the
   *  resampling's entries (writeResampledFit). */
  nlohmann::json report;
};

/** \brief The scan resampled without a registration (METHOD section 5): read (readScanOrDepthImage) and brought to mm
 *  (\a units given or guessed, scanInputUnit), the model's mean warped by a thin plate spline onto the landmarks
 *  marked on it (landmarkReference) as the reference, which is written, then resampled into it (writeResampledFit).
 *  InvalidInputError when there are no landmarks, or they lie off the scan.
 *  \param[in] model the model (its mean head and landmarks)
 *  \param[in] files the inputs and outputs
 *  \param[in] units the scan's unit, or "auto"
 *  \param[in] settings the resampling's settings
 *  \param[out] warnings where the resampling's warnings go
 *  \return the resampling, the unit and the report */
LandmarkResampling
resampleFromLandmarks (const MorphableModel& model, const LandmarkResamplingFiles& files, const std::string& units,
                       const ResamplingSettings& settings, std::ostream& warnings);

} // namespace morphreg

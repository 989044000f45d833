// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/synthetic/scanner_options.h>

namespace morphreg
{
namespace synthetic
{
namespace
{
using P = ScanSimulator::Parameters;

/** The scanner: its rays, rows, sight and noise. */
std::vector<ScannerOption>
scannerGeometry ()
{
  return {
      {"angular_samples",
       "scanner rays per turn (at most 100000: a scan must fit in memory)",
       &P::angular_samples,
       8,
       ScanSimulator::kMaxAngularSamples,
       {}},
      {"row_spacing", "scanner row spacing (mm)", &P::row_spacing, ScanSimulator::kMinRowSpacing, 1000.0, {}},
      {"max_incidence_deg",
       "surfaces seen more obliquely than this (degrees) by the laser or camera are lost",
       &P::max_incidence_deg,
       kAboveZeroSetting,
       89.9,
       {}},
      {"camera_elevation_deg",
       "the triangulating camera looks down at the laser plane from this angle (degrees)",
       &P::camera_elevation_deg,
       0.0,
       89.9,
       {}},
      {"noise", "scanner range noise sigma (mm)", &P::noise_sigma, 0.0, 100.0, {}},
      {"outliers", "fraction of outlier points", &P::outlier_fraction, 0.0, 0.5, {}},
      {"range_mesh", "also write the triangulated range image", &P::range_mesh, 0, 0, {}},
      {"max_edge_length",
       "range-image neighbours farther apart than this (mm) are not connected",
       &P::max_edge_length,
       kAboveZeroSetting,
       kUnboundedSetting,
       {}},
  };
}

/** The random pose and scale of the head in the scan. */
std::vector<ScannerOption>
scannerPose ()
{
  return {
      {"max_rotation_deg",
       "the head's random rotation is at most this (degrees, about a random axis)",
       &P::max_rotation_deg,
       0.0,
       180.0,
       {}},
      {"scale_deviation",
       "the scan's random scale lies in [1 - D, 1 + D] (0: the scanner measures true size, as when building models "
       "from the scans)",
       &P::max_scale_deviation,
       0.0,
       0.5,
       {}},
      {"max_translation",
       "the head's random translation is at most this (mm)",
       &P::max_translation,
       0.0,
       kUnboundedSetting,
       {}},
  };
}

} // namespace

const std::vector<ScannerOption>&
scannerOptions ()
{
  static const std::vector<ScannerOption> options = joinedOptions ({scannerGeometry (), scannerPose ()});
  return options;
}

void
requireValidScannerParameters (const ScanSimulator::Parameters& parameters)
{
  requireValidOptions (scannerOptions (), parameters, "scanner setting");
}
} // namespace synthetic
} // namespace morphreg

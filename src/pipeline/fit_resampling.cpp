// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/pipeline/fit_resampling.h>
#include <morphreg/resampling/resampling_report.h>

#include <chrono>

namespace morphreg
{
FitResampling
resampleFit (const pcl::PointCloud<pcl::PointNormal>& scan, const std::string& scan_name, const TriangleMesh& fitted,
             bool fit_passed, const ResamplingSettings& settings)
{
  if (!fit_passed)
    return {std::nullopt, {{"status", "skipped"}, {"reason", "the fit failed its checks"}}};
  const auto start = std::chrono::steady_clock::now ();
  ScanResampler resampler;
  resampler.setSettings (settings);
  resampler.setInputReference (fitted);
  FitResampling resampled;
  try {
    resampler.setInputScan (scan);
    resampled.result = resampler.resample ();
  }
  catch (const InvalidInputError& e) {
    throw InvalidInputError (scan_name + ": cannot be resampled into the model's topology: " + e.what ());
  }
  resampled.report = toJson (resampled.result->statistics);
  resampled.report["status"] = "ok";
  resampled.report["settings"] = toJson (settings);
  resampled.report["timings_s"]["total"] =
      std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  return resampled;
}

} // namespace morphreg

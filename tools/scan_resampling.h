// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The resampling options of `resample` and `build-model --from-scans` (the library's writeResampledFit, in
// morphreg/pipeline/fit_resampling.h, resamples and writes the mesh).
#include <morphreg/resampling/resampling_settings.h>

#include <CLI/CLI.hpp>

#include <string>

namespace morphreg
{
namespace tools
{
/** The ScanResampler settings of the command line (the library's, by the same names) and the mesh's colours. */
struct ResamplingOptions : ResamplingSettings
{
  std::string colours = "state"; ///< the resampled mesh's vertex colours: auto, scan or state (observed / filled)
};

/** Adds the options of resamplingOptions()'s table (--ray-distance, --passes, ...) to \a command. */
void
addResamplingOptions (CLI::App* command, ResamplingOptions& options);

} // namespace tools
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The scanner settings shared by every command that simulates scans.
#include "table_options.h"

#include <morphreg/synthetic/scanner_options.h>

#include <CLI/CLI.hpp>

namespace morphreg
{
namespace tools
{
/** Adds the scanner's settings from the library's table (synthetic/scanner_options.h: --noise, --outliers,
 *  --angular-samples, --row-spacing, --scale-deviation, --range-mesh, ...) to \a command. */
inline void
addScannerOptions (CLI::App* command, synthetic::ScanSimulator::Parameters& parameters)
{
  for (const synthetic::ScannerOption& option : synthetic::scannerOptions ())
    addTableOption<synthetic::ScanSimulator::Parameters> (command, parameters, option);
}
} // namespace tools
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The scanner settings shared by every command that simulates scans.
#include "option_checks.h"

#include <morphreg/synthetic/scan_simulator.h>

#include <CLI/CLI.hpp>

namespace morphreg
{
namespace tools
{
/** Adds --noise, --outliers, --angular-samples, --row-spacing, --scale-deviation and --range-mesh to \a command. */
inline void
addScannerOptions (CLI::App* command, synthetic::ScanSimulator::Parameters& parameters)
{
  using synthetic::ScanSimulator;
  command->add_option ("--noise", parameters.noise_sigma, "scanner range noise sigma (mm)")
      ->check (inRange (0.0, 100.0))
      ->capture_default_str ();
  command->add_option ("--outliers", parameters.outlier_fraction, "fraction of outlier points")
      ->check (inRange (0.0, 0.5))
      ->capture_default_str ();
  command->add_option ("--angular-samples", parameters.angular_samples, "scanner rays per turn")
      ->check (inRange (8, ScanSimulator::kMaxAngularSamples))
      ->capture_default_str ();
  command->add_option ("--row-spacing", parameters.row_spacing, "scanner row spacing (mm)")
      ->check (inRange (ScanSimulator::kMinRowSpacing, 1000.0))
      ->capture_default_str ();
  command
      ->add_option ("--scale-deviation", parameters.max_scale_deviation,
                    "the scan's random scale lies in [1 - D, 1 + D] (0: the scanner measures true size, as when "
                    "building models from the scans)")
      ->check (inRange (0.0, 0.5))
      ->capture_default_str ();
  command->add_flag ("--range-mesh", parameters.range_mesh, "also write the triangulated range image");
}
} // namespace tools
} // namespace morphreg

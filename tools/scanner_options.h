#pragma once
// The scanner settings shared by every command that simulates scans.
#include <morphreg/synthetic/scan_simulator.h>

#include <CLI/CLI.hpp>

namespace morphreg
{
namespace tools
{
/** Adds --noise, --outliers, --angular-samples, --row-spacing and --range-mesh to \a command. */
inline void
addScannerOptions (CLI::App* command, synthetic::ScanSimulator::Parameters& parameters)
{
  command->add_option ("--noise", parameters.noise_sigma, "scanner range noise sigma (mm)")->capture_default_str ();
  command->add_option ("--outliers", parameters.outlier_fraction, "fraction of outlier points")->capture_default_str ();
  command->add_option ("--angular-samples", parameters.angular_samples, "scanner rays per turn")
      ->capture_default_str ();
  command->add_option ("--row-spacing", parameters.row_spacing, "scanner row spacing (mm)")->capture_default_str ();
  command->add_flag ("--range-mesh", parameters.range_mesh, "also write the triangulated range image");
}
} // namespace tools
} // namespace morphreg

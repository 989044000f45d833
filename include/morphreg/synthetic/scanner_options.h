// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file scanner_options.h
 *  \brief The one table of the simulated scanner's settings (ScanSimulator::Parameters): name, help text and range.
 *  The command line (`synth --noise`), the Python keywords (`ScanSimulator(noise=...)`) and the scanner's own check
 *  all read it.
 */
#include <morphreg/common/setting_options.h>
#include <morphreg/synthetic/scan_simulator.h>

#include <vector>

namespace morphreg
{
namespace synthetic
{
/** \brief One setting of the scanner as users set it. */
using ScannerOption = SettingOption<ScanSimulator::Parameters>;

/** \brief Every setting of the scanner.
 *  \return the table, in the order --help lists it */
const std::vector<ScannerOption>&
scannerOptions ();

/** \brief Throws InvalidInputError naming the first setting of \a parameters ("scanner setting NAME") outside its
 *  range.
 *  \param[in] parameters the settings */
void
requireValidScannerParameters (const ScanSimulator::Parameters& parameters);
} // namespace synthetic
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file convergence_plot.h
 *  \brief A PNG plot of a registration's convergence: the RMS distance to the scan at each iteration, the similarity
 *  and the shape stages in their own colours (VTK's charts, rendered offscreen).
 */
#include <morphreg/registration/registration_report.h>

#include <string>

namespace morphreg
{
/** \brief Writes the RMS scan-to-model distance (mm, the square root of each iteration's mean squared error) of
 *  every iteration of \a report as a line chart, \a width x \a height pixels, titled \a title. Debian's VTK renders
 *  through X even offscreen: run headless programs under `xvfb-run -a`. Throws InvalidInputError for a report
 *  without iterations or a size under 160 x 120, Error without an X display, IoError if the file cannot be written.
 *  \param[in] png_path the PNG file
 *  \param[in] report a finished registration's report (its history)
 *  \param[in] title the chart's title, e.g. the scan's name
 *  \param[in] width the image width in pixels
 *  \param[in] height the image height in pixels
 */
void
saveConvergencePlot (const std::string& png_path, const IcpReport& report, const std::string& title = "",
                     int width = 800, int height = 500);
} // namespace morphreg

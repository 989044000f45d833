// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file x_display.h
 *  \brief Debian's VTK renders through X even offscreen: a program that renders checks for a display before long work
 *  whose pictures would then fail.
 */
#include <string>

namespace morphreg
{
/** \brief Throws morphreg::Error naming \a who when $DISPLAY is unset (run headless programs under `xvfb-run -a`).
 *  \param[in] who what is about to render, for the message */
void
requireXDisplay (const std::string& who);
} // namespace morphreg

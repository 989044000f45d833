// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The visualisation component's PNG output of a VTK render window, and its check for an X display.
#include <string>

class vtkRenderWindow;

namespace morphreg
{
namespace detail
{
/** Renders \a window and writes it as a PNG, atomically; IoError naming \a png_path if it cannot be written whole. */
void
writeWindowPng (vtkRenderWindow& window, const std::string& png_path);
} // namespace detail
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include "window_png.h"

#include <morphreg/visualization/x_display.h>

#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>

#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkSmartPointer.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>

namespace morphreg
{
namespace detail
{
namespace
{
/** Whether \a path ends with a PNG's closing IEND chunk: a PNG cut short by a full disk does not. */
bool
endsWithPngEnd (const std::string& path)
{
  static const char kEnd[] = {'I', 'E', 'N', 'D', '\xAE', '\x42', '\x60', '\x82'};
  std::ifstream file (path, std::ios::binary | std::ios::ate);
  if (!file || file.tellg () < static_cast<std::streamoff> (sizeof (kEnd)))
    return false;
  char tail[sizeof (kEnd)];
  file.seekg (-static_cast<std::streamoff> (sizeof (kEnd)), std::ios::end);
  file.read (tail, sizeof (tail));
  return file && std::equal (tail, tail + sizeof (tail), kEnd);
}
} // namespace

void
writeWindowPng (vtkRenderWindow& window, const std::string& png_path)
{
  window.Render ();
  auto capture = vtkSmartPointer<vtkWindowToImageFilter>::New ();
  capture->SetInput (&window);
  capture->SetInputBufferTypeToRGB ();
  capture->ReadFrontBufferOff ();
  capture->Update ();
  writeAtomically (png_path, [&] (const std::string& partial) {
    auto writer = vtkSmartPointer<vtkPNGWriter>::New ();
    writer->SetFileName (partial.c_str ());
    writer->SetInputConnection (capture->GetOutputPort ());
    writer->Write ();
    if (writer->GetErrorCode () != 0 || !endsWithPngEnd (partial))
      throw IoError (png_path + ": cannot write the image (disk full, or no permission?)");
  });
}
} // namespace detail

void
requireXDisplay (const std::string& who)
{
  const char* x_display = std::getenv ("DISPLAY");
  if (x_display == nullptr || *x_display == '\0')
    throw Error (who + ": no X display ($DISPLAY is unset); VTK renders through X even offscreen, so run headless "
                       "programs under `xvfb-run -a`");
}
} // namespace morphreg

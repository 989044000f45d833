// SPDX-License-Identifier: BSD-3-Clause
// The morphreg Python module (_morphreg; the package morphreg re-exports it): numpy in and out, the library's
// errors as Python exceptions.
#include "bindings.h"

#include <pcl/console/print.h>

PYBIND11_MODULE (_morphreg, m)
{
  m.doc () = "Morphable-model registration and thin plate spline warping (morphreg, C++ on PCL). Units are mm.";
  m.attr ("__version__") = MORPHREG_VERSION;
  // PCL's readers print warnings for every cloud without normals ("Failed to find match for field"); morphreg's
  // own errors are the exceptions, so only PCL's errors reach the console, as the command line's default.
  pcl::console::setVerbosityLevel (pcl::console::L_ERROR);
  using namespace morphreg::python;
  bindErrors (m);
  bindIo (m);
  bindModel (m);
  bindRegistration (m);
  bindBatch (m);
  bindResampling (m);
  bindWarp (m);
  bindSynthetic (m);
  bindPhoto (m);
}

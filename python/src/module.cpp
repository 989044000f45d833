// The morphreg Python module (_morphreg; the package morphreg re-exports it): numpy in and out, the library's
// errors as Python exceptions.
#include "bindings.h"

PYBIND11_MODULE (_morphreg, m)
{
  m.doc () = "Morphable-model registration and thin plate spline warping (morphreg, C++ on PCL). Units are mm.";
  m.attr ("__version__") = MORPHREG_VERSION;
  using namespace morphreg::python;
  bindErrors (m);
  bindIo (m);
  bindModel (m);
  bindRegistration (m);
  bindWarp (m);
  bindSynthetic (m);
  bindPhoto (m);
}

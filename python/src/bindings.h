// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The parts of the morphreg Python module, one file each; module.cpp calls them in order.
#include <pybind11/pybind11.h>

namespace morphreg
{
namespace python
{
namespace py = pybind11;

void
bindErrors (py::module_& m); ///< errors.cpp: the morphreg.Error hierarchy
void
bindIo (py::module_& m); ///< io.cpp: mesh, cloud and landmark files
void
bindModel (py::module_& m); ///< model.cpp: morphreg.Model
void
bindRegistration (py::module_& m); ///< registration.cpp: morphreg.register
void
bindBatch (py::module_& m); ///< batch.cpp: morphreg.register_study
void
bindResampling (py::module_& m); ///< resampling.cpp: morphreg.resample
void
bindWarp (py::module_& m); ///< warp.cpp: ThinPlateSpline, SegmentedWarp
void
bindSynthetic (py::module_& m); ///< synthetic.cpp: HeadGenerator, ScanSimulator
void
bindPhoto (py::module_& m); ///< photo.cpp: fit_photos

} // namespace python
} // namespace morphreg

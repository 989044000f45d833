// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Model arguments shared by the parts of the module.
#include <morphreg/model/morphable_model.h>
#include <morphreg/model/region_segmentation.h>

#include <pybind11/pybind11.h>

#include <vector>

namespace morphreg
{
namespace python
{
namespace py = pybind11;

/** Region labels given as (names, labels): a list of names and each vertex's index into it. */
RegionLabels
regionLabels (const py::handle& regions);

/** Component counts given as an int (the same for every region) or a list of ints (one per region); None: none
 *  given (empty: the callee's default). */
std::vector<int>
componentCounts (const py::handle& components);

/** The components a Python caller selects: None (all), an int (the first k of every region) or a list of ints (the
 *  first k_j of region j), as the command line's --components. */
ComponentSelection
componentSelection (const MorphableModel& model, const py::handle& components);

} // namespace python
} // namespace morphreg

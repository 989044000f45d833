// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Reports (nlohmann JSON) as Python dicts and lists.
#include <nlohmann/json.hpp>

#include <pybind11/pybind11.h>

namespace morphreg
{
namespace python
{
namespace py = pybind11;

/** \a json as Python objects (dict, list, str, float, int, bool, None), through the json module: numbers keep
 *  every digit (the dump round-trips doubles). */
inline py::object
toPython (const nlohmann::json& json)
{
  return py::module_::import ("json").attr ("loads") (json.dump ());
}

} // namespace python
} // namespace morphreg

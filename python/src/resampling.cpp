// SPDX-License-Identifier: BSD-3-Clause
// morphreg.resample: a scan's points brought into a reference mesh's topology by ScanResampler (the reference a fit,
// e.g. morphreg.register's vertices and faces), its settings the keywords of resampling_settings.h's table, with the
// GIL released while it runs.
#include "bindings.h"
#include "json_objects.h"
#include "keyword_settings.h"
#include "numpy_arrays.h"

#include <morphreg/resampling/resampling_report.h>
#include <morphreg/resampling/resampling_settings.h>
#include <morphreg/resampling/scan_resampler.h>

#include <pybind11/numpy.h>

#include <nlohmann/json.hpp>

#include <string>

namespace morphreg
{
namespace python
{
namespace
{
/** What morphreg.resample returns. */
struct ResampledMesh
{
  ResamplingResult result;
  nlohmann::json report;
};

ResampledMesh
resampleScan (const py::handle& vertices, const py::handle& faces, const py::handle& points, const py::handle& normals,
              const py::kwargs& keywords)
{
  ScanResampler resampler;
  resampler.setSettings (settingsFromKeywords (keywords, resamplingOptions (), "resample"));
  resampler.setInputReference (toMesh (vertices, faces, "reference"));
  const auto cloud = toCloud (points, normals, "points");
  ResampledMesh resampled;
  {
    py::gil_scoped_release released;
    resampler.setInputScan (*cloud);
    resampled.result = resampler.resample ();
  }
  resampled.report = toJson (resampled.result.statistics);
  resampled.report["settings"] = toJson (resampler.getSettings ());
  return resampled;
}

/** Per vertex: whether it was observed on the scan (else filled). */
py::array_t<bool>
observedVertices (const ResampledMesh& resampled)
{
  const auto& state = resampled.result.state;
  py::array_t<bool> observed (static_cast<py::ssize_t> (state.size ()));
  auto flags = observed.mutable_unchecked<1> ();
  for (std::size_t v = 0; v < state.size (); ++v)
    flags (static_cast<py::ssize_t> (v)) = state[v] == ResampledVertex::observed;
  return observed;
}

std::string
resampleDoc ()
{
  return keywordDoc ("Moves each vertex of a reference mesh ((N, 3) vertices, (M, 3) faces; a fit close to the scan,\n"
                     "e.g. morphreg.register's) along its normal onto the scan's points ((K, 3), with normals if\n"
                     "known), and fills the vertices that see no scan from their observed neighbours, as\n"
                     "`morphreg resample` does. Returns a ResampledMesh (mm). The keyword settings are resample's\n"
                     "options (--ray-distance is ray_distance):\n",
                     resamplingOptions ());
}
} // namespace

void
bindResampling (py::module_& m)
{
  py::class_<ResampledMesh> (m, "ResampledMesh", "The outcome of morphreg.resample (mm, the reference's topology).")
      .def_property_readonly (
          "vertices", [] (const ResampledMesh& r) { return toArray (Eigen::Matrix3Xd (r.result.mesh.vertices)); },
          "The resampled vertices, (N, 3): on the scan where observed, filled elsewhere.")
      .def_property_readonly (
          "faces", [] (const ResampledMesh& r) { return toArray (TriangleMesh::Triangles (r.result.mesh.triangles)); })
      .def_property_readonly ("observed", &observedVertices, "Per vertex, (N,): True where the scan was met.")
      .def_property_readonly (
          "displacement", [] (const ResampledMesh& r) { return toArray (Eigen::Matrix3Xd (r.result.displacement)); },
          "Per vertex, (N, 3): resampled minus reference position.")
      .def_property_readonly (
          "report", [] (const ResampledMesh& r) { return toPython (r.report); },
          "Coverage, holes, folds and settings as a dict, as `morphreg resample` reports them.");
  m.def ("resample", &resampleScan, py::arg ("vertices"), py::arg ("faces"), py::arg ("points"),
         py::arg ("normals") = py::none (), resampleDoc ().c_str ());
  m.attr ("_resampling_options") = keywordTable (resamplingOptions ());
}

} // namespace python
} // namespace morphreg

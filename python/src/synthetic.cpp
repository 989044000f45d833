// SPDX-License-Identifier: BSD-3-Clause
// The built-in synthetic data: morphreg.HeadGenerator (heads with known parameters, landmarks and regions) and
// morphreg.ScanSimulator (laser scans of them with a known pose and per-point ground truth).
#include "bindings.h"
#include "keyword_settings.h"
#include "numpy_arrays.h"

#include <morphreg/common/cloud_matrix.h>
#include <morphreg/common/error.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/scan_simulator.h>
#include <morphreg/synthetic/scanner_options.h>

#include <pybind11/stl.h>

namespace morphreg
{
namespace python
{
namespace
{
using synthetic::HeadGenerator;
using synthetic::HeadParameters;
using synthetic::ScanSimulator;
using synthetic::SimulatedScan;
using synthetic::SyntheticHead;

py::dict
parametersDict (const HeadParameters& parameters)
{
  py::dict dict;
  for (const HeadParameters::Range& range : HeadParameters::ranges ())
    dict[py::str (range.name)] = parameters.*range.member;
  return dict;
}

/** Parameters from a dict name -> mm: the population mean, overridden by the given ones (unknown names refused). */
HeadParameters
parametersFrom (const py::dict& values)
{
  HeadParameters parameters;
  for (const auto& item : values) {
    const auto name = py::str (item.first).cast<std::string> ();
    const auto& ranges = HeadParameters::ranges ();
    const auto range = std::find_if (ranges.begin (), ranges.end (), [&] (const auto& r) { return r.name == name; });
    if (range == ranges.end ())
      throw InvalidInputError ("parameters: no head parameter \"" + name + "\"");
    parameters.*(range->member) = item.second.cast<double> ();
  }
  parameters.validate ();
  return parameters;
}

void
bindHead (py::module_& m)
{
  py::class_<SyntheticHead> (m, "SyntheticHead", "A generated head (mm) and the parameters it was made from.")
      .def_property_readonly ("vertices",
                              [] (const SyntheticHead& h) { return toArray (Eigen::Matrix3Xd (h.mesh.vertices)); })
      .def_property_readonly (
          "faces", [] (const SyntheticHead& h) { return toArray (TriangleMesh::Triangles (h.mesh.triangles)); })
      .def_property_readonly (
          "parameters", [] (const SyntheticHead& h) { return parametersDict (h.parameters); },
          "The 20 anthropometric parameters (mm) by name.");
}

void
bindHeadGenerator (py::module_& m)
{
  py::class_<HeadGenerator, HeadGenerator::Ptr> (m, "HeadGenerator",
                                                 "Deterministic human-like heads in one topology, with landmarks, a "
                                                 "profile line and region labels.")
      .def (py::init<int> (), py::arg ("resolution") = 40, "resolution: vertices per half-ring step (20 to 44).")
      .def ("sample", &HeadGenerator::sample, py::arg ("seed"), "The head drawn with this seed.")
      .def (
          "generate",
          [] (const HeadGenerator& g, const py::dict& values) {
            const HeadParameters parameters = parametersFrom (values);
            return SyntheticHead{g.generate (parameters), parameters};
          },
          py::arg ("parameters"), "The head of these parameters (dict name -> mm; missing ones at the mean).")
      .def ("population", &HeadGenerator::population, py::arg ("count"), py::arg ("seed"),
            "count heads, head i drawn with seed + i.")
      .def_property_readonly ("num_vertices", &HeadGenerator::numVertices)
      .def_property_readonly (
          "faces", [] (const HeadGenerator& g) { return toArray (TriangleMesh::Triangles (g.triangles ())); })
      .def_property_readonly ("landmarks", &HeadGenerator::landmarks, "Landmark id -> vertex index.")
      .def_property_readonly ("profile_line", &HeadGenerator::profileLine)
      .def_property_readonly (
          "region_labels", [] (const HeadGenerator& g) { return g.regions ().labels; },
          "The region index of each vertex (into the names of regions).")
      .def_property_readonly (
          "regions", [] (const HeadGenerator& g) { return py::make_tuple (g.regions ().names, g.regions ().labels); },
          "(names, labels) of the seven regions, as Model.build takes them.")
      .def_property_readonly ("parameter_names", [] (const HeadGenerator&) {
        std::vector<std::string> names;
        for (const HeadParameters::Range& range : HeadParameters::ranges ())
          names.push_back (range.name);
        return names;
      });
}

py::object
rangeMeshFaces (const SimulatedScan& scan)
{
  if (scan.range_mesh.polygons.empty ())
    return py::none ();
  return toArray (fromPolygonMesh (scan.range_mesh).triangles);
}

void
bindScan (py::module_& m)
{
  py::class_<SimulatedScan> (m, "SimulatedScan", "A simulated laser scan (mm, the scanner's frame) and its truth.")
      .def_property_readonly ("points", [] (const SimulatedScan& s) { return toArray (pointsOf (*s.cloud)); })
      .def_property_readonly ("normals", [] (const SimulatedScan& s) { return toArray (normalsOf (*s.cloud)); })
      .def_property_readonly ("faces", &rangeMeshFaces, "The range image's triangles, or None unless range_mesh.")
      .def_property_readonly (
          "head_to_scan", [] (const SimulatedScan& s) { return toArray (Eigen::MatrixXd (s.head_to_scan.matrix ())); },
          "The similarity from head to scan coordinates, (4, 4).")
      .def_property_readonly ("scale", [] (const SimulatedScan& s) { return s.scale; })
      .def_property_readonly (
          "source_triangle", [] (const SimulatedScan& s) { return s.source_triangle; },
          "Per point, the head triangle it lies on (-1: outlier).")
      .def_property_readonly ("barycentric",
                              [] (const SimulatedScan& s) { return toArray (Eigen::Matrix3Xd (s.barycentric)); })
      .def_property_readonly ("num_outliers", [] (const SimulatedScan& s) { return s.num_outliers; });
}

void
bindScanSimulator (py::module_& m)
{
  py::class_<ScanSimulator> (m, "ScanSimulator",
                             keywordDoc ("A cylindrical laser scanner; its keyword settings are synth's options:\n",
                                         synthetic::scannerOptions ())
                                 .c_str ())
      .def (py::init ([] (const py::kwargs& settings) {
        return ScanSimulator (settingsFromKeywords (settings, synthetic::scannerOptions (), "ScanSimulator"));
      }))
      .def_property_readonly (
          "settings",
          [] (const ScanSimulator& scanner) {
            return keywordValues (scanner.parameters (), synthetic::scannerOptions ());
          },
          "The settings by their names: name -> value.")
      .def (
          "scan",
          [] (const ScanSimulator& scanner, const py::handle& vertices, const py::handle& faces, std::uint64_t seed) {
            const TriangleMesh head = toMesh (vertices, faces, "head");
            py::gil_scoped_release released;
            return scanner.scan (head, seed);
          },
          py::arg ("vertices"), py::arg ("faces"), py::arg ("seed"), "Scans the head (mm) with a random pose (seed).");
}
} // namespace

void
bindSynthetic (py::module_& m)
{
  bindHead (m);
  bindHeadGenerator (m);
  bindScan (m);
  bindScanSimulator (m);
}

} // namespace python
} // namespace morphreg

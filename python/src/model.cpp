// SPDX-License-Identifier: BSD-3-Clause
// morphreg.Model: a multi-region PCA head model (statismo HDF5 files), its mean, regions, components, landmarks,
// instances and random samples as numpy arrays.
#include "bindings.h"
#include "json_objects.h"
#include "keyword_settings.h"
#include "numpy_arrays.h"
#include "python_model.h"

#include <morphreg/common/error.h>
#include <morphreg/io/model_description.h>
#include <morphreg/io/model_io.h>
#include <morphreg/model/coefficient_units.h>
#include <morphreg/model/model_builder.h>
#include <morphreg/model/model_builder_options.h>
#include <morphreg/pipeline/model_building.h>

#include <pybind11/stl.h>

#include <random>

namespace morphreg
{
namespace python
{
namespace
{
py::dict
regionDict (const ModelRegion& region)
{
  py::dict dict;
  dict["name"] = region.name;
  dict["vertices"] = py::array_t<int> (static_cast<py::ssize_t> (region.vertices.size ()), region.vertices.data ());
  dict["weights"] = toArray (Eigen::VectorXd (region.weights));
  dict["basis"] = toArray (Eigen::MatrixXd (region.basis));
  dict["variances"] = toArray (Eigen::VectorXd (region.variances));
  return dict;
}

py::list
regionList (const MorphableModel& model)
{
  py::list regions;
  for (const ModelRegion& region : model.regions ())
    regions.append (regionDict (region));
  return regions;
}

Eigen::VectorXd
coefficientsFor (const ComponentSelection& selection, const py::handle& coefficients)
{
  return toVector (coefficients, "coefficients (one per selected component)", selection.total ());
}

/** The shape of \a coefficients, in prior standard deviations or (\a in_mm) in mm. */
py::array
instance (const MorphableModel& model, const py::handle& coefficients, const py::handle& components, bool in_mm)
{
  const ComponentSelection selection = componentSelection (model, components);
  const Eigen::VectorXd given = coefficientsFor (selection, coefficients);
  return toArray (model.generate (in_mm ? given : coefficientsInMillimetres (model, given, selection), selection));
}

py::array
sample (const MorphableModel& model, std::uint64_t seed, const py::handle& components)
{
  const ComponentSelection selection = componentSelection (model, components);
  std::mt19937_64 rng (seed);
  return toArray (model.generate (model.sampleCoefficients (rng, selection), selection));
}

/** The least-squares coefficients of \a vertices, in prior standard deviations or (\a in_mm) in mm. */
py::array
project (const MorphableModel& model, const py::handle& vertices, const py::handle& components, bool in_mm)
{
  const PointsArgument shape = pointsArgument (vertices, "vertices");
  const ComponentSelection selection = componentSelection (model, components);
  const Eigen::VectorXd mm = model.project (Eigen::Matrix3Xd (shape.points), selection).coefficients;
  return toArray (in_mm ? mm : coefficientsInStandardDeviations (model, mm, selection));
}

/** A model from meshes in correspondence (a list of (N, 3) arrays sharing \a faces) by the library's ModelFromMeshes,
 *  as `morphreg build-model`; the keywords are its builder settings (model_builder_options.h). */
MorphableModel::Ptr
buildModel (const py::list& meshes, const py::handle& faces, const py::handle& regions,
            const LandmarkVertices& landmarks, const std::vector<int>& profile_line, const py::kwargs& keywords)
{
  ModelFromMeshesSettings settings;
  settings.builder = settingsFromKeywords (keywords, modelBuilderOptions (), "Model.build");
  std::vector<TriangleMesh> training;
  std::vector<std::string> names;
  for (std::size_t i = 0; i < meshes.size (); ++i) {
    names.push_back ("meshes[" + std::to_string (i) + "]");
    training.push_back (toMesh (meshes[i], faces, names.back ()));
  }
  const MeshAnnotations annotations{regions.is_none () ? std::nullopt
                                                       : std::optional<RegionLabels> (regionLabels (regions)),
                                    landmarks, profile_line};
  py::gil_scoped_release released;
  return ModelFromMeshes (settings).build (training, names, annotations).model;
}

std::vector<int>
regionComponentCounts (const MorphableModel& model)
{
  std::vector<int> counts;
  for (const ModelRegion& region : model.regions ())
    counts.push_back (static_cast<int> (region.basis.cols ()));
  return counts;
}
} // namespace

std::vector<int>
componentCounts (const py::handle& components)
{
  if (components.is_none ())
    return {};
  if (py::isinstance<py::int_> (components))
    return {components.cast<int> ()};
  if (py::isinstance<py::sequence> (components) && !py::isinstance<py::str> (components)) {
    std::vector<int> counts;
    for (const py::handle& count : py::reinterpret_borrow<py::sequence> (components)) {
      if (!py::isinstance<py::int_> (count))
        throw InvalidInputError ("components: " + std::string (py::repr (count)) + " is not an int");
      counts.push_back (count.cast<int> ());
    }
    return counts;
  }
  throw InvalidInputError ("components: expected an int (per region) or a list of ints (one per region), got " +
                           std::string (py::repr (components)));
}

RegionLabels
regionLabels (const py::handle& regions)
{
  if (!py::isinstance<py::tuple> (regions) || py::len (regions) != 2)
    throw InvalidInputError ("regions: expected (names, labels): a list of region names and each vertex's index");
  const auto pair = py::reinterpret_borrow<py::tuple> (regions);
  return {pair[0].cast<std::vector<std::string>> (), pair[1].cast<std::vector<int>> ()};
}

ComponentSelection
componentSelection (const MorphableModel& model, const py::handle& components)
{
  if (components.is_none ())
    return model.allComponents ();
  const std::vector<int> counts = componentCounts (components);
  return counts.size () == 1 ? model.firstComponents (counts.front ()) : model.firstComponents (counts);
}

namespace
{
/** Model's instances, samples and projections, with coefficients in prior standard deviations or in mm. */
void
bindShapes (py::class_<MorphableModel, MorphableModel::Ptr>& cls)
{
  cls.def (
         "standard_deviations",
         [] (const MorphableModel& model, const py::handle& components) {
           return toArray (Eigen::VectorXd (model.variances (componentSelection (model, components)).cwiseSqrt ()));
         },
         py::arg ("components") = py::none (),
         "The selected components' prior standard deviations (mm), stacked by region: coefficients_mm / these = "
         "coefficients.")
      .def (
          "instance",
          [] (const MorphableModel& model, const py::handle& coefficients, const py::handle& components) {
            return instance (model, coefficients, components, false);
          },
          py::arg ("coefficients"), py::arg ("components") = py::none (),
          "The shape of the coefficients in prior standard deviations (statismo's unit): (N, 3) vertices.")
      .def (
          "instance_mm",
          [] (const MorphableModel& model, const py::handle& coefficients, const py::handle& components) {
            return instance (model, coefficients, components, true);
          },
          py::arg ("coefficients_mm"), py::arg ("components") = py::none (),
          "The shape of coefficients given as lengths (mm along each selected component): (N, 3) vertices.")
      .def ("sample", &sample, py::arg ("seed") = 0, py::arg ("components") = py::none (),
            "A random shape, coefficients drawn from N(0, 1) standard deviations with the seed: (N, 3) vertices.")
      .def (
          "project",
          [] (const MorphableModel& model, const py::handle& vertices, const py::handle& components) {
            return project (model, vertices, components, false);
          },
          py::arg ("vertices"), py::arg ("components") = py::none (),
          "The least-squares coefficients of a shape in the model's frame and topology, in prior standard "
          "deviations.")
      .def (
          "project_mm",
          [] (const MorphableModel& model, const py::handle& vertices, const py::handle& components) {
            return project (model, vertices, components, true);
          },
          py::arg ("vertices"), py::arg ("components") = py::none (),
          "The least-squares coefficients of a shape as lengths (mm along each selected component).");
}
} // namespace

void
bindModel (py::module_& m)
{
  py::class_<MorphableModel, MorphableModel::Ptr> model (
      m, "Model",
      "A multi-region PCA shape model (mm), as `morphreg build-model` writes it; components: None (all), an int per "
      "region, or a list. Coefficients are in prior standard deviations (statismo's unit); the *_mm methods take "
      "and give lengths (mm along each component).");
  bindShapes (model);
  model.def_static ("load", &loadModel, py::arg ("path"), "Reads a model file (statismo HDF5, morphreg or BFM layout).")
      .def (
          "save", [] (const MorphableModel& model, const std::string& path) { saveModel (path, model); },
          py::arg ("path"), "Writes the model as statismo HDF5, atomically.")
      .def (
          "describe", [] (const MorphableModel& model) { return toPython (describeModel (model)); },
          "What the model holds, as `morphreg model-info --json` prints it: vertices, triangles, regions (name, "
          "vertices, components, variances_mm2), global_pca, landmarks, profile_line_vertices, metadata, units.")
      .def_property_readonly ("num_vertices", &MorphableModel::numVertices)
      .def_property_readonly ("num_regions", &MorphableModel::numRegions)
      .def_property_readonly ("component_counts", &regionComponentCounts, "Components per region.")
      .def_property_readonly (
          "mean",
          [] (py::object self) {
            const auto& model = self.cast<const MorphableModel&> ();
            return pointsView (model.mean ().data (), model.numVertices (), self);
          },
          "The mean shape, (N, 3) float64, read-only (a view of the model).")
      .def_property_readonly (
          "faces", [] (const MorphableModel& model) { return toArray (TriangleMesh::Triangles (model.triangles ())); },
          "The triangles, (T, 3) int32.")
      .def_property_readonly ("regions", &regionList,
                              "Per region a dict: name, vertices, weights (blending), basis (3B x P), variances.")
      .def_property_readonly ("landmarks", &MorphableModel::landmarks, "Landmark id -> vertex index.")
      .def_property_readonly ("profile_line", &MorphableModel::profileLine, "The mid-sagittal profile's vertices.")
      .def (
          "variances",
          [] (const MorphableModel& model, const py::handle& components) {
            return toArray (model.variances (componentSelection (model, components)));
          },
          py::arg ("components") = py::none (), "The selected components' variances (mm^2), stacked by region.")
      .def (
          "components",
          [] (const MorphableModel& model, const py::handle& components) {
            return toArray (Eigen::MatrixXd (model.shapeMatrix (componentSelection (model, components))));
          },
          py::arg ("components") = py::none (),
          "The selected components as the (3N, K) shape matrix (rows x, y, z per vertex; blended across regions).")
      .def_static ("build", &buildModel, py::arg ("meshes"), py::arg ("faces"), py::arg ("regions") = py::none (),
                   py::arg ("landmarks") = LandmarkVertices (), py::arg ("profile_line") = std::vector<int> (),
                   keywordDoc ("A model from meshes in correspondence ((N, 3) arrays sharing faces), as `morphreg\n"
                               "build-model`: regions (names, labels) for a multi-region model (None: one global\n"
                               "PCA); landmarks: id -> vertex. The keyword settings are build-model's:\n",
                               modelBuilderOptions ())
                       .c_str ())
      .def ("__repr__", [] (const MorphableModel& model) {
        return "<morphreg.Model: " + std::to_string (model.numVertices ()) + " vertices, " +
               std::to_string (model.numRegions ()) + " regions>";
      });
}

} // namespace python
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
// morphreg.register: a MorphableICP fit of a model to points (numpy), configured and checked as `morphreg register`
// does it, with the GIL released while it runs and an optional per-iteration progress callback.
#include "bindings.h"
#include "json_objects.h"
#include "numpy_arrays.h"
#include "python_model.h"

#include <morphreg/common/cloud_matrix.h>
#include <morphreg/common/error.h>
#include <morphreg/registration/iteration_progress.h>
#include <morphreg/registration/registration_result_json.h>
#include <morphreg/registration/registration_settings.h>
#include <morphreg/registration/scan_checks.h>
#include <morphreg/registration/scan_units.h>

#include <pybind11/stl.h>

#include <nlohmann/json.hpp>

namespace morphreg
{
namespace python
{
namespace
{
using Icp = MorphableICP<pcl::PointNormal>;

/** What a fit returns to Python. */
struct RegistrationResult
{
  Eigen::Matrix4d similarity;      ///< model to scan frame (mm)
  Eigen::VectorXd coefficients;    ///< stacked over the regions' selected components, prior standard deviations
  Eigen::VectorXd coefficients_mm; ///< the same as lengths (mm)
  Eigen::Matrix3Xd vertices;       ///< the fitted model, scan frame, mm
  TriangleMesh::Triangles faces;
  Eigen::VectorXd residuals; ///< per model vertex (mm), NaN without a correspondence
  nlohmann::json report;
};

/** The landmarks the model has, in mm and on the scan; the others are skipped with a Python warning. */
LandmarkPositions
modelLandmarks (const py::handle& landmarks, double to_mm, const MorphableModel& model,
                const pcl::PointCloud<pcl::PointNormal>& scan)
{
  LandmarkPositions positions = toLandmarks (landmarks, "landmarks");
  for (auto& entry : positions)
    entry.second *= to_mm;
  requireLandmarksOnScan (positions, pointsOf (scan), "landmarks");
  std::string skipped;
  for (const std::string& id : keepKnownLandmarks (positions, model.landmarks ()))
    skipped += " " + id;
  if (!skipped.empty ())
    PyErr_WarnEx (
        PyExc_UserWarning,
        ("landmarks: the model has no landmark" + skipped + "; using the other " + std::to_string (positions.size ()))
            .c_str (),
        1);
  if (positions.empty ())
    throw InvalidInputError ("landmarks: none of them is on the model");
  return positions;
}

/** Per iteration: Ctrl-C stops the fit (KeyboardInterrupt), and \a progress, if given, is called. */
void
watchFromPython (Icp& icp, py::object progress)
{
  watchIterations (icp, [progress] (int iteration, std::size_t correspondences, double rms) {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals () != 0)
      throw py::error_already_set ();
    if (!progress.is_none ())
      progress (iteration, correspondences, rms);
  });
}

nlohmann::json
scanJson (std::size_t points, const LengthUnitGuess& unit, const std::string& units)
{
  return {{"points", points},
          {"units", toString (unit.unit)},
          {"unit_detection", units == "auto" ? "auto" : "given"},
          {"unit_reason", unit.reason},
          {"scale_to_mm", millimetresPer (unit.unit)}};
}

RegistrationResult
registerPoints (const MorphableModel::Ptr& model, const py::handle& points, const py::handle& normals,
                const py::handle& landmarks, const RegistrationSettings& settings, py::object progress)
{
  if (!model)
    throw InvalidInputError ("model: None where a morphreg.Model was expected");
  requireValidSettings (settings);
  auto scan = toCloud (points, normals, "points");
  requireRegistrableScan (pointsOf (*scan), "points");
  const LengthUnitGuess unit = convertScanToMillimetres (*scan, settings.units, *model, "points");
  Icp icp;
  configureRegistration (icp, settings, model);
  if (!landmarks.is_none ())
    icp.setTargetLandmarks (modelLandmarks (landmarks, millimetresPer (unit.unit), *model, *scan),
                            settings.landmark_weight);
  icp.setInputTarget (scan);
  watchFromPython (icp, std::move (progress));
  {
    py::gil_scoped_release released;
    pcl::PointCloud<pcl::PointNormal> aligned;
    icp.align (aligned);
  }
  RegistrationResult result{icp.getFinalTransformation ().cast<double> (),
                            icp.getShapeCoefficients (),
                            icp.getShapeCoefficientsMm (),
                            icp.getFittedVertices (),
                            model->triangles (),
                            icp.getVertexResiduals (),
                            registrationResultJson (icp, *model)};
  result.report["scan"] = scanJson (scan->size (), unit, settings.units);
  result.report["settings"] = toJson (settings);
  return result;
}

/** target_smoothing as given: "auto", "on" or "off", or a bool (True: "on"). */
std::string
smoothingName (const py::handle& smoothing)
{
  if (py::isinstance<py::bool_> (smoothing))
    return smoothing.cast<bool> () ? "on" : "off";
  if (py::isinstance<py::str> (smoothing))
    return smoothing.cast<std::string> ();
  throw InvalidInputError ("target_smoothing: expected \"auto\", \"on\", \"off\" or a bool, got " +
                           std::string (py::repr (smoothing)));
}

/** register's keyword arguments (the command line's option names) as RegistrationSettings, and the fit. */
py::object
registerFunction (const MorphableModel::Ptr& model, const py::handle& points, const py::handle& normals,
                  const py::handle& landmarks, py::object progress, const std::string& units, int iterations,
                  int similarity_iterations, double max_distance, const py::handle& components, bool point_to_plane,
                  double tangential_weight, double shape_prior, std::optional<double> refinement_prior,
                  double refinement_smoothness, double landmark_weight, bool area_weighting, const std::string& loss,
                  double loss_scale, double reject_distance, double reject_median, bool reject_one_to_one,
                  double reject_trimmed, const py::handle& target_smoothing)
{
  RegistrationSettings settings;
  settings.units = units;
  settings.iterations = iterations;
  settings.similarity_iterations = similarity_iterations;
  settings.max_distance = max_distance;
  settings.components = componentCounts (components);
  settings.point_to_plane = point_to_plane;
  settings.tangential_weight = tangential_weight;
  settings.shape_prior = shape_prior;
  settings.refinement_prior = refinement_prior;
  settings.refinement_smoothness = refinement_smoothness;
  settings.landmark_weight = landmark_weight;
  settings.area_weighting = area_weighting;
  settings.loss = loss;
  settings.loss_scale = loss_scale;
  settings.reject_distance = reject_distance;
  settings.reject_median = reject_median;
  settings.reject_one_to_one = reject_one_to_one;
  settings.reject_trimmed = reject_trimmed;
  settings.target_smoothing = smoothingName (target_smoothing);
  return py::cast (registerPoints (model, points, normals, landmarks, settings, std::move (progress)));
}

void
bindResult (py::module_& m)
{
  py::class_<RegistrationResult> (m, "RegistrationResult", "The outcome of morphreg.register (mm, the scan's frame).")
      .def_property_readonly (
          "similarity", [] (const RegistrationResult& r) { return toArray (Eigen::MatrixXd (r.similarity)); },
          "Model-to-scan similarity, (4, 4): scale * rotation, then translation.")
      .def_property_readonly (
          "scale", [] (const RegistrationResult& r) { return r.report["similarity"]["scale"].get<double> (); })
      .def_property_readonly ("rotation",
                              [] (const RegistrationResult& r) {
                                const Eigen::Matrix3d linear = r.similarity.topLeftCorner<3, 3> ();
                                return toArray (Eigen::MatrixXd (linear / std::cbrt (linear.determinant ())));
                              })
      .def_property_readonly (
          "translation",
          [] (const RegistrationResult& r) { return toArray (Eigen::VectorXd (r.similarity.topRightCorner<3, 1> ())); })
      .def_property_readonly (
          "coefficients", [] (const RegistrationResult& r) { return toArray (Eigen::VectorXd (r.coefficients)); },
          "Shape coefficients in prior standard deviations (statismo's unit), stacked by region.")
      .def_property_readonly (
          "coefficients_mm", [] (const RegistrationResult& r) { return toArray (Eigen::VectorXd (r.coefficients_mm)); },
          "The shape coefficients as lengths (mm along each selected component), stacked by region.")
      .def_property_readonly (
          "vertices", [] (const RegistrationResult& r) { return toArray (Eigen::Matrix3Xd (r.vertices)); },
          "The fitted model's vertices, (N, 3), mm, in the scan's frame.")
      .def_property_readonly ("faces",
                              [] (const RegistrationResult& r) { return toArray (TriangleMesh::Triangles (r.faces)); })
      .def_property_readonly (
          "residuals", [] (const RegistrationResult& r) { return toArray (Eigen::VectorXd (r.residuals)); },
          "Scan-to-model distance per model vertex (mm), NaN where no scan point corresponds.")
      .def_property_readonly (
          "status", [] (const RegistrationResult& r) { return r.report["status"].get<std::string> (); },
          "\"ok\", or \"failed\" when the fit failed its plausibility checks (see report).")
      .def_property_readonly (
          "report", [] (const RegistrationResult& r) { return toPython (r.report); },
          "The report as a dict, as `morphreg register` writes it.")
      .def ("__repr__", [] (const RegistrationResult& r) {
        return "<morphreg.RegistrationResult " + r.report["status"].get<std::string> () + ", RMS " +
               std::to_string (r.report["residuals_mm"]["scan_to_model"]["rms"].get<double> ()) + " mm>";
      });
}
} // namespace

void
bindRegistration (py::module_& m)
{
  bindResult (m);
  const RegistrationSettings d;
  m.def ("register", &registerFunction, py::arg ("model"), py::arg ("points"), py::arg ("normals") = py::none (),
         py::arg ("landmarks") = py::none (), py::kw_only (), py::arg ("progress") = py::none (),
         py::arg ("units") = d.units, py::arg ("iterations") = d.iterations,
         py::arg ("similarity_iterations") = d.similarity_iterations, py::arg ("max_distance") = d.max_distance,
         py::arg ("components") = py::none (), py::arg ("point_to_plane") = d.point_to_plane,
         py::arg ("tangential_weight") = d.tangential_weight, py::arg ("shape_prior") = d.shape_prior,
         py::arg ("refinement_prior") = d.refinement_prior, py::arg ("refinement_smoothness") = d.refinement_smoothness,
         py::arg ("landmark_weight") = d.landmark_weight, py::arg ("area_weighting") = d.area_weighting,
         py::arg ("loss") = d.loss, py::arg ("loss_scale") = d.loss_scale,
         py::arg ("reject_distance") = d.reject_distance, py::arg ("reject_median") = d.reject_median,
         py::arg ("reject_one_to_one") = d.reject_one_to_one, py::arg ("reject_trimmed") = d.reject_trimmed,
         py::arg ("target_smoothing") = d.target_smoothing,
         "Fits the model to a scan's points ((N, 3), with (N, 3) normals if known) by MorphableICP, as\n"
         "`morphreg register` does; landmarks: a dict id -> (x, y, z) in the points' unit. The keyword\n"
         "arguments are register's options (--max-distance is max_distance). progress(iteration,\n"
         "correspondences, rms_mm) is called after each iteration. Returns a RegistrationResult (mm).");
}

} // namespace python
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
// morphreg.register: the library's scan registration (pipeline/scan_registration.h) of points (numpy), as `morphreg
// register` runs it, its settings the keywords of registration_options.h's table, with the GIL released while it runs
// and an optional per-iteration progress callback.
#include "bindings.h"
#include "json_objects.h"
#include "keyword_settings.h"
#include "numpy_arrays.h"
#include "python_model.h"

#include <morphreg/common/cloud_matrix.h>
#include <morphreg/common/error.h>
#include <morphreg/pipeline/scan_input.h>
#include <morphreg/pipeline/scan_registration.h>
#include <morphreg/registration/registration_options.h>
#include <morphreg/registration/registration_settings.h>

#include <pybind11/stl.h>

#include <nlohmann/json.hpp>

#include <string>

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

/** Per iteration: Ctrl-C stops the fit (KeyboardInterrupt), and the progress callback, if any, is called;
 *  landmarks the model lacks become Python warnings. Each call takes the GIL, which the fit runs without. */
class PythonObserver : public RegistrationObserver
{
public:
  explicit PythonObserver (py::object progress) : progress_ (std::move (progress)) {}

  void
  iterationDone (int iteration, std::size_t correspondences, double rms) override
  {
    py::gil_scoped_acquire gil;
    if (PyErr_CheckSignals () != 0)
      throw py::error_already_set ();
    if (!progress_.is_none ())
      progress_ (iteration, correspondences, rms);
  }

  void
  warning (const std::string& text) override
  {
    py::gil_scoped_acquire gil;
    if (PyErr_WarnEx (PyExc_UserWarning, text.c_str (), 1) != 0)
      throw py::error_already_set ();
  }

private:
  py::object progress_;
};

RegistrationResult
toResult (const ScanRegistration& registration, const ScanRegistrationOutcome& fit)
{
  if (fit.lostScan ())
    throw TooFewCorrespondencesError (fit.lost);
  Icp& icp = *fit.icp;
  return {icp.getFinalTransformation ().cast<double> (),
          icp.getShapeCoefficients (),
          icp.getShapeCoefficientsMm (),
          icp.getFittedVertices (),
          registration.model ()->triangles (),
          icp.getVertexResiduals (),
          registration.report (fit)};
}

/** The fit of morphreg.register: the library's scan registration, the GIL released while it runs. */
RegistrationResult
registerPoints (const MorphableModel::Ptr& model, const py::handle& points, const py::handle& normals,
                const py::handle& landmarks, py::object progress, const py::kwargs& keywords)
{
  if (!model)
    throw InvalidInputError ("model: None where a morphreg.Model was expected");
  const auto settings = settingsFromKeywords (keywords, registrationOptions (), "register");
  const ScanInput scan = makeScanInput (*toCloud (points, normals, "points"), "points");
  PythonObserver observer (std::move (progress));
  ScanRegistration registration (model, settings);
  registration.setObserver (&observer);
  if (!landmarks.is_none ())
    registration.setLandmarks (toLandmarks (landmarks, "landmarks"), "landmarks", LandmarkUnit::scan);
  py::gil_scoped_release released;
  const ScanRegistrationOutcome fit = registration.registerScan (scan);
  return toResult (registration, fit);
}

/** register's docstring: what it does, then one line per setting of the table. */
std::string
registerDoc ()
{
  return keywordDoc ("Fits the model to a scan's points ((N, 3), with (N, 3) normals if known) by MorphableICP, as\n"
                     "`morphreg register` does; landmarks: a dict id -> (x, y, z) in the points' unit.\n"
                     "progress(iteration, correspondences, rms_mm) is called after each iteration. Returns a\n"
                     "RegistrationResult (mm). The keyword settings are register's options (--max-distance is\n"
                     "max_distance):\n",
                     registrationOptions ());
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
  m.def ("register", &registerPoints, py::arg ("model"), py::arg ("points"), py::arg ("normals") = py::none (),
         py::arg ("landmarks") = py::none (), py::kw_only (), py::arg ("progress") = py::none (),
         registerDoc ().c_str ());
  m.attr ("_registration_options") = keywordTable (registrationOptions ());
}

} // namespace python
} // namespace morphreg

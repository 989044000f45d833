// SPDX-License-Identifier: BSD-3-Clause
// Fitting the model to two photographs: morphreg.ProfileView and morphreg.FrontalView (pixels, or the annotation
// files of `morphreg fit-photos`), morphreg.fit_photos, and morphreg.PhotoSimulator for annotated synthetic photos.
#include "bindings.h"
#include "json_objects.h"
#include "keyword_settings.h"
#include "numpy_arrays.h"
#include "python_model.h"

#include <morphreg/common/error.h>
#include <morphreg/photo/photo_view_io.h>
#include <morphreg/photo/photo_fit_options.h>
#include <morphreg/pipeline/photo_registration.h>
#include <morphreg/synthetic/photo_simulator.h>

#include <pybind11/stl.h>

#include <nlohmann/json.hpp>

namespace morphreg
{
namespace python
{
namespace
{
using synthetic::PhotoSimulator;
using synthetic::SimulatedPhotos;

/** (M, 2) pixels as points. */
std::vector<Eigen::Vector2d>
pixelList (const py::handle& pixels, const std::string& name)
{
  const DoubleArray array = floatArray (pixels, name, 2, 2);
  std::vector<Eigen::Vector2d> list (array.shape (0));
  for (py::ssize_t i = 0; i < array.shape (0); ++i)
    list[i] = {array.at (i, 0), array.at (i, 1)};
  return list;
}

Eigen::Vector2d
pixel (const py::handle& value, const std::string& name)
{
  const DoubleArray array = floatArray (value, name, 1, 2);
  return {array.at (0), array.at (1)};
}

LandmarkPixels
landmarkPixels (const py::handle& landmarks)
{
  if (!py::isinstance<py::dict> (landmarks))
    throw InvalidInputError ("landmarks: expected a dict of landmark id -> (x, y) pixels");
  LandmarkPixels pixels;
  for (const auto& item : py::reinterpret_borrow<py::dict> (landmarks)) {
    const auto id = py::str (item.first).cast<std::string> ();
    pixels[id] = pixel (item.second, "landmarks[\"" + id + "\"]");
  }
  return pixels;
}

py::array
pixelArray (const std::vector<Eigen::Vector2d>& points)
{
  Eigen::MatrixXd rows (points.size (), 2);
  for (std::size_t i = 0; i < points.size (); ++i)
    rows.row (i) = points[i].transpose ();
  return toArray (std::move (rows));
}

void
bindViews (py::module_& m)
{
  py::class_<ProfileView> (m, "ProfileView", "An annotated profile photo: the head's silhouette and the nose tip (px).")
      .def (py::init ([] (int width, int height, const py::handle& silhouette, const py::handle& nose_tip) {
              return ProfileView (width, height, pixelList (silhouette, "silhouette"), pixel (nose_tip, "nose_tip"));
            }),
            py::arg ("width"), py::arg ("height"), py::arg ("silhouette"), py::arg ("nose_tip"))
      .def_static ("load", &loadProfileView, py::arg ("path"), "Reads a profile annotation (JSON).")
      .def (
          "save", [] (const ProfileView& v, const std::string& path) { saveProfileView (path, v); }, py::arg ("path"))
      .def_property_readonly ("silhouette", [] (const ProfileView& v) { return pixelArray (v.silhouette ()); });
  py::class_<FrontalView> (m, "FrontalView", "An annotated frontal photo: named landmarks (px).")
      .def (py::init ([] (int width, int height, const py::handle& landmarks) {
              return FrontalView (width, height, landmarkPixels (landmarks));
            }),
            py::arg ("width"), py::arg ("height"), py::arg ("landmarks"))
      .def_static ("load", &loadFrontalView, py::arg ("path"), "Reads a frontal annotation (JSON).")
      .def (
          "save", [] (const FrontalView& v, const std::string& path) { saveFrontalView (path, v); }, py::arg ("path"))
      .def_property_readonly ("landmarks", [] (const FrontalView& v) {
        py::dict dict;
        for (const auto& [id, p] : v.landmarks ())
          dict[py::str (id)] = toArray (Eigen::VectorXd (p));
        return dict;
      });
}

/** The fit and its report. */
struct PhotoFitResult
{
  PhotoFit fit;
  nlohmann::json report;
};

void
bindResult (py::module_& m)
{
  py::class_<PhotoFitResult> (m, "PhotoFitResult", "The outcome of morphreg.fit_photos.")
      .def_property_readonly (
          "coefficients", [] (const PhotoFitResult& r) { return toArray (Eigen::VectorXd (r.fit.coefficients)); },
          "Shape coefficients in prior standard deviations (statismo's unit), stacked by region.")
      .def_property_readonly (
          "coefficients_mm", [] (const PhotoFitResult& r) { return toArray (Eigen::VectorXd (r.fit.coefficients_mm)); },
          "The shape coefficients as lengths (mm along each selected component), stacked by region.")
      .def_property_readonly (
          "scale", [] (const PhotoFitResult& r) { return r.fit.scale; }, "Normalised photo units per model millimetre.")
      .def_property_readonly ("rotation",
                              [] (const PhotoFitResult& r) { return toArray (Eigen::MatrixXd (r.fit.rotation)); })
      .def_property_readonly ("translation",
                              [] (const PhotoFitResult& r) { return toArray (Eigen::VectorXd (r.fit.translation)); })
      .def_property_readonly (
          "vertices", [] (const PhotoFitResult& r) { return toArray (Eigen::Matrix3Xd (r.fit.model_mesh.vertices)); },
          "The fitted head in the model's frame, (N, 3), mm.")
      .def_property_readonly (
          "image_vertices",
          [] (const PhotoFitResult& r) { return toArray (Eigen::Matrix3Xd (r.fit.image_mesh.vertices)); },
          "The fitted head in the views' frame (the normalised photo frame of the pair).")
      .def_property_readonly (
          "faces",
          [] (const PhotoFitResult& r) { return toArray (TriangleMesh::Triangles (r.fit.model_mesh.triangles)); })
      .def_property_readonly (
          "report", [] (const PhotoFitResult& r) { return toPython (r.report); },
          "The report as a dict, as `morphreg fit-photos` writes it.");
}

PhotoFitResult
fitPhotoPair (const MorphableModel::Ptr& model, const ProfileView& profile, const FrontalView* frontal,
              const py::kwargs& keywords)
{
  const PhotoFitOptions options = settingsFromKeywords (keywords, photoFitOptionTable (), "fit_photos");
  PhotoSet photos;
  photos.views = orthographicPairViews (profile, frontal);
  photos.images.resize (photos.views.size ());
  photos.sources = frontal ? "profile and frontal" : "profile";
  const PhotoRegistration registration (model, "the model", options);
  PhotoRegistrationOutcome outcome;
  {
    py::gil_scoped_release released;
    outcome = registration.fit (photos);
  }
  PhotoFitResult result{std::move (outcome.fit), std::move (outcome.report)};
  return result;
}

void
bindSimulator (py::module_& m)
{
  py::class_<SimulatedPhotos> (m, "SimulatedPhotos", "Annotated synthetic photos of a head and the true pose.")
      .def_readonly ("profile", &SimulatedPhotos::profile)
      .def_readonly ("frontal", &SimulatedPhotos::frontal)
      .def_readonly ("scale", &SimulatedPhotos::scale)
      .def_property_readonly ("rotation",
                              [] (const SimulatedPhotos& p) { return toArray (Eigen::MatrixXd (p.rotation)); })
      .def_property_readonly ("translation",
                              [] (const SimulatedPhotos& p) { return toArray (Eigen::VectorXd (p.translation)); });
  py::class_<PhotoSimulator> (m, "PhotoSimulator", "Orthographic profile and frontal photos of a head, annotated.")
      .def (py::init ([] (double landmark_noise, double silhouette_noise) {
              PhotoSimulator::Parameters parameters;
              parameters.landmark_noise = landmark_noise;
              parameters.silhouette_noise = silhouette_noise;
              return PhotoSimulator (parameters);
            }),
            py::arg ("landmark_noise") = 1.0, py::arg ("silhouette_noise") = 0.5)
      .def (
          "photograph",
          [] (const PhotoSimulator& camera, const py::handle& vertices, const LandmarkVertices& landmarks,
              const std::vector<int>& profile_line, std::uint64_t seed) {
            const PointsArgument head = pointsArgument (vertices, "vertices");
            return camera.photograph (head.points, frontalLandmarks (landmarks), profile_line, seed);
          },
          py::arg ("vertices"), py::arg ("landmarks"), py::arg ("profile_line"), py::arg ("seed"),
          "Photographs the head (landmarks: id -> vertex; the frontal ones are marked).");
}
} // namespace

void
bindPhoto (py::module_& m)
{
  bindViews (m);
  bindResult (m);
  bindSimulator (m);
  m.def ("fit_photos", &fitPhotoPair, py::arg ("model"), py::arg ("profile"), py::arg ("frontal") = nullptr,
         keywordDoc ("Fits the model to a profile view and (unless approach='profile') a frontal view, as `morphreg\n"
                     "fit-photos --profile --frontal` does. Returns a PhotoFitResult. The keyword settings are\n"
                     "fit-photos' options:\n",
                     photoFitOptionTable ())
             .c_str ());
  m.attr ("_photo_fit_options") = keywordTable (photoFitOptionTable ());
}

} // namespace python
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
// Landmark warps from numpy landmarks: morphreg.ThinPlateSpline (3D), morphreg.SegmentedWarp (one spline per segment,
// seams blended), morphreg.MovingLeastSquaresWarp and morphreg.evaluate_warp.
#include "bindings.h"
#include "numpy_arrays.h"

#include <morphreg/common/error.h>
#include <morphreg/warp/moving_least_squares_warp.h>
#include <morphreg/warp/segmented_warp.h>
#include <morphreg/warp/thin_plate_spline.h>
#include <morphreg/warp/warp_quality.h>

#include <pybind11/stl.h>

namespace morphreg
{
namespace python
{
namespace
{
using Spline = ThinPlateSpline<double, 3>;

/** Source and target landmarks of one size (3 x L each). */
std::pair<Eigen::Matrix3Xd, Eigen::Matrix3Xd>
landmarkPair (const py::handle& source, const py::handle& target)
{
  const PointsArgument from = pointsArgument (source, "source");
  const PointsArgument to = pointsArgument (target, "target");
  if (from.points.cols () != to.points.cols ())
    throw InvalidInputError ("source has " + std::to_string (from.points.cols ()) + " landmarks and target " +
                             std::to_string (to.points.cols ()) + ": they must pair up");
  return {from.points, to.points};
}

void
fitSpline (Spline& spline, const py::handle& source, const py::handle& target)
{
  const auto [from, to] = landmarkPair (source, target);
  py::gil_scoped_release released;
  spline.fit (from, to);
}

/** The (N, 3) \a points moved by \a transform (a callable taking and returning 3 x N points), the GIL released
 *  while it runs. */
template <typename Transform>
py::array
transformedPoints (const py::handle& points, Transform transform)
{
  const PointsArgument at = pointsArgument (points, "points", 0);
  Eigen::Matrix3Xd warped;
  {
    py::gil_scoped_release released;
    warped = transform (at.points);
  }
  return toArray (std::move (warped));
}

py::array
evaluateSpline (const Spline& spline, const py::handle& points)
{
  return transformedPoints (points, [&] (const Eigen::Matrix3Xd& at) { return spline.evaluate (at); });
}

void
bindSpline (py::module_& m)
{
  py::class_<Spline, Spline::Ptr> (m, "ThinPlateSpline",
                                   "A 3D thin plate spline: fit(source, target) on (L, 3) landmarks, then evaluate "
                                   "(N, 3) points (mm).")
      .def (py::init ([] (double regularization) {
              auto spline = std::make_shared<Spline> ();
              spline->setRegularization (regularization);
              return spline;
            }),
            py::arg ("regularization") = 0.0, "regularization: lambda >= 0 (0 interpolates the landmarks).")
      .def ("fit", &fitSpline, py::arg ("source"), py::arg ("target"),
            "Fits the spline sending the source landmarks to the target landmarks.")
      .def ("evaluate", &evaluateSpline, py::arg ("points"), "The warped points, (N, 3).")
      .def ("__call__", &evaluateSpline, py::arg ("points"))
      .def_property_readonly ("is_fitted", &Spline::isFitted)
      .def_property_readonly ("regularization", &Spline::getRegularization)
      .def_property_readonly ("bending_energy", &Spline::bendingEnergy)
      .def_property_readonly (
          "landmarks", [] (const Spline& s) { return toArray (Eigen::MatrixXd (s.getLandmarks ())); },
          "The landmarks the spline uses (L, 3), coincident ones merged.")
      .def_property_readonly (
          "weights", [] (const Spline& s) { return toArray (Eigen::MatrixXd (s.getWeights ())); },
          "The kernel weights (L, 3).")
      .def_property_readonly (
          "affine", [] (const Spline& s) { return toArray (Eigen::MatrixXd (s.getAffine ())); },
          "The affine part (4, 3): rows 1, x, y, z.");
}

py::array
warpPoints (const MovingLeastSquaresWarp& warp, const py::handle& points)
{
  return transformedPoints (points, [&] (const Eigen::Matrix3Xd& at) { return warp.transformPoints (at); });
}

void
bindMovingLeastSquaresWarp (py::module_& m)
{
  py::class_<MovingLeastSquaresWarp, MovingLeastSquaresWarp::Ptr> (
      m, "MovingLeastSquaresWarp",
      "Moving least squares warp: each point follows the affine map that best carries the (L, 3) landmarks under "
      "weights 1 / distance^(2 falloff) (mm).")
      .def (py::init ([] (double falloff) {
              auto warp = std::make_shared<MovingLeastSquaresWarp> ();
              warp->setFalloff (falloff);
              return warp;
            }),
            py::arg ("falloff") = 1.0, "falloff: the exponent alpha > 0 (larger is more local).")
      .def (
          "set_landmarks",
          [] (MovingLeastSquaresWarp& warp, const py::handle& source, const py::handle& target) {
            const auto [from, to] = landmarkPair (source, target);
            warp.setLandmarks (from, to);
          },
          py::arg ("source"), py::arg ("target"), "Sets the landmark pairs, (L, 3) each; four not on one plane.")
      .def ("evaluate", &warpPoints, py::arg ("points"), "The warped points, (N, 3).")
      .def ("__call__", &warpPoints, py::arg ("points"))
      .def_property_readonly ("falloff", &MovingLeastSquaresWarp::getFalloff)
      .def_property_readonly ("merged_landmarks", &MovingLeastSquaresWarp::mergedLandmarks);
}

std::vector<int>
labelsArgument (const py::handle& labels)
{
  const py::array array = py::array::ensure (labels);
  if (!array || (array.dtype ().kind () != 'i' && array.dtype ().kind () != 'u') || array.ndim () != 1)
    throw InvalidInputError ("labels: expected a 1-D integer array (the segment of each vertex)");
  return py::array_t<int, py::array::forcecast>::ensure (array).cast<std::vector<int>> ();
}

py::array
warpMesh (const SegmentedWarp& warp, const py::handle& vertices, const py::handle& faces)
{
  const TriangleMesh mesh = toMesh (vertices, faces, "mesh");
  TriangleMesh warped;
  {
    py::gil_scoped_release released;
    warped = warp.warp (mesh);
  }
  return toArray (std::move (warped.vertices));
}

std::vector<std::vector<int>>
setLandmarks (SegmentedWarp& warp, const py::handle& vertices, const py::handle& faces, const py::handle& source,
              const py::handle& target, const std::vector<double>& overlap)
{
  const TriangleMesh mesh = toMesh (vertices, faces, "mesh");
  const auto [from, to] = landmarkPair (source, target);
  return warp.setLandmarks (mesh, from, to, overlap);
}

void
bindSegmentedWarp (py::module_& m)
{
  py::class_<SegmentedWarp, SegmentedWarp::Ptr> (m, "SegmentedWarp",
                                                 "One thin plate spline per body segment, recombined into one mesh "
                                                 "with seams blended along the surface.")
      .def (py::init ([] (const py::handle& labels, int num_segments) {
              return std::make_shared<SegmentedWarp> (labelsArgument (labels), num_segments);
            }),
            py::arg ("labels"), py::arg ("num_segments"), "labels: the segment (0 to num_segments - 1) of each vertex.")
      .def_property_readonly ("num_segments", &SegmentedWarp::numSegments)
      .def ("set_landmarks", &setLandmarks, py::arg ("vertices"), py::arg ("faces"), py::arg ("source"),
            py::arg ("target"), py::arg ("overlap"),
            "Shares the landmarks out to the segments (overlap: mm per segment) and fits each spline; returns the "
            "landmark indices of each segment.")
      .def (
          "set_segment_landmarks",
          [] (SegmentedWarp& warp, int segment, const py::handle& source, const py::handle& target) {
            const auto [from, to] = landmarkPair (source, target);
            warp.setSegmentLandmarks (segment, from, to);
          },
          py::arg ("segment"), py::arg ("source"), py::arg ("target"), "Fits one segment's spline.")
      .def_property ("blend_width", &SegmentedWarp::getBlendWidth, &SegmentedWarp::setBlendWidth,
                     "How far (mm, along the mesh) each segment's warp reaches into its neighbours.")
      .def ("set_segment_blend_width", &SegmentedWarp::setSegmentBlendWidth, py::arg ("segment"), py::arg ("width"))
      .def ("set_regularization", &SegmentedWarp::setRegularization, py::arg ("regularization"))
      .def ("warp", &warpMesh, py::arg ("vertices"), py::arg ("faces"), "The warped vertices, (N, 3).");
}

py::dict
evaluateWarpFunction (const py::handle& warped, const py::handle& truth, const py::handle& faces,
                      const py::handle& labels, double band_width)
{
  const WarpQuality q = evaluateWarp (toMesh (warped, faces, "warped"), toMesh (truth, faces, "truth"),
                                      labelsArgument (labels), band_width);
  py::dict result;
  result["mean_error"] = q.mean_error;
  result["rms_error"] = q.rms_error;
  result["max_error"] = q.max_error;
  result["seam"] = q.seam;
  result["band"] = q.band;
  result["folded"] = q.folded;
  result["folded_in_band"] = q.folded_in_band;
  result["collapsed"] = q.collapsed;
  return result;
}
} // namespace

void
bindWarp (py::module_& m)
{
  bindSpline (m);
  bindSegmentedWarp (m);
  bindMovingLeastSquaresWarp (m);
  m.def ("evaluate_warp", &evaluateWarpFunction, py::arg ("warped"), py::arg ("truth"), py::arg ("faces"),
         py::arg ("labels"), py::arg ("band_width") = 100.0,
         "Errors of a warped mesh against the true one (mm), seam stretch and folded triangles, as a dict.");
}

} // namespace python
} // namespace morphreg

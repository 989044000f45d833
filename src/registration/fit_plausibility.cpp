// SPDX-License-Identifier: BSD-3-Clause
#include "../common/number_text.h"

#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/registration/fit_plausibility.h>
#include <morphreg/registration/surface_distance.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <vector>

namespace morphreg
{
namespace
{
using detail::numberText;

/** At most this many scan points are scored for the explained share. */
constexpr Eigen::Index kScoredScanPoints = 20000;

/** Scan points farther than this (mm) from the fitted surface are other things (a wall, a chair, the body below the
 *  model's neck, hair spikes), not the head the fit should explain. */
constexpr double kHeadBand = 25.0;

/** Smallest over largest principal spread of \a points. */
double
thicknessRatio (const Eigen::Matrix3Xd& points)
{
  const Eigen::Vector3d centroid = points.rowwise ().mean ();
  const Eigen::Matrix3Xd centred = points.colwise () - centroid;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (centred * centred.transpose ());
  const Eigen::Vector3d spread = solver.eigenvalues ().cwiseMax (0.0).cwiseSqrt ();
  return spread[2] > 0.0 ? spread[0] / spread[2] : 0.0;
}

/** Share of the mean's surface area whose triangles in \a fitted, turned back by \a rotation, face against the mean's. */
double
foldedShare (const MorphableModel& model, const Eigen::Matrix3d& rotation, const Eigen::Matrix3Xd& fitted)
{
  const Eigen::Map<const Eigen::Matrix3Xd> mean (model.mean ().data (), 3, model.numVertices ());
  const TriangleMesh mean_mesh{mean, model.triangles ()};
  const Eigen::Matrix3Xd before = faceNormals (mean_mesh);
  const Eigen::Matrix3Xd after = rotation.transpose () * faceNormals (TriangleMesh{fitted, model.triangles ()});
  const Eigen::VectorXd areas = triangleAreas (mean_mesh);
  double folded = 0.0;
  for (Eigen::Index t = 0; t < before.cols (); ++t)
    folded += before.col (t).dot (after.col (t)) < 0.0 ? areas[t] : 0.0;
  return areas.sum () > 0.0 ? folded / areas.sum () : 0.0;
}

/** The explained share of \a scan (at most kScoredScanPoints of it) against the fitted surface. */
void
measureExplained (const Eigen::Matrix3Xd& scan, const TriangleMesh& fitted, FitMeasures& measures)
{
  if (scan.cols () == 0)
    return;
  const Eigen::Index step = std::max<Eigen::Index> (1, scan.cols () / kScoredScanPoints);
  Eigen::Matrix3Xd scored (3, (scan.cols () + step - 1) / step);
  for (Eigen::Index i = 0; i < scored.cols (); ++i)
    scored.col (i) = scan.col (i * step);
  const SurfaceDistance distances = pointDistances (scored, fitted);
  measures.scored_points = static_cast<int> (std::count_if (distances.distances.begin (), distances.distances.end (),
                                                            [] (double d) { return d <= kHeadBand; }));
  const auto explained = std::count_if (distances.distances.begin (), distances.distances.end (),
                                        [] (double d) { return d <= kExplainedDistance; });
  measures.explained_share =
      measures.scored_points ? static_cast<double> (explained) / static_cast<double> (measures.scored_points) : 0.0;
}
/** FitMeasures::region_coverage of \a model's regions from the per-vertex residuals (NaN: no correspondence). */
std::vector<std::pair<std::string, double>>
regionCoverage (const MorphableModel& model, const Eigen::VectorXd& vertex_residuals)
{
  std::vector<std::pair<std::string, double>> coverage;
  for (const ModelRegion& region : model.regions ()) {
    double own = 0.0, covered = 0.0;
    for (size_t r = 0; r < region.vertices.size (); ++r)
      if (region.weights[static_cast<Eigen::Index> (r)] >= 0.5) {
        own += 1.0;
        const double residual = vertex_residuals[region.vertices[r]];
        covered += std::isfinite (residual) && residual <= kExplainedDistance ? 1.0 : 0.0;
      }
    coverage.emplace_back (region.name, own > 0.0 ? covered / own : 0.0);
  }
  return coverage;
}
} // namespace

FitMeasures
measureFit (const MorphableModel& model, const ComponentSelection& selection, const Eigen::VectorXd& coefficients,
            const Eigen::Matrix4d& similarity, const Eigen::Matrix3Xd& fitted_vertices,
            const Eigen::VectorXd& vertex_residuals, const Eigen::Matrix3Xd& scan, const IcpReport& report,
            int leading_components)
{
  if (vertex_residuals.size () != fitted_vertices.cols () || fitted_vertices.cols () != model.numVertices ())
    throw InvalidInputError ("measureFit: " + std::to_string (vertex_residuals.size ()) + " residuals and " +
                             std::to_string (fitted_vertices.cols ()) + " fitted vertices for a model of " +
                             std::to_string (model.numVertices ()));
  FitMeasures measures;
  const Eigen::Matrix3d linear = similarity.topLeftCorner<3, 3> ();
  measures.scale = std::cbrt (linear.determinant ());
  measures.correspondence_share = static_cast<double> (vertex_residuals.array ().isFinite ().count ()) /
                                  static_cast<double> (vertex_residuals.size ());
  const Eigen::VectorXd leading = leadingCoefficientsInSigma (model, selection, coefficients, leading_components);
  measures.largest_sigma = leading.size () > 0 ? leading.cwiseAbs ().maxCoeff () : 0.0;
  measures.thickness_ratio = thicknessRatio (fitted_vertices);
  measures.median_residual = report.fitness_median;
  measureExplained (scan, TriangleMesh{fitted_vertices, model.triangles ()}, measures);
  measures.folded_share =
      foldedShare (model, measures.scale > 0.0 ? Eigen::Matrix3d (linear / measures.scale) : linear, fitted_vertices);
  measures.region_coverage = regionCoverage (model, vertex_residuals);
  measures.divergence = report.divergence;
  measures.divergence_message = report.message;
  return measures;
}

FitPlausibility
checkFitPlausibility (const FitMeasures& m, const FitPlausibilitySettings& settings)
{
  FitPlausibility result;
  const auto fail = [&result] (const std::string& why) {
    result.plausible = false;
    result.failures.push_back (why);
  };
  if (!(m.scale >= settings.min_scale && m.scale <= settings.max_scale))
    fail ("the head's scale " + numberText (m.scale) + " is outside what the model's population allows (" +
          numberText (settings.min_scale) + "-" + numberText (settings.max_scale) + "): a wrong unit or not a head");
  if (!(m.correspondence_share >= settings.min_correspondence_share))
    fail ("only " + numberText (100.0 * m.correspondence_share) +
          " % of the model has correspondences on the scan (at "
          "least " +
          numberText (100.0 * settings.min_correspondence_share) + " % needed)");
  if (!(m.largest_sigma <= settings.max_sigma))
    fail ("a leading shape coefficient is " + numberText (m.largest_sigma) +
          " standard deviations from the mean (at "
          "most " +
          numberText (settings.max_sigma) + "): the fit left the model");
  if (!(m.thickness_ratio >= settings.min_thickness_ratio))
    fail ("the fitted head is collapsed or flat (thinnest over widest extent " + numberText (m.thickness_ratio) +
          ", at least " + numberText (settings.min_thickness_ratio) + ")");
  if (!(m.median_residual <= settings.max_median_residual))
    fail ("the fit lies " + numberText (m.median_residual) + " mm from the scan (median; at most " +
          numberText (settings.max_median_residual) + " mm): the model was not fitted onto the head");
  if (!(m.explained_share >= settings.min_explained_share))
    fail ("the fit explains " + numberText (100.0 * m.explained_share) + " % of the " +
          std::to_string (m.scored_points) + " scan points it covers (within " + numberText (kExplainedDistance) +
          " mm; at least " + numberText (100.0 * settings.min_explained_share) +
          " % needed): it is not on the head, or the head is not the model's");
  if (!(m.folded_share <= settings.max_folded_share))
    fail ("the fitted surface folds over itself: " + numberText (100.0 * m.folded_share) +
          " % of its area faces against the model's (at most " + numberText (100.0 * settings.max_folded_share) +
          " %)");
  if (m.divergence == IcpDivergence::unsolvable)
    fail ("the fit diverged: " + m.divergence_message);
  return result;
}

Eigen::VectorXd
leadingCoefficientsInSigma (const MorphableModel& model, const ComponentSelection& selection,
                            const Eigen::VectorXd& coefficients, int leading)
{
  const Eigen::VectorXd sigma = model.variances (selection).cwiseSqrt ();
  std::vector<double> kept;
  for (int region = 0; region < selection.numRegions (); ++region)
    for (int k = 0; k < std::min (selection.count (region), leading); ++k) {
      const int index = selection.offset (region) + k;
      kept.push_back (coefficients[index] / std::max (sigma[index], 1e-12));
    }
  return Eigen::Map<const Eigen::VectorXd> (kept.data (), static_cast<Eigen::Index> (kept.size ()));
}

} // namespace morphreg

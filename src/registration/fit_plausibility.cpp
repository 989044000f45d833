// SPDX-License-Identifier: BSD-3-Clause
#include "../common/number_text.h"

#include <morphreg/common/error.h>
#include <morphreg/registration/fit_plausibility.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <vector>

namespace morphreg
{
namespace
{
using detail::numberText;

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
} // namespace

FitPlausibility
checkFitPlausibility (double scale, const Eigen::Matrix3Xd& fitted_vertices, const Eigen::VectorXd& vertex_residuals,
                      const Eigen::VectorXd& coefficients_in_sigma, const IcpReport& report,
                      const FitPlausibilitySettings& settings)
{
  if (vertex_residuals.size () != fitted_vertices.cols () || fitted_vertices.cols () == 0)
    throw InvalidInputError ("checkFitPlausibility: " + std::to_string (vertex_residuals.size ()) + " residuals for " +
                             std::to_string (fitted_vertices.cols ()) + " fitted vertices");
  FitPlausibility result;
  const auto fail = [&result] (const std::string& why) {
    result.plausible = false;
    result.failures.push_back (why);
  };
  if (!(scale >= settings.min_scale && scale <= settings.max_scale))
    fail ("the head's scale " + numberText (scale) + " is outside what the model's population allows (" +
          numberText (settings.min_scale) + "-" + numberText (settings.max_scale) + "): a wrong unit or not a head");
  const double share = static_cast<double> (vertex_residuals.array ().isFinite ().count ()) /
                       static_cast<double> (vertex_residuals.size ());
  if (share < settings.min_correspondence_share)
    fail ("only " + numberText (100.0 * share) + " % of the model has correspondences on the scan (at least " +
          numberText (100.0 * settings.min_correspondence_share) + " % needed)");
  const double largest = coefficients_in_sigma.size () > 0 ? coefficients_in_sigma.cwiseAbs ().maxCoeff () : 0.0;
  if (largest > settings.max_sigma)
    fail ("a shape coefficient is " + numberText (largest) + " standard deviations from the mean (at most " +
          numberText (settings.max_sigma) + ")");
  const double thickness = thicknessRatio (fitted_vertices);
  if (thickness < settings.min_thickness_ratio)
    fail ("the fitted head is collapsed or flat (thinnest over widest extent " + numberText (thickness) +
          ", at least " + numberText (settings.min_thickness_ratio) + ")");
  if (!(report.fitness_median <= settings.max_median_residual))
    fail ("the fit lies " + numberText (report.fitness_median) + " mm from the scan (median; at most " +
          numberText (settings.max_median_residual) + " mm): the model was not fitted onto the head");
  if (report.divergence == IcpDivergence::prior_exceeded || report.divergence == IcpDivergence::unsolvable)
    fail ("the fit diverged: " + report.message);
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

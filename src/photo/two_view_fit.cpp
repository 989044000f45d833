// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/photo/two_view_fit.h>

#include <morphreg/io/json_file.h>

#include <cmath>

namespace morphreg
{
namespace
{
nlohmann::json
iterationJson (const TwoViewIteration& iteration)
{
  const char* const stages[] = {"similarity", "shape", "tps_icp"};
  return {{"stage", stages[static_cast<int> (iteration.stage)]},
          {"profile_correspondences", iteration.profile_correspondences},
          {"profile_rms_mm", iteration.profile_rms},
          {"landmark_rms_mm", iteration.landmark_rms}};
}
} // namespace

Eigen::Matrix4d
TwoViewFit::similarity () const
{
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity ();
  m.topLeftCorner<3, 3> () = scale * rotation;
  m.topRightCorner<3, 1> () = translation;
  return m;
}

double
TwoViewFit::maxCoefficientSigma () const
{
  return coefficient_sigmas.size () > 0 ? coefficient_sigmas.cwiseAbs ().maxCoeff () : 0.0;
}

double
TwoViewFit::shapeDistance () const
{
  return coefficient_sigmas.norm ();
}

bool
isPlausibleShape (const Eigen::VectorXd& standardised)
{
  const double p = static_cast<double> (standardised.size ());
  return standardised.squaredNorm () <= p + 5.0 * std::sqrt (2.0 * p);
}

nlohmann::json
twoViewFitJson (const TwoViewFit& fit)
{
  nlohmann::json history = nlohmann::json::array ();
  for (const TwoViewIteration& iteration : fit.history)
    history.push_back (iterationJson (iteration));
  nlohmann::json rotation = nlohmann::json::array ();
  for (int r = 0; r < 3; ++r)
    rotation.push_back ({fit.rotation (r, 0), fit.rotation (r, 1), fit.rotation (r, 2)});
  return {{"scale", fit.scale},
          {"rotation", rotation},
          {"translation", {fit.translation.x (), fit.translation.y (), fit.translation.z ()}},
          {"component_counts", fit.selection.counts ()},
          {"coefficients",
           std::vector<double> (fit.coefficients.data (), fit.coefficients.data () + fit.coefficients.size ())},
          {"returned", fit.returned},
          {"tps_rounds", fit.tps_rounds},
          {"max_coefficient_sigma", fit.maxCoefficientSigma ()},
          {"coefficients_beyond_3_sigma", (fit.coefficient_sigmas.array ().abs () > 3.0).count ()},
          {"shape_distance_sigma", fit.shapeDistance ()},
          {"plausible_shape", isPlausibleShape (fit.coefficient_sigmas)},
          {"ignored_landmarks", fit.ignored_landmarks},
          {"final", iterationJson (fit.final_residuals)},
          {"history", history}};
}

void
saveTwoViewFitReport (const std::string& path, const TwoViewFit& fit)
{
  writeJsonFile (path, twoViewFitJson (fit));
}
} // namespace morphreg

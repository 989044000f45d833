// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file two_view_fit.h
 *  \brief The result of a two-view (profile + frontal photo) fit of a morphable model, and its JSON report.
 */
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/model/component_selection.h>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace morphreg
{
/** \brief The stage of a two-view fit iteration. */
enum class TwoViewStage
{
  similarity, ///< pose and scale only (mean shape)
  shape,      ///< pose, scale and shape coefficients
  tps_icp     ///< one round of approach 2: TPS warp to the landmarks, then the 3D-3D fit to the warped mesh
};

/** \brief One Gauss-Newton iteration (or TPS-ICP round) of a two-view fit, measured at its start. Residuals are in
 *  model millimetres (normalised-frame distances divided by the fit's scale).
 */
struct TwoViewIteration
{
  TwoViewStage stage = TwoViewStage::similarity; ///< what the iteration estimated
  int profile_correspondences = 0;               ///< profile-line vertices within the correspondence distance
  double profile_rms = 0.0;                      ///< RMS in-image distance of those vertices to the silhouette (mm)
  double landmark_rms = 0.0; ///< RMS in-image distance of the frontal landmarks (mm; 0 without them)
};

/** \brief A fitted model instance v = mu + M m and the similarity X = s R v + t from the model frame (mm) into the
 *  normalised photo frame (frontal image = (X, Y), profile image = (Z, Y)).
 */
struct TwoViewFit
{
  ComponentSelection selection;                            ///< the components of \a coefficients
  Eigen::VectorXd coefficients;                            ///< shape coefficients (mm along the orthonormal basis)
  double scale = 1.0;                                      ///< s: normalised units per model millimetre
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity (); ///< R
  Eigen::Vector3d translation = Eigen::Vector3d::Zero ();  ///< t, normalised units
  TriangleMesh model_mesh;                                 ///< the fitted shape in the model frame (mm)
  TriangleMesh image_mesh;                                 ///< the fitted shape in the normalised photo frame
  std::vector<TwoViewIteration> history;                   ///< every iteration's residuals, in order
  TwoViewIteration final_residuals;                        ///< the residuals at the returned state
  /** \brief What the result is: "profile", "joint" or "tps_icp"; a TPS-ICP fit none of whose rounds lowered the image
   *  error returns its starting profile fit, and says "profile" here. */
  std::string returned;
  int tps_rounds = 0;                 ///< TPS-ICP rounds whose result was kept (0 for the other fits)
  Eigen::VectorXd coefficient_sigmas; ///< the coefficients in prior standard deviations (stacked like them)

  std::vector<std::string>
      ignored_landmarks; ///< frontal outline landmarks left out (TwoViewFitting::setContourLandmarkWeight)

  /** \brief The largest |coefficient| in prior standard deviations (0 without components).
   *  \return the largest |coefficient_sigmas| entry
   */
  double
  maxCoefficientSigma () const;

  /** \brief The shape's Mahalanobis distance from the mean head: the norm of the coefficients in prior standard
   *  deviations.
   *  \return the norm of coefficient_sigmas
   */
  double
  shapeDistance () const;

  /** \brief [s R | t] as a 4 x 4 matrix.
   *  \return the similarity from the model frame into the normalised photo frame
   */
  Eigen::Matrix4d
  similarity () const;
};

/** \brief Whether coefficients \a standardised (in prior standard deviations) describe a head the model's population
 *  holds: their squared norm at most p + 5 sqrt(2 p) for p coefficients, the chi-square mean plus five standard
 *  deviations. Heads drawn from the model almost never pass it; it is that loose because a model built from few heads
 *  underestimates the variance of new ones (an unseen head fitted with a 30-head model reaches p + 3.2 sd).
 *  \param[in] standardised the coefficients divided by their prior standard deviations
 *  \return true if the shape is plausible
 */
bool
isPlausibleShape (const Eigen::VectorXd& standardised);

/** \brief \a fit's similarity, coefficients, final residuals and iteration history as JSON (not the meshes).
 *  \param[in] fit the fit
 *  \return the report document
 */
nlohmann::json
twoViewFitJson (const TwoViewFit& fit);

/** \brief Writes \a fit's similarity, coefficients, final residuals and iteration history as JSON (not the meshes);
 *  IoError if the file cannot be written.
 *  \param[in] path the JSON file
 *  \param[in] fit the fit
 */
void
saveTwoViewFitReport (const std::string& path, const TwoViewFit& fit);
} // namespace morphreg

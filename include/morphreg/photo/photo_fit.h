// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file photo_fit.h
 *  \brief The result of fitting a morphable model to photos (PhotoFitting), and its JSON report.
 */
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/model/component_selection.h>
#include <morphreg/photo/photo_camera.h>

#include <Eigen/Core>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace morphreg
{
/** \brief The stage of a photo fit iteration. */
enum class PhotoFitStage
{
  similarity, ///< pose and scale only (mean shape)
  shape,      ///< pose, scale and shape coefficients
  tps_icp     ///< one round of TPS-ICP: TPS warp to the image targets, then the 3D-3D fit to the warped mesh
};

/** \brief One Gauss-Newton iteration (or TPS-ICP round) of a photo fit, measured at its start. Residuals are
 *  in-image distances in model millimetres (pixels divided by the pixels per model millimetre).
 */
struct PhotoFitIteration
{
  PhotoFitStage stage = PhotoFitStage::similarity; ///< what the iteration estimated
  int outline_correspondences = 0;                 ///< model outline points pulled to a traced outline
  int outline_inside = 0;            ///< model outline points inside a traced outline where it may lie inside (hair)
  double outline_rms = 0.0;          ///< RMS in-image distance of the pulled points to the outline (mm)
  double landmark_rms = 0.0;         ///< RMS in-image distance of the landmarks (mm; 0 without them)
  int outline_landmarks = 0;         ///< outline landmarks (jaw, chin, ...) matched to the model's outline
  double outline_landmark_rms = 0.0; ///< RMS in-image distance of the model's outline to those marks (mm)
};

/** \brief One candidate of the data-chosen shape prior: its weight and how well it predicts left-out landmarks. */
struct PriorCandidate
{
  double weight = 0.0;   ///< lambda_2
  double error_mm = 0.0; ///< RMS in-image error of the left-out landmarks (model mm)
};

/** \brief How the shape prior's weight lambda_2 was chosen (ShapePriorSelection). */
struct ShapePriorChoice
{
  double weight = 0.0;                    ///< the lambda_2 fitted
  double noise_weight = 0.0;              ///< the weight the stated landmark noise gives (model mm per pixel of noise)
  std::string rule;                       ///< "given", "noise" (nothing to leave out) or "left-out landmarks"
  std::vector<PriorCandidate> candidates; ///< the weights tried and their left-out errors
  double mean_head_error_mm = 0.0;        ///< the mean head's left-out error, posed by the same data
  bool beats_mean_head = true;            ///< false: the photos predict left-out landmarks no better than the mean head
};

/** \brief What a fit did with one photo. */
struct PhotoFitView
{
  std::string source;             ///< the photo
  PhotoCamera camera;             ///< the camera used (given or estimated)
  bool camera_estimated = false;  ///< whether it was estimated from the landmarks
  std::string focal_source;       ///< for an estimated camera: where its focal length came from
  double camera_rms_pixels = 0.0; ///< for an estimated camera: the fitted landmarks' reprojection RMS (px)
  int landmarks = 0;              ///< landmarks that fix a model vertex
  int outline_landmarks = 0;      ///< outline landmarks (constraints on the model's outline)
  int outline_points = 0;         ///< traced outline points (0 without an outline)
  int outline_two_sided = 0;      ///< of those, the ones the model must lie on (the face)
  std::string hairline;           ///< how the hair was found: "marked", "from the fit" or "" (no outline)
};

/** \brief A fitted model instance v = mu + M m and the similarity X = s R v + t from the model frame (mm) into the
 *  views' common frame: the cameras' frame, or for the orthographic pair the normalised photo frame (frontal image
 *  = (X, Y), profile image = (Z, Y)).
 */
struct PhotoFit
{
  ComponentSelection selection; ///< the components of \a coefficients
  /** \brief Shape coefficients in prior standard deviations (statismo's unit; docs/coefficients.md). */
  Eigen::VectorXd coefficients;
  Eigen::VectorXd coefficients_mm;                         ///< the same as lengths: mm along the orthonormal basis
  double scale = 1.0;                                      ///< s: world units per model millimetre
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity (); ///< R
  Eigen::Vector3d translation = Eigen::Vector3d::Zero ();  ///< t, world units
  TriangleMesh model_mesh;                                 ///< the fitted shape in the model frame (mm)
  TriangleMesh image_mesh;                                 ///< the fitted shape in the views' frame
  std::vector<PhotoFitIteration> history;                  ///< every iteration's residuals, in order
  PhotoFitIteration final_residuals;                       ///< the residuals at the returned state
  std::string method;                                      ///< the method asked for ("joint", "tps", "profile", ...)
  /** \brief What the result is: "profile", "joint" or "tps_icp"; a TPS-ICP fit none of whose rounds lowered the image
   *  error returns its starting profile fit, and says "profile" here. */
  std::string returned;
  int tps_rounds = 0;                         ///< TPS-ICP rounds whose result was kept (0 for the other fits)
  std::vector<std::string> ignored_landmarks; ///< outline landmarks left out (PhotoFitting::setOutlineLandmarkWeight)
  std::vector<PhotoFitView> views;            ///< per photo: camera, constraints, hair
  ShapePriorChoice prior;                     ///< how lambda_2 was chosen

  /** \brief The largest |coefficient| in prior standard deviations (0 without components).
   *  \return the largest |coefficients| entry
   */
  double
  maxCoefficientSigma () const;

  /** \brief The shape's Mahalanobis distance from the mean head: the norm of the coefficients in prior standard
   *  deviations.
   *  \return the norm of coefficients
   */
  double
  shapeDistance () const;

  /** \brief [s R | t] as a 4 x 4 matrix.
   *  \return the similarity from the model frame into the views' frame
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

/** \brief \a fit's similarity, coefficients, prior, views, final residuals and iteration history as JSON (not the
 *  meshes).
 *  \param[in] fit the fit
 *  \return the report document
 */
nlohmann::json
photoFitJson (const PhotoFit& fit);

/** \brief Writes photoFitJson (\a fit) to \a path; IoError if the file cannot be written.
 *  \param[in] path the JSON file
 *  \param[in] fit the fit
 */
void
savePhotoFitReport (const std::string& path, const PhotoFit& fit);
} // namespace morphreg

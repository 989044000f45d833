// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file photo_fitting.h
 *  \brief Fitting a morphable model to photos (docs/method.md, "Fitting to photographs"): any number of views with
 *  perspective cameras (given, or estimated from the landmarks), or the orthographic frontal and profile pair; the
 *  profile fit, approach 1 "joint" and approach 2 "TPS-ICP" as PhotoFitMethod strategies over one MultiViewProblem;
 *  the shape prior chosen from the data.
 */
#include <morphreg/model/morphable_model.h>
#include <morphreg/photo/frontal_view.h>
#include <morphreg/photo/multi_view_problem.h>
#include <morphreg/photo/photo_fit.h>
#include <morphreg/photo/photo_fit_method.h>
#include <morphreg/photo/photo_view.h>
#include <morphreg/photo/profile_view.h>

#include <memory>
#include <optional>

namespace morphreg
{
/** \brief Fits X = s R (mu + M m) + t to photos. Each view's landmarks fix model vertices (their pixels), its
 *  outline landmarks (jaw, chin, neck, head contour) and traced outline constrain the model's outline in that view:
 *  on it along the face, inside it where the outline runs over hair. Residuals count in model millimetres, so the
 *  priors lambda_1^2 |Gamma m|^2 + lambda_2^2 |Lambda m|^2 weigh as in MorphableICP; lambda_1 > 0 carries the
 *  shape into regions the photos do not constrain. lambda_2 is chosen from the data (ShapePriorSelection) unless
 *  setShapePriorWeight fixes it. Model axes as the built-in heads: +Y up, +Z out of the face, +X the subject's left.
 *
 *  \code
 *  morphreg::PhotoFitting fitting (model);                  // model with a profile line and landmarks
 *  morphreg::PhotoView left (1200, 1600, morphreg::loadLandmarkPixels ("left.pts"), "left.jpg");
 *  left.setCamera (morphreg::loadPhotoCamera ("cameras.json", "left.jpg", 1200, 1600));
 *  morphreg::PhotoFit fit = fitting.fit ({left, right}, "joint");
 *  morphreg::saveTriangleMesh ("head.ply", fit.model_mesh);  // mm, model frame
 *  \endcode
 */
class PhotoFitting
{
public:
  using Ptr = std::shared_ptr<PhotoFitting>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const PhotoFitting>; ///< shared pointer to const

  /** Components fitted per region unless setComponentSelection says otherwise. */
  static constexpr int kDefaultComponents = 20;
  static constexpr double kDefaultSmoothnessWeight = 0.5; ///< default lambda_1 (setSmoothnessWeight)
  static constexpr double kDefaultCoefficientLimit = 3.0; ///< default coefficient clamp in sigmas (setCoefficientLimit)
  static constexpr double kDefaultLandmarkWeight = 0.5;   ///< default landmark weight (setLandmarkWeight)
  static constexpr double kDefaultSagittalWeight = 1.0;   ///< default sagittal row weight (setSagittalWeight)
  static constexpr double kDefaultLandmarkNoise = 1.0;    ///< default landmark noise, pixels (setLandmarkNoise)

  /** \brief Selects kDefaultComponents per region (or all a region has). Throws InvalidInputError for a null model,
   *  one without a profile line (MorphableModel::setProfileLine) or without a nose_tip landmark.
   *  \param[in] model the model fitted (mm), with a profile line and landmarks
   */
  explicit PhotoFitting (MorphableModel::ConstPtr model);

  /** \brief The components fitted in the shape stage (validated against the model).
   *  \param[in] selection the number of components per region
   */
  void
  setComponentSelection (const ComponentSelection& selection);

  /** \brief lambda_1, the weight of the smoothness prior across overlapping regions: finite and > 0
   *  (kDefaultSmoothnessWeight).
   *  \param[in] lambda1 the smoothness weight; it carries the shape into regions the photos do not constrain
   */
  void
  setSmoothnessWeight (double lambda1);

  /** \brief Fixes lambda_2 and the kind of Lambda (>= 0); without it, lambda_2 is chosen from the data
   *  (ShapePriorSelection with setLandmarkNoise).
   *  \param[in] lambda2 the weight of the shape regulariser
   *  \param[in] prior Lambda: coefficients penalised in mm or in prior standard deviations
   */
  void
  setShapePriorWeight (double lambda2, ShapePrior prior = ShapePrior::inverse_std_dev);

  /** \brief The landmarks' noise in pixels (one standard deviation per coordinate; finite and > 0,
   *  kDefaultLandmarkNoise): what the data-chosen shape prior starts from. Leaves lambda_2 to the data.
   *  \param[in] pixels the noise
   */
  void
  setLandmarkNoise (double pixels);

  /** \brief After every step each shape coefficient is clamped to +-\a sigmas prior standard deviations (> 0, or
   *  infinity for no limit; kDefaultCoefficientLimit).
   *  \param[in] sigmas the clamp in prior standard deviations
   */
  void
  setCoefficientLimit (double sigmas);

  /** \brief Weight of each landmark's rows relative to one outline point (> 0, kDefaultLandmarkWeight).
   *  \param[in] weight the landmark weight
   */
  void
  setLandmarkWeight (double weight);

  /** \brief How the outline landmarks (isOutlineLandmarkId) are used, and their rows' weight (>= 0; default:
   *  OutlineLandmarkMode::outline at kDefaultLandmarkWeight). They mark where the surface turns away from the
   *  camera, which moves with the head's shape and pose: by default the model's outline near the landmark's vertex
   *  passes through the mark; OutlineLandmarkMode::vertex pins the vertex (photos simulated by projecting fixed
   *  vertices); OutlineLandmarkMode::ignored leaves them out (listed in PhotoFit::ignored_landmarks).
   *  \param[in] mode how they are used
   *  \param[in] weight their rows' weight
   */
  void
  setOutlineLandmarks (OutlineLandmarkMode mode, double weight = kDefaultLandmarkWeight);

  /** \brief Weight of the rows that pull the profile line of an orthographic side view into the sagittal plane
   *  (>= 0, kDefaultSagittalWeight; the profile fit and TPS-ICP of the orthographic pair need > 0: nothing else
   *  fixes X there). They assume the head in the photos is turned and tilted by nothing, only nodding: for a turned
   *  or tilted head, set 0 and let the landmarks fix X.
   *  \param[in] weight the sagittal rows' weight
   */
  void
  setSagittalWeight (double weight);

  /** \brief Model outline points farther than this (model mm, in the image) from a traced outline have no row
   *  (> 0, default 20).
   *  \param[in] millimetres the largest outline distance of a correspondence (model mm)
   */
  void
  setMaxCorrespondenceDistance (double millimetres);

  /** \brief Iteration budgets of the similarity and the shape stage (>= 0 each; default 20 and 30).
   *  \param[in] similarity the similarity stage's iterations
   *  \param[in] shape the shape stage's iterations
   */
  void
  setIterations (int similarity, int shape);

  /** \brief Fits \a views with \a method: estimates the missing cameras (MultiViewProblem::estimateCameras),
   *  chooses the prior and fits. Throws
   *  InvalidInputError naming the problem for views the method cannot fit (MultiViewProblem, the method).
   *  \param[in] views the photos
   *  \param[in] method the fitting method
   *  \return the fit
   */
  PhotoFit
  fit (std::vector<PhotoView> views, const PhotoFitMethod& method) const;

  /** \brief fit() with the registered method \a method ("profile", "joint", "tps"; photoFitMethodNames).
   *  \param[in] views the photos
   *  \param[in] method the method's name
   *  \return the fit
   */
  PhotoFit
  fit (std::vector<PhotoView> views, const std::string& method) const;

  /** \brief The profile fit of the orthographic pair's profile photo alone (docs/method.md, "Profile fit"); the
   *  frontal photo's landmarks, when given, only validate the prior.
   *  \param[in] profile the profile photo's silhouette
   *  \param[in] frontal the frontal photo's landmarks, or null
   *  \return the fit
   */
  PhotoFit
  fitProfile (const ProfileView& profile, const FrontalView* frontal = nullptr) const;

  /** \brief Approach 1 on the orthographic pair: the profile and the frontal landmarks in one Gauss-Newton.
   *  \param[in] profile the profile photo's silhouette
   *  \param[in] frontal the frontal photo's landmarks
   *  \return the fit
   */
  PhotoFit
  fitJoint (const ProfileView& profile, const FrontalView& frontal) const;

  /** \brief Approach 2 (TPS-ICP) on the orthographic pair.
   *  \param[in] profile the profile photo's silhouette
   *  \param[in] frontal the frontal photo's landmarks
   *  \return the fit
   */
  PhotoFit
  fitTpsIcp (const ProfileView& profile, const FrontalView& frontal) const;

private:
  MorphableModel::ConstPtr model_;
  PhotoFitSettings settings_;
  std::optional<double> fixed_prior_; ///< lambda_2 when set, else chosen from the data
  double landmark_noise_ = kDefaultLandmarkNoise;
};
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file two_view_fitting.h
 *  \brief Fitting a morphable model to a profile and a frontal photo under orthographic projection
 *  (docs/method.md, "Fitting to two orthogonal photographs": the profile fit, approach 1 "joint" and approach 2
 *  "TPS-ICP").
 */
#include <morphreg/model/morphable_model.h>
#include <morphreg/photo/frontal_view.h>
#include <morphreg/photo/profile_view.h>
#include <morphreg/photo/two_view_fit.h>
#include <morphreg/registration/pose_shape_least_squares.h>

#include <memory>

namespace morphreg
{
/** \brief Fits X = s R (mu + M m) + t to two photos in the normalised photo frame (PhotoNormalisation): the frontal
 *  photo is the projection along Z onto (X, Y), the profile photo the projection along X onto (Z, Y) with the face
 *  looking to +Z, i.e. to the right of the image. Model axes as the built-in heads: +Y up, +Z out of the face, +X
 *  the subject's left, the sagittal plane x = 0. Both photos must show the head at the same size relative to their
 *  longer side (one similarity maps the model into both).
 *
 *  Rows (each weighted by 1 / s^2 of the iteration, so residuals count in model millimetres and the priors weigh as
 *  in MorphableICP): every profile-line vertex whose projection lies within setMaxCorrespondenceDistance of the
 *  silhouette pulls (Z, Y) to the closest point of the polyline and, with setSagittalWeight, X to the sagittal
 *  plane X = 0 (docs/method.md, "Profile fit"; the nose tip, which centres the frame, is on it); every frontal
 *  landmark pulls (X, Y) to its marked position with setFrontalWeight (its depth row is dropped). Gauss-Newton over
 *  (log s, rotation, t) to convergence, then with the shape coefficients under the prior
 *  lambda_1^2 |Gamma m|^2 + lambda_2^2 |Lambda m|^2 (as MorphableICP). lambda_1 > 0 is required: regions the
 *  photos do not constrain (ears, eyes, cheeks) follow their neighbours through Gamma.
 *
 *  \code
 *  morphreg::TwoViewFitting fitting (model);                 // model with a profile line and landmarks
 *  morphreg::TwoViewFit fit = fitting.fitJoint (morphreg::loadProfileView ("side.json"),
 *                                               morphreg::loadFrontalView ("front.json"));
 *  morphreg::saveTriangleMesh ("head.ply", fit.model_mesh);   // mm, model frame
 *  \endcode
 */
class TwoViewFitting
{
public:
  using Ptr = std::shared_ptr<TwoViewFitting>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const TwoViewFitting>; ///< shared pointer to const

  /** Components fitted per region unless setComponentSelection says otherwise. */
  static constexpr int kDefaultComponents = 20;
  static constexpr double kDefaultSmoothnessWeight = 0.5; ///< default lambda_1 (setSmoothnessWeight)
  static constexpr double kDefaultShapePriorWeight = 0.3; ///< default lambda_2 (setShapePriorWeight)
  static constexpr double kDefaultCoefficientLimit = 3.0; ///< default coefficient clamp in sigmas (setCoefficientLimit)
  static constexpr double kDefaultFrontalWeight = 0.5;    ///< default frontal landmark weight (setFrontalWeight)
  static constexpr double kDefaultSagittalWeight = 1.0;   ///< default sagittal row weight (setSagittalWeight)

  /** \brief Selects kDefaultComponents per region (or all a region has). Throws InvalidInputError for a null model,
   *  one without a profile line (MorphableModel::setProfileLine) or without a nose_tip landmark.
   *  \param[in] model the model fitted (mm), with a profile line and landmarks
   */
  explicit TwoViewFitting (MorphableModel::ConstPtr model);

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

  /** \brief lambda_2 and the kind of Lambda (>= 0; kDefaultShapePriorWeight with inverse standard deviations).
   *  \param[in] lambda2 the weight of the shape regulariser
   *  \param[in] prior Lambda: coefficients penalised in mm or in prior standard deviations
   */
  void
  setShapePriorWeight (double lambda2, ShapePrior prior = ShapePrior::inverse_std_dev);

  /** \brief After every step each shape coefficient is clamped to +-\a sigmas prior standard deviations, so a fit
   *  never leaves the model's range however the photos pull (> 0, or infinity for no limit;
   *  kDefaultCoefficientLimit).
   *  \param[in] sigmas the clamp in prior standard deviations
   */
  void
  setCoefficientLimit (double sigmas);

  /** \brief Weight of each frontal landmark's two rows relative to one profile correspondence (> 0,
   *  kDefaultFrontalWeight).
   *  \param[in] weight the frontal landmark weight
   */
  void
  setFrontalWeight (double weight);

  /** \brief Weight of the frontal landmarks that are points of the photo's outline (isFrontalContourLandmarkId:
   *  jaw, chin, neck, head contour) rather than fixed points of the face (>= 0; default 0: they are left out and
   *  listed in TwoViewFit::ignored_landmarks). The outline crosses the face where its surface turns away from the
   *  camera, which moves with the head's shape and pose, so pinning it to one model vertex pulls the fit (on
   *  photos of MediaPipe's face the chin's mark lies 4 mm below ICT's chin vertex).
   *  \param[in] weight the outline landmarks' weight, 0 to leave them out
   */
  void
  setContourLandmarkWeight (double weight);

  /** \brief Weight of the profile rows that pull X to the sagittal plane (>= 0, kDefaultSagittalWeight: one
   *  equation per profile point as in docs/method.md, "Profile fit"; the profile fit and TPS-ICP need > 0: nothing
   *  else fixes X there). They assume the head in the photos is turned and tilted by nothing, only nodding (a
   *  rotation about X keeps the plane X = 0): for a turned or tilted head, set 0 for fitJoint and let the frontal
   *  landmarks fix X (on 3 synthetic heads turned and tilted by 3 degrees the vertex RMS is 1.25 mm with 0,
   *  4.80 mm with 1).
   *  \param[in] weight the sagittal rows' weight
   */
  void
  setSagittalWeight (double weight);

  /** \brief Profile-line vertices farther than this (model mm, in the image) from the silhouette have no
   *  correspondence (> 0, default 20).
   *  \param[in] millimetres the largest silhouette distance of a correspondence (model mm)
   */
  void
  setMaxCorrespondenceDistance (double millimetres);

  /** \brief Iteration budgets of the similarity and the shape stage (>= 0 each; default 20 and 30).
   *  \param[in] similarity the similarity stage's iterations
   *  \param[in] shape the shape stage's iterations
   */
  void
  setIterations (int similarity, int shape);

  /** \brief Fits the profile alone (docs/method.md, "Profile fit"). Throws InvalidInputError when the sagittal
   *  weight is 0 or too few profile-line vertices find the silhouette.
   *  \param[in] profile the profile photo's silhouette (normalised photo frame)
   *  \return the fitted similarity, coefficients, meshes, residuals and iteration history
   */
  TwoViewFit
  fitProfile (const ProfileView& profile) const;

  /** \brief Approach 1: the profile and the frontal landmarks in one Gauss-Newton. Throws InvalidInputError for a
   *  frontal landmark the model does not have (named), fewer than 3 frontal landmarks, or landmarks that are
   *  coincident or collinear in the photo.
   *  \param[in] profile the profile photo's silhouette (normalised photo frame)
   *  \param[in] frontal the frontal photo's named landmarks (normalised photo frame)
   *  \return the fitted similarity, coefficients, meshes, residuals and iteration history
   */
  TwoViewFit
  fitJoint (const ProfileView& profile, const FrontalView& frontal) const;

  /** \brief Approach 2 (TPS-ICP): the profile fit, then rounds of: warp the posed model by a 3D thin plate spline
   *  that moves the frontal landmark vertices to their marked (X, Y) at their current depth, and fit the model to the
   *  warped mesh (every vertex a row, together weighing as much as the image rows) and to the profile rows and the
   *  landmark targets at their own weights, for up to 10 rounds while
   *  the joint fit's image residuals (profile and landmarks together) decrease and the head stays plausible
   *  (isPlausibleShape); returns the best round. The history holds the profile fit's iterations, then one entry per
   *  round. Throws as fitProfile and fitJoint.
   *  \param[in] profile the profile photo's silhouette (normalised photo frame)
   *  \param[in] frontal the frontal photo's named landmarks (normalised photo frame)
   *  \return the best round's fit: similarity, coefficients, meshes, residuals and history
   */
  TwoViewFit
  fitTpsIcp (const ProfileView& profile, const FrontalView& frontal) const;

private:
  /** Both fits: without \a frontal the profile alone. */
  TwoViewFit
  fit (const ProfileView& profile, const FrontalView* frontal) const;

  MorphableModel::ConstPtr model_;
  PoseShapeSettings settings_; ///< components, priors and coefficient limit; costs in model units
  double frontal_weight_ = kDefaultFrontalWeight;
  double contour_weight_ = 0.0;
  double sagittal_weight_ = kDefaultSagittalWeight;
  double max_distance_ = 20.0;
  int similarity_iterations_ = 20;
  int shape_iterations_ = 30;
};
} // namespace morphreg

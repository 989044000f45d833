// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file multi_view_problem.h
 *  \brief The one problem every photo fitting method works over (docs/method.md, "Fitting to photographs"): the
 *  model X = s R (mu + M m) + t seen by any number of cameras, each photo contributing landmark rows (a vertex on
 *  its mark), outline-landmark rows (the model's outline through the mark) and outline rows (the model's outline on
 *  the traced one along the face, inside it elsewhere), linearised into PoseShapeLeastSquares rows in model
 *  millimetres.
 */
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/model/morphable_model.h>
#include <morphreg/photo/photo_fit.h>
#include <morphreg/photo/photo_view.h>
#include <morphreg/photo/polyline_2d.h>
#include <morphreg/fitting/pose_shape_least_squares.h>

#include <memory>
#include <optional>
#include <vector>

namespace morphreg
{
/** \brief How the outline landmarks (isOutlineLandmarkId: jaw, chin, neck, head contour) are used. */
enum class OutlineLandmarkMode
{
  outline, ///< the model's outline near the landmark's vertex passes through the mark (the default)
  vertex,  ///< the landmark's vertex lies on the mark (photos simulated by projecting fixed vertices)
  ignored  ///< left out (listed in PhotoFit::ignored_landmarks)
};

/** \brief The settings of a photo fit (PhotoFitting's setters document each). */
struct PhotoFitSettings
{
  PoseShapeSettings shape;      ///< components, lambda_1, lambda_2, coefficient limit
  double landmark_weight = 0.5; ///< each landmark's rows
  OutlineLandmarkMode outline_landmarks = OutlineLandmarkMode::outline; ///< how outline landmarks are used
  double outline_landmark_weight = 0.5;                                 ///< each outline landmark's row
  double sagittal_weight = 1.0;   ///< profile-line rows pulling X to the sagittal plane (orthographic side views)
  double max_distance = 20.0;     ///< model mm: outline points farther from the traced outline get no row
  int similarity_iterations = 20; ///< Gauss-Newton iterations of the similarity stage
  int shape_iterations = 30;      ///< and of the shape stage
};

/** \brief What rows a fit uses: the traced outlines alone (the profile fit) or everything. */
enum class PhotoRows
{
  outlines,
  all
};

/** \brief What a row of MultiViewProblem::rows stands for. */
enum class PhotoRowKind : char
{
  landmark,         ///< a landmark's vertex on its mark
  outline,          ///< a model outline point on (or inside) a traced outline
  outline_landmark, ///< the model's outline through an outline landmark
  depth             ///< a profile-line vertex in the sagittal plane (orthographic side views)
};

/** \brief The photos of one head, their cameras and the model, as one least-squares problem.
 *
 *  The views' common frame is the cameras' frame when cameras are given, the model's frame (the mean head) when
 *  every camera is estimated, and the normalised photo frame for the orthographic pair. Image residuals count in
 *  model millimetres (pixels over the pixels per model millimetre at the head), so the priors weigh as in
 *  MorphableICP. The traced outlines are split into the face (the front of the head and neck below the brows, and up
 *  to where the outline leaves the skull: the user's hairline mark, or where the outline steps out of the fitted
 *  model, hairStarts)
 *  with two-sided rows, and the rest (hair, ears, neck) with one-sided rows that only pull a model point lying
 *  outside the outline.
 */
class MultiViewProblem
{
public:
  using Ptr = std::shared_ptr<MultiViewProblem>; ///< shared pointer

  /** Model mm: hair begins where the outline lies more than kHairGap outside the fitted model having risen by more
   *  than kHairStep within the last kHairRise of outline (a step: a skull larger than the model rises slowly), or
   *  anywhere more than kHairMax outside it. */
  static constexpr double kHairGap = 3.0;
  static constexpr double kHairStep = 2.5;  ///< model mm (kHairGap)
  static constexpr double kHairRise = 10.0; ///< model mm of outline (kHairGap)
  static constexpr double kHairMax = 8.0;   ///< model mm (kHairGap)

  /** \brief Validates \a views against \a model (landmark ids the model has, enough data) and takes every camera
   *  a view has; views without one get cameras estimated later (estimateCameras). Throws InvalidInputError
   *  naming the view for a landmark the model lacks, and for no view at all.
   *  \param[in] model the model (with a profile line and a nose_tip landmark)
   *  \param[in] views the photos
   *  \param[in] settings the fit's settings
   */
  MultiViewProblem (MorphableModel::ConstPtr model, std::vector<PhotoView> views, const PhotoFitSettings& settings);

  /** \brief Throws InvalidInputError for a null model, one without a profile line (MorphableModel::setProfileLine)
   *  or without a nose_tip landmark: what every photo fit needs.
   *  \param[in] model the model
   *  \return the model
   */
  static const MorphableModel&
  requireFittable (const MorphableModel::ConstPtr& model);

  /** \brief The model.
   *  \return the model fitted
   */
  const MorphableModel&
  model () const
  {
    return *model_;
  }

  /** \brief The settings.
   *  \return the settings given to the constructor (the shape prior as set by setPriorWeight)
   */
  const PhotoFitSettings&
  settings () const
  {
    return settings_;
  }

  /** \brief Replaces lambda_2 (the shape prior chosen from the data).
   *  \param[in] weight lambda_2 (>= 0)
   */
  void
  setPriorWeight (double weight);

  /** \brief The number of views.
   *  \return views
   */
  size_t
  numViews () const
  {
    return views_.size ();
  }

  /** \brief The landmarks that fix model vertices, over all views (the ones a fit can leave out).
   *  \return their number
   */
  int
  numLandmarks () const;

  /** \brief Whether any view has a traced outline.
   *  \return true if one has
   */
  bool
  hasOutline () const;

  /** \brief Model millimetres per pixel of view \a view at the head of \a state: what one pixel of landmark noise
   *  is worth in the fit's units.
   *  \param[in] view the view
   *  \param[in] state a fit state
   *  \return mm per pixel
   */
  double
  millimetresPerPixel (size_t view, const PoseShapeState& state) const;

  /** \brief Estimates the camera of every view that came without one from its landmarks on the mean head at the
   *  start (initialState: the given cameras' frame, or the model's when every camera is estimated), by
   *  perspective-n-point with the focal length from EXIF or searched within FocalRange. The cameras are not
   *  re-estimated on the fitted head: on james's two photos each round of that made the fit worse (0.84x the mean
   *  head's face median, 0.92x after one round, 0.98x after two), the cameras taking up what the shape should.
   *  Throws InvalidInputError naming the view when it has too few landmarks for it.
   */
  void
  estimateCameras ();

  /** \brief The start of every fit: the pose from the landmarks (and the outline's size for a profile fit without
   *  them), the mean shape.
   *  \return the state
   */
  PoseShapeState
  initialState () const;

  /** \brief The similarity stage, then the shape stage, then (when the outlines' hairlines moved) the shape stage
   *  again, with the rows of \a rows; landmarks flagged in \a left_out are not fitted (leave-out validation). Each
   *  iteration's residuals are appended to \a history.
   *  \param[in,out] state the start, replaced by the fit
   *  \param[in] rows what is fitted
   *  \param[in] left_out per landmark (numLandmarks() flags, or empty): left out of the fit
   *  \param[in] history the iterations so far (appended to)
   */
  void
  fitStages (PoseShapeState& state, PhotoRows rows, const std::vector<bool>& left_out,
             std::vector<PhotoFitIteration>& history);

  /** \brief The similarity stage of fitStages (the mean head posed by the data).
   *  \param[in,out] state the start, replaced by the fit
   *  \param[in] rows what is fitted
   *  \param[in] left_out per landmark: left out, or empty
   *  \param[in] history the iterations so far (appended to)
   */
  void
  poseStage (PoseShapeState& state, PhotoRows rows, const std::vector<bool>& left_out,
             std::vector<PhotoFitIteration>& history);

  /** \brief The shape stages of fitStages.
   *  \param[in,out] state the start, replaced by the fit
   *  \param[in] rows what is fitted
   *  \param[in] left_out per landmark: left out, or empty
   *  \param[in] history the iterations so far (appended to)
   *  \param[in] budget the iterations of each shape stage (< 0: the settings')
   */
  void
  shapeStages (PoseShapeState& state, PhotoRows rows, const std::vector<bool>& left_out,
               std::vector<PhotoFitIteration>& history, int budget = -1);

  /** \brief The model vertex of each landmark that fixes one (numLandmarks() of them, in the order of the
   *  left-out flags).
   *  \return the vertices
   */
  std::vector<int>
  landmarkVertices () const;

  /** \brief fitStages from \a start, as a PhotoFit that says it returned \a returned.
   *  \param[in] start the state to begin with
   *  \param[in] rows what is fitted
   *  \param[in] returned what the result is called ("profile", "joint")
   *  \return the fit with its history
   */
  PhotoFit
  stagedFit (const PoseShapeState& start, PhotoRows rows, const std::string& returned);

  /** \brief The rows at \a state (fixed while one Gauss-Newton step is taken) and their residuals.
   *  \param[in] state the current state (every model vertex)
   *  \param[in] rows what is fitted
   *  \param[in] left_out per landmark: left out, or empty
   *  \param[out] residuals the residuals of the rows
   *  \param[out] kinds what each row stands for (if not null)
   *  \return the rows, their slots model vertex indices
   */
  std::vector<PoseShapeRow>
  rows (const PoseShapeState& state, PhotoRows rows, const std::vector<bool>& left_out, PhotoFitIteration& residuals,
        std::vector<PhotoRowKind>* kinds = nullptr) const;

  /** \brief The image rows' weighted mean squared residual (model mm^2) in \a residuals: the error that image-driven
   *  loops (TPS-ICP's rounds) watch.
   *  \param[in] residuals the residuals of rows (state, PhotoRows::all, ...)
   *  \return the error
   */
  double
  imageError (const PhotoFitIteration& residuals) const;

  /** \brief Whether a Gauss-Newton loop has converged: the model's vertices moved by less than 1e-6 mm^2 (mean
   *  square, model units) from \a before to \a after.
   *  \param[in] before the posed vertices before the step
   *  \param[in] after the state after it
   *  \return true once converged
   */
  static bool
  converged (const Eigen::Matrix3Xd& before, const PoseShapeState& after);

  /** \brief Whether any view has a pinhole camera.
   *  \return true if one has
   */
  bool
  hasPerspectiveCamera () const;

  /** \brief RMS in-image distance (model mm) of the landmarks flagged in \a which at \a state.
   *  \param[in] state a fit state
   *  \param[in] which per landmark (numLandmarks() flags)
   *  \return the RMS, 0 if none is flagged
   */
  double
  landmarkError (const PoseShapeState& state, const std::vector<bool>& which) const;

  /** \brief The solver over every model vertex with the settings' components (or none: the similarity only).
   *  \param[in] shape false for the similarity-only solver
   *  \return the solver
   */
  const PoseShapeLeastSquares&
  solver (bool shape) const
  {
    return shape ? *shape_solver_ : *pose_solver_;
  }

  /** \brief \a state as a PhotoFit: similarity, coefficients, meshes, the residuals of \a rows and the views'
   *  cameras and constraints.
   *  \param[in] state the fitted state
   *  \param[in] rows what was fitted (for the final residuals)
   *  \return the fit (method, history and prior left for the caller)
   */
  PhotoFit
  result (const PoseShapeState& state, PhotoRows rows) const;

  /** \brief Throws InvalidInputError unless at least 3 landmarks fix model vertices, spread out in every photo
   *  that has 3 or more (a fit to landmarks needs them).
   */
  void
  requireLandmarks () const;

  /** \brief The outline landmarks left out (OutlineLandmarkMode::ignored), for the report.
   *  \return their ids
   */
  const std::vector<std::string>&
  ignoredLandmarks () const
  {
    return ignored_;
  }

  /** \brief Frees the problem. */
  ~MultiViewProblem ();

private:
  /** A landmark that fixes a model vertex. */
  struct Landmark
  {
    size_t view;           ///< the view it was marked in
    int vertex;            ///< the model vertex
    Eigen::Vector2d pixel; ///< the mark
    double weight;         ///< the row weight
  };

  /** An outline landmark: the model's outline near \a vertex passes through \a pixel. */
  struct OutlineLandmark
  {
    int vertex;              ///< the model vertex the landmark names
    Eigen::Vector2d pixel;   ///< the mark
    std::vector<int> nearby; ///< model vertices within kOutlineLandmarkRadius of it (mean shape)
    bool two_sided;          ///< on the face: the outline passes through the mark, else it may lie inside
  };

  /** A view, its camera and its outline. */
  struct ViewData
  {
    explicit ViewData (PhotoView photo) : view (std::move (photo)) {}

    PhotoView view;
    std::optional<PhotoCamera> camera; ///< given, or estimated (estimateCameras)
    bool estimated = false;            ///< the camera was estimated
    std::string focal_source;          ///< for an estimated camera
    double camera_rms = 0.0;           ///< for an estimated camera: reprojection RMS (px)
    int landmarks = 0;                 ///< fixed-vertex landmarks of this view
    std::vector<OutlineLandmark> outline_landmarks;
    std::optional<Polyline2d> outline; ///< the traced outline
    std::vector<char> two_sided;       ///< per outline point: on the face
    Eigen::Index hairline = -1;        ///< the outline point nearest the user's hairline mark, or -1
  };

  /** Model mm: the model vertices near an outline landmark's vertex where the outline may pass. */
  static constexpr double kOutlineLandmarkRadius = 25.0;

  /** The model vertices that may lie on a view's traced outline at one state, and their pixels. */
  struct ViewOutline
  {
    std::vector<int> vertices; ///< the profile line (a side view) or the silhouette's contour vertices
    Eigen::Matrix2Xd pixels;   ///< their projections
    bool side;                 ///< the camera looks at the model's side: the profile line is the outline
  };

  /** Squared residuals (model mm^2) and counts of one set of rows. */
  struct RowSums
  {
    double outline = 0.0, landmark = 0.0, outline_landmark = 0.0;
    int outline_count = 0, inside = 0, landmark_count = 0, outline_landmark_count = 0;
    std::vector<PhotoRowKind> kinds; ///< per row added
  };

  void
  computeFaceZone ();

  void
  addView (PhotoView view);

  void
  addOutline (ViewData& data);

  /** Model vertices within kOutlineLandmarkRadius of \a vertex (mean shape). */
  std::vector<int>
  nearbyVertices (int vertex) const;

  /** The mean head at the identity. */
  PoseShapeState
  meanState () const;

  /** The orthographic pair's start: no rotation, the nose tip at the origin, the scale from the landmarks or the
   *  outline. */
  PoseShapeState
  orthographicStart (PoseShapeState state) const;

  double
  landmarkScale () const;

  double
  outlineScale (const Eigen::Vector3d& nose) const;

  /** The posed positions at \a state and the marks of \a view's fixed-vertex landmarks. */
  std::pair<Eigen::Matrix3Xd, Eigen::Matrix2Xd>
  viewLandmarks (size_t view, const PoseShapeState& state) const;

  /** Whether \a view's camera looks along the model's X axis at \a state. */
  bool
  isSideView (size_t view, const PoseShapeState& state) const;

  ViewOutline
  outlineCandidates (size_t view, const TriangleMesh& posed, const PoseShapeState& state) const;

  /** One stage's Gauss-Newton iterations. */
  void
  runStage (PoseShapeState& state, PhotoFitStage stage, PhotoRows rows, const std::vector<bool>& left_out,
            std::vector<PhotoFitIteration>& history, int budget) const;

  void
  addLandmarkRow (const Landmark& landmark, const Eigen::Matrix3Xd& posed, const PoseShapeState& state,
                  std::vector<PoseShapeRow>& rows, RowSums& sums) const;

  /** The outline rows of \a view (none added with \a rows null); returns the outline points matched. */
  int
  addOutlineRows (size_t view, const ViewOutline& outline, const Eigen::Matrix3Xd& posed, const PoseShapeState& state,
                  std::vector<PoseShapeRow>* rows, RowSums& sums) const;

  /** The row pulling a profile-line vertex into the plane X = 0 of an orthographic side view. */
  PoseShapeRow
  sagittalRow (int vertex, const Eigen::Vector3d& point, const PhotoCamera& camera, const PoseShapeState& state) const;

  void
  addOutlineLandmarkRows (size_t view, const TriangleMesh& posed, const PoseShapeState& state,
                          std::vector<PoseShapeRow>& rows, RowSums& sums) const;

  /** Per view: the profile-line vertices on the outline of a side view, or -1. */
  std::vector<int>
  profileLineMatches (const PoseShapeState& state) const;

  /** Throws InvalidInputError when a side view's outline holds less than a quarter of the profile line. */
  void
  requireOutlineMatch (const PoseShapeState& state) const;

  /** Labels each outline point of every view as face (two-sided) or not from \a state: the conservative face
   *  zone (below the brows, in front of the ears), cut at the user's hairline mark. */
  void
  resetOutlineLabels (const PoseShapeState& state);

  /** Extends the face labels along the outlines until they leave the fitted model (hairStarts) or reach the user's
   *  mark; returns whether a label changed. */
  bool
  extendFaceLabels (const PoseShapeState& state);

  /** Whether the outline leaves the skull at point \a k, walking in \a direction (kHairGap). */
  static bool
  hairStarts (const std::vector<double>& gaps, const std::vector<double>& along, Eigen::Index k, int direction);

  /** Whether outline point \a k lies beyond the user's hairline mark, on the hair's side. */
  bool
  beyondHairline (const ViewData& data, Eigen::Index k) const;

  /** Per outline point of \a view: how far (model mm) it lies outside the model's nearest outline point. */
  std::vector<double>
  outlineGaps (size_t view, const TriangleMesh& posed, const PoseShapeState& state) const;

  MorphableModel::ConstPtr model_;
  PhotoFitSettings settings_;
  MeshTopology topology_;
  std::vector<ViewData> views_;
  std::vector<Landmark> landmarks_; ///< every fixed-vertex landmark of every view (view, vertex, pixel)
  std::vector<std::string> ignored_;
  std::vector<char> face_zone_; ///< per model vertex: below the brows, in front of the ears
  std::unique_ptr<PoseShapeLeastSquares> shape_solver_, pose_solver_;
};
} // namespace morphreg

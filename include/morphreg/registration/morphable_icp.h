// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file morphable_icp.h
 *  \brief ICP with shape parameters (docs/method.md, "ICP with shape parameters"): registers a scan to a
 *  MorphableModel by a similarity [sR | t] and the model's shape coefficients, as a pcl::Registration.
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/model/morphable_model.h>
#include <morphreg/registration/correspondence_rejection_normal_compatibility.h>
#include <morphreg/registration/correspondence_rejection_target_boundary.h>
#include <morphreg/registration/initial_alignment_strategy.h>
#include <morphreg/registration/morphable_convergence.h>
#include <morphreg/fitting/pose_shape_least_squares.h>
#include <morphreg/registration/registration_report.h>
#include <morphreg/registration/kernels/tukey_kernel.h>
#include <morphreg/registration/robust_kernel.h>
#include <morphreg/registration/target_surface.h>

#include <pcl/PolygonMesh.h>
#include <pcl/point_types.h>
#include <pcl/registration/registration.h>

#include <memory>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

namespace morphreg
{
/** \brief One phase of the shape stage: the components fitted and the weights lambda_1 (smoothness) and lambda_2
 *  (shape regulariser) used. */
struct ShapePhase
{
  ComponentSelection components;  ///< per region at most the counts of MorphableICP::getComponentSelection()
  double smoothness_weight = 1.0; ///< lambda_1 of this phase (>= 0)
  /** lambda_2 of this phase (>= 0); unset: MorphableICP::setShapePriorWeight's. A strong prior while the
   *  correspondences settle and a weak one once they have lets many components fit a scan's detail. */
  std::optional<double> prior_weight = std::nullopt;
};

/** \brief MorphableICP's defaults, which are also the command line's (RegistrationSettings{} and `morphreg register`
 *  start from them), so that a program that only sets the model and the target fits as the command line does. */
struct MorphableIcpDefaults
{
  static constexpr int iterations = 100;            ///< setMaximumIterations: both stages together
  static constexpr int similarity_iterations = 60;  ///< setSimilarityIterations
  static constexpr int components_per_region = 60;  ///< setModel selects every component up to this many per region
  static constexpr bool point_to_plane = true;      ///< setPointToPlane
  static constexpr double tangential_weight = 0.02; ///< setPointToPlane's tangential weight
  static constexpr double shape_prior = 3.0;        ///< setShapePriorWeight's lambda_2
  static constexpr double landmark_weight = 0.0;    ///< setTargetLandmarks: landmarks only place the start
};

namespace detail
{
/** \brief The Scalar of MorphableICP<PointTarget, Scalar>, checked: a wrong argument fails here with a plain message
 *  instead of deep inside pcl::Registration (and the base is then built with float, so that no more errors
 *  follow). */
template <typename PointTarget, typename Scalar>
struct MorphableIcpScalar
{
  static constexpr bool point_ok = pcl::traits::has_xyz_v<PointTarget>; ///< whether PointTarget has x, y, z
  /** whether Scalar is float or double */
  static constexpr bool scalar_ok = std::is_same_v<Scalar, float> || std::is_same_v<Scalar, double>;
  static_assert (point_ok, "MorphableICP<PointTarget, Scalar>: PointTarget, the scan's point type, must have x, y, z "
                           "(e.g. pcl::PointNormal or pcl::PointXYZ)");
  static_assert (scalar_ok, "MorphableICP<PointTarget, Scalar>: the second template argument is the scalar (float or "
                            "double), not a point type: the source is the model (setModel), so write "
                            "MorphableICP<pcl::PointNormal> or MorphableICP<pcl::PointXYZ>");
  using type = std::conditional_t<scalar_ok, Scalar, float>; ///< Scalar, or float after a failed check
};
} // namespace detail

/** \brief ICP with shape parameters: fits s R (mu_i + M_i m) + t to a target cloud by Gauss-Newton over
 *  (log s, rotation as an exponential-map update, t, m), first similarity-only to convergence, then with shape in
 *  the phases of setShapeSchedule (default: two phases with lambda_1 = 0.1). One update moves no shape coefficient
 *  by more than 3 prior standard deviations (a trust region against the first, still sliding correspondences), and
 *  a coefficient update that reverses the previous one is halved (the correspondences of a region over a scan hole
 *  can otherwise flip between two sets, and the shape between two states, until the iterations run out).
 *
 *  It is a pcl::Registration whose source is the model instance (as PointTarget points: PCL 1.13's Registration and
 *  CorrespondenceEstimation do not compile for different source and target point types). The model is set with
 *  setModel (setInputSource throws InvalidInputError: the source is the model's), the scan with setInputTarget, in
 *  mm. Every fit runs in computeTransformation, so align() through a pcl::Registration pointer is the same fit with
 *  the same checks. The defaults are the command line's (MorphableIcpDefaults: 100 iterations, point-to-plane rows,
 *  every component up to 60 per region), and the base settings work as for pcl::IterativeClosestPoint:
 *  setMaximumIterations (total over both stages), setMaxCorrespondenceDistance, setTransformationEpsilon (here: mean
 *  squared vertex motion of one update, mm^2; 0 means 1e-4), setEuclideanFitnessEpsilon (absolute change of the
 *  cost per row between iterations, mm^2), addCorrespondenceRejector (every rejector, in order, each iteration; a
 *  chain added replaces the default chain, which is getTargetBoundaryRejector when setRejectTargetBoundary is on),
 *  setCorrespondenceEstimation (default CachedCorrespondenceEstimation: PCL's nearest-neighbour correspondences with
 *  parallel, mostly cached queries, on the Registration's k-d tree, built once per target; estimations that need
 *  source normals, such as CorrespondenceEstimationNormalShooting, get the model's vertex normals),
 *  setSearchMethodTarget and registerVisualizationCallback (called each iteration with the deformed model in the
 *  target frame and the accepted correspondences). The pcl::Registration settings this class has no use for are
 *  refused, not ignored: align() throws InvalidInputError naming the setter after setTransformationEstimation (pose
 *  and shape come from one Gauss-Newton step), setRANSACIterations, setRANSACOutlierRejectionThreshold,
 *  setTransformationRotationEpsilon, setSearchMethodSource, setIndices or setPointRepresentation (the distances are
 *  in x, y, z).
 *
 *  The target must be in mm: a target whose size says it is in another unit (guessLengthUnit against the model:
 *  cm, m or inches) is refused with an InvalidInputError that names the unit; convert it first, e.g. with
 *  convertScanToMillimetres (pipeline/scan_units.h).
 *
 *  computeTransformation is PCL's ICP loop: per phase (the similarity stage, then each shape phase) and iteration,
 *  correspondences (their distances measured to the TargetSurface's smoothed points), the rejector chain, IRLS
 *  weights (a RobustKernel, robust_kernel.h), one PoseShapeLeastSquares step, and a MorphableConvergence that ends the phase
 *  (budget, motion and fitness epsilons, divergence rules). Too few correspondences follow requireEnoughRows. The
 *  cost is
 *  sum_i w_i |r_i|^2_W + landmark_weight sum_l |r_l|^2 + lambda_1^2 |Gamma m|^2 + lambda_2^2 |Lambda m|^2,
 *  with W the identity (point-to-point) or n n^T + tangential_weight (I - n n^T) (point-to-plane).
 *
 *  getFinalTransformation() is the similarity [sR | t]; align()'s output holds the fitted model vertices in the
 *  target frame (with vertex normals for point types that have normals). The fitness score is PCL's, a mean squared
 *  distance (mm^2): over the model vertices with an accepted correspondence at the returned state, the squared
 *  distance from each to its nearest target point; getRegistrationReport() gives its root (fitness_rms, mm), mean and
 *  median. After align() the source cloud (getInputSource()) holds those vertices of the fitted shape in the model
 *  frame, so pcl::Registration::getFitnessScore(), through this class or a base pointer, gives fitness_rms^2.
 *
 *  \code
 *  morphreg::MorphableICP<pcl::PointNormal> icp;
 *  icp.setModel (model);                                   // every component, up to 60 per region, by default
 *  icp.setInputTarget (scan);                              // mm
 *  icp.setTargetLandmarks (marked);                        // optional: >= 3 start with Umeyama
 *  pcl::PointCloud<pcl::PointNormal> fitted;
 *  icp.align (fitted);                                     // identity guess: landmarks or coarse start
 *  Eigen::VectorXd sd = icp.getShapeCoefficients ();       // prior standard deviations (statismo's unit)
 *  pcl::PolygonMesh mesh = icp.getFittedMesh ();
 *  \endcode
 */
template <typename PointTarget, typename Scalar = float>
class MorphableICP
  : public pcl::Registration<PointTarget, PointTarget, typename detail::MorphableIcpScalar<PointTarget, Scalar>::type>
{
public:
  /** \brief The PCL registration it extends. */
  using Base =
      pcl::Registration<PointTarget, PointTarget, typename detail::MorphableIcpScalar<PointTarget, Scalar>::type>;
  using Ptr = std::shared_ptr<MorphableICP>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const MorphableICP>; ///< shared pointer to const
  using typename Base::Matrix4;
  using typename Base::PointCloudSource;
  using typename Base::PointCloudSourceConstPtr;
  using typename Base::PointCloudTarget;
  using typename Base::PointCloudTargetConstPtr;

  /** \brief A registration with the defaults above (MorphableIcpDefaults), CachedCorrespondenceEstimation and the
   *  target boundary and normal rejectors on its own target surface. Until setModel and setInputTarget, the source
   *  and target are placeholders, so that PCL's align(), which returns without a word when either is missing, reaches
   *  computeTransformation, which names what is missing.
   */
  MorphableICP ();

  /** \brief Not copyable: the target surface (smoothed points and normals) and the boundary rejector that reads it
   *  belong to one registration and its target; a copy would share them.
   */
  MorphableICP (const MorphableICP&) = delete;
  MorphableICP&
  operator= (const MorphableICP&) = delete;
  /** \brief Movable: the moved-from registration is left without a target surface. */
  MorphableICP (MorphableICP&&) = default;
  /** \brief Move assignment: the moved-from registration is left without a target surface.
   *  \return this registration
   */
  MorphableICP&
  operator= (MorphableICP&&) = default;

  // ---- model and shape ------------------------------------------------------------------------------------

  /** \brief Sets the model and makes its mean the source cloud; selects every component, up to
   *  MorphableIcpDefaults::components_per_region per region. Throws InvalidInputError for a null model.
   *  \param[in] model the model fitted to the target (mm)
   */
  void
  setModel (const MorphableModel::ConstPtr& model);

  /** \brief The model fitted.
   *  \return the model of setModel, or nullptr
   */
  MorphableModel::ConstPtr
  getModel () const
  {
    return model_;
  }

  /** \brief The components fitted in the shape stage (validated against the model).
   *  \param[in] selection the number of components per region
   */
  void
  setComponentSelection (const ComponentSelection& selection);

  /** \brief The components fitted in the shape stage.
   *  \return the selection; the shape coefficients are stacked like it
   */
  const ComponentSelection&
  getComponentSelection () const
  {
    return selection_;
  }

  /** \brief lambda_1: weight of the smoothness prior Gamma across overlapping regions (>= 0) in the first
   *  phase of the default shape schedule (default 0.1: a strong Gamma, e.g. 1, holds a region whose coefficients
   *  must differ from its neighbours' in the overlaps, and the first phase then stalls short of the scan).
   *  \param[in] lambda1 the smoothness weight of the first phase
   */
  void
  setSmoothnessWeight (double lambda1);

  /** \brief lambda_1 of the default schedule's second (refinement) phase (>= 0; default 0.1). A larger first-phase
   *  lambda_1 keeps the regions consistent while the correspondences settle; a small one here lets each region fit
   *  its own data (region coefficients need not agree exactly in the overlaps).
   *  \param[in] lambda1 the smoothness weight of the refinement phase
   */
  void
  setRefinementSmoothnessWeight (double lambda1);

  /** \brief lambda_1 of the default schedule's first phase.
   *  \return the weight of setSmoothnessWeight
   */
  double
  getSmoothnessWeight () const
  {
    return lambda1_;
  }

  /** \brief Runs the shape stage as these phases in order, each to convergence (coarse-to-fine components,
   *  changing lambda_1); coefficients carry over between phases. Every phase's components must fit within
   *  getComponentSelection() (checked in align()). Empty (the default): two phases over the selection, with
   *  setSmoothnessWeight, then with setRefinementSmoothnessWeight.
   *  \param[in] phases the shape phases in order, or empty for the default two
   */
  void
  setShapeSchedule (std::vector<ShapePhase> phases);

  /** \brief The shape phases of setShapeSchedule.
   *  \return the phases given, empty for the default schedule
   */
  const std::vector<ShapePhase>&
  getShapeSchedule () const
  {
    return schedule_;
  }

  /** \brief The phases align() runs: setShapeSchedule's, or the default two (see setShapeSchedule).
   *  \return the shape phases in the order they run
   */
  std::vector<ShapePhase>
  effectiveShapeSchedule () const;

  /** \brief lambda_2 and Lambda: weight and kind of the shape regulariser (>= 0, default 3 with inverse standard
   *  deviations; a huge value freezes the shape).
   *  \param[in] lambda2 the weight of the shape regulariser
   *  \param[in] prior Lambda: coefficients penalised in mm or in prior standard deviations
   */
  void
  setShapePriorWeight (double lambda2, ShapePrior prior = ShapePrior::inverse_std_dev);

  /** \brief Skip the shape stage (a similarity-only ICP).
   *  \param[in] enabled false to fit the similarity only (default true)
   */
  void
  setShapeStage (bool enabled)
  {
    shape_stage_ = enabled;
  }

  /** \brief Estimate the scale (default) or keep s = 1 (a rigid ICP).
   *  \param[in] estimate false to keep s = 1
   */
  void
  setEstimateScale (bool estimate)
  {
    estimate_scale_ = estimate;
  }

  /** \brief At most this many of the iterations go to the similarity stage (default 60; at most half of them when
   *  shape phases follow).
   *  \param[in] iterations the similarity stage's budget, out of setMaximumIterations
   */
  void
  setSimilarityIterations (int iterations);

  // ---- robustness -----------------------------------------------------------------------------------------

  /** \brief Point-to-plane rows, with \a tangential_weight in [0, 1] of the point-to-point term kept along the
   *  tangent plane (0 = pure point-to-plane). Uses the target's normals, or for targets without normals (or with
   *  invalid ones) normals estimated from the k-neighbourhood of setRejectTargetBoundary.
   *  \param[in] enabled true for point-to-plane rows (the default), false for point-to-point
   *  \param[in] tangential_weight the share of the point-to-point term kept along the tangent plane
   */
  void
  setPointToPlane (bool enabled, double tangential_weight = 0.02);

  /** \brief The IRLS kernel weighing the residual distances (default Tukey's, automatic width; see
   *  robust_kernel.h, makeRobustKernel by name). InvalidInputError for a null kernel.
   *  \param[in] kernel the kernel, with its width
   */
  void
  setRobustKernel (const RobustKernel::ConstPtr& kernel);

  /** \brief The IRLS kernel.
   *  \return the kernel of setRobustKernel
   */
  RobustKernel::ConstPtr
  getRobustKernel () const
  {
    return robust_kernel_;
  }

  /** \brief With a redescending kernel (Tukey's, Cauchy's, Geman-McClure's: RobustKernel::graduatedStart), the
   *  similarity stage and every shape phase but the last use Huber weights, the last the kernel's (off by default). Tukey gives weight 0 to a region of the model still far from the scan (a higher
   *  skull, a longer chin), which is then never pulled in; Huber keeps its pull until the last phase. For scans
   *  that cover the model's surface (up to holes); not where parts of the model have no counterpart in the target
   *  (ICT-FaceKit against the fsaverage scalp: those parts then pull the fit off, from a median of 0.64 to 1.35 mm).
   *  \param[in] enabled true for Huber weights before the last phase
   */
  void
  setGraduatedRobustLoss (bool enabled)
  {
    graduated_loss_ = enabled;
  }

  /** \brief Weight each correspondence by its model vertex's share of the mean surface's area (a third of its
   *  triangles' areas, normalised to mean 1), so that the fit balances area, not vertex count. Off by default; for
   *  models with very uneven vertex density (ICT-FaceKit: a dense face, a sparse skull) against targets that cover
   *  the sparse parts too (a whole scalp).
   *  \param[in] enabled true to weight correspondences by vertex area
   */
  void
  setAreaWeighting (bool enabled)
  {
    area_weighting_ = enabled;
  }

  /** \brief Whether the default rejector chain (used when no rejector was added) holds
   *  getTargetBoundaryRejector (on by default), and the size \a neighbours of the target surface's neighbourhoods
   *  (boundary test, smoothing and estimated normals; >= 4, default 20).
   *  \param[in] enabled whether the default chain rejects target boundary points
   *  \param[in] neighbours the neighbourhood size k of the target surface
   */
  void
  setRejectTargetBoundary (bool enabled, int neighbours = 20);

  /** \brief The rejector of target boundary points on this registration's target surface (the smoothed points and
   *  normals the rows use). It is the default chain; a chain of addCorrespondenceRejector replaces the default, so
   *  add this one first to keep it: icp.addCorrespondenceRejector (icp.getTargetBoundaryRejector ()).
   *  \return the boundary rejector bound to this registration's target surface
   */
  CorrespondenceRejectorTargetBoundary::Ptr
  getTargetBoundaryRejector () const
  {
    return boundary_rejector_;
  }

  /** \brief Where the sensor of a one-view target stood (target frame and unit), which estimated target normals
   *  face; unset (the default): the origin of an organised target cloud, else none, and estimated normals face away
   *  from the target's centre (see TargetSurface::setViewpoint).
   *  \param[in] viewpoint the sensor's position, or std::nullopt
   */
  void
  setTargetViewpoint (std::optional<Eigen::Vector3d> viewpoint)
  {
    viewpoint_ = viewpoint;
    target_prepared_ = false;
  }

  /** \brief Whether the default rejector chain also holds getNormalCompatibilityRejector (on by default) and its
   *  largest angle between a model vertex's normal and its target point's (degrees, default 60).
   *  \param[in] enabled whether the default chain rejects correspondences whose normals disagree
   *  \param[in] max_angle_deg the largest angle kept (0 to 180)
   */
  void
  setRejectIncompatibleNormals (bool enabled, double max_angle_deg = 60.0);

  /** \brief The rejector of correspondences whose normals disagree, on this registration's target surface (its
   *  normals given by the scan, or estimated and turned outwards: towards the sensor of an organised cloud, else away
   *  from the scan's centre). After getTargetBoundaryRejector in the default chain; a chain of
   *  addCorrespondenceRejector replaces the default, so add both to keep them.
   *  \return the normal-compatibility rejector bound to this registration's target surface
   */
  CorrespondenceRejectorNormalCompatibility::Ptr
  getNormalCompatibilityRejector () const
  {
    return normal_rejector_;
  }

  /** \brief Residuals against each target point projected onto the least-squares plane of its neighbourhood
   *  (the k of setRejectTargetBoundary) instead of the raw point: scan noise then averages out instead of pulling
   *  the model towards the nearest noisy points. Automatic by default: on for noisy targets (depth cameras), off for
   *  clean ones, where a plane through a curved, sparsely sampled neighbourhood pulls the surface inwards (see
   *  TargetSmoothing; the report says what was decided). The k-d tree still holds the raw points, and the
   *  correspondences' distances are measured to the smoothed points before any rejector sees them.
   *  \param[in] smoothing on, off or automatic
   */
  void
  setTargetSmoothing (TargetSmoothing smoothing);

  /** \brief setTargetSmoothing with on (true) or off (false).
   *  \param[in] enabled false to use the raw target points
   */
  void
  setTargetSmoothing (bool enabled)
  {
    setTargetSmoothing (enabled ? TargetSmoothing::on : TargetSmoothing::off);
  }

  /** \brief Stop and revert to the best state when a coefficient exceeds \a max_sigma prior standard deviations
   *  (<= 0: never; default 8) or, in a shape phase, the cost per row stayed above 1.05 times the phase's best for
   *  \a rising_iterations iterations in a row (default 3). The similarity stage is not checked for a rising cost:
   *  while its correspondences settle, the IRLS weights change and its cost per row may rise on a good path.
   *  \param[in] max_sigma the coefficients' limit in prior standard deviations (<= 0: none)
   *  \param[in] rising_iterations iterations with a rising cost that count as divergence
   */
  void
  setDivergenceGuard (double max_sigma, int rising_iterations = 3);

  // ---- landmarks and initialisation -----------------------------------------------------------------------

  /** \brief Named target landmarks (model landmark name -> target point, mm), used as extra rows with weight
   *  \a weight (one landmark counts as \a weight correspondences) and for the landmark initialisation. The default,
   *  0, the command line's, uses them only for the start (hand-placed landmarks lie millimetres off the model's
   *  points); 1 suits landmarks placed with a few mm of error: heavier ones pin their vertex there and bend the
   *  small regions around it (nose, eyes) away from the scan.
   *  Throws InvalidInputError for non-finite positions, a negative weight, or (once a model is set) names the
   *  model does not have.
   *  \param[in] landmarks target position (mm, the target's frame) per model landmark name
   *  \param[in] weight how many correspondences one landmark row counts as (>= 0)
   */
  void
  setTargetLandmarks (const LandmarkPositions& landmarks, double weight = MorphableIcpDefaults::landmark_weight);

  /** \brief How the start is found (see starts/; default AutomaticStart: the guess passed to align() unless it is
   *  the identity, else the landmarks if >= 3 are set, else the global start). Throws InvalidInputError for null.
   *  \param[in] start the start, e.g. makeInitialAlignment ("coarse")
   */
  void
  setInitialAlignment (InitialAlignmentStrategy::ConstPtr start);

  /** \brief The start in force.
   *  \return the start
   */
  const InitialAlignmentStrategy::ConstPtr&
  getInitialAlignment () const
  {
    return initial_alignment_;
  }

  // ---- results --------------------------------------------------------------------------------------------

  /** \brief Shape coefficients of the last align() (stacked like getComponentSelection()) in prior standard
   *  deviations, as statismo, scalismo, BFM and eos read them (see docs/coefficients.md).
   *  \return the coefficients: each one's length divided by its component's prior standard deviation
   */
  const Eigen::VectorXd&
  getShapeCoefficients () const
  {
    return coefficients_sd_;
  }

  /** \brief Shape coefficients of the last align() as lengths: mm along the model's orthonormal components, what
   *  MorphableModel::generate takes (stacked like getComponentSelection()).
   *  \return the coefficients (mm)
   */
  const Eigen::VectorXd&
  getShapeCoefficientsMm () const
  {
    return coefficients_;
  }

  /** \brief The fitted model as a mesh in the model topology, in the target frame.
   *  \return the mesh (mm)
   */
  pcl::PolygonMesh
  getFittedMesh () const;

  /** \brief The fitted model vertices (3 x N, target frame).
   *  \return the vertices (mm)
   */
  const Eigen::Matrix3Xd&
  getFittedVertices () const
  {
    return fitted_vertices_;
  }

  /** \brief Per model vertex: distance (mm) to its accepted correspondence's point on the target surface (the
   *  smoothed point where target smoothing is on) at the returned state, NaN where it has none.
   *  \return one residual per model vertex (mm)
   */
  const Eigen::VectorXd&
  getVertexResiduals () const
  {
    return vertex_residuals_;
  }

  /** \brief What the last align() did: why it stopped, its iterations, its start and the fit quality.
   *  \return the report (fitness in mm; fitness_rms^2 is getFitnessScore())
   */
  const IcpReport&
  getRegistrationReport () const
  {
    return report_;
  }

  /** \brief Refused: the source is the model instance of setModel. Throws InvalidInputError saying so.
   *  \param[in] cloud unused
   */
  void
  setInputSource (const PointCloudSourceConstPtr& cloud) override;

  /** \brief Sets the target cloud (the scan, mm); its surface and tree are prepared again on the next align().
   *  Throws InvalidInputError for a null or empty cloud (PCL would keep the previous target).
   *  \param[in] cloud the scan (mm)
   */
  void
  setInputTarget (const PointCloudTargetConstPtr& cloud) override;

protected:
  /** \brief PCL's registration hook, run by align() through this class or a pcl::Registration pointer: validates
   *  the inputs and settings (InvalidInputError for a missing model or target, an empty target or one with
   *  non-finite points, a target not in mm, unknown landmark names, a pcl::Registration setting that is not used,
   *  or fewer correspondences than unknowns), then runs the phases of the fit.
   *  \param[out] output the fitted model vertices in the target frame
   *  \param[in] guess the start similarity, model frame to target frame (the identity: the setInitialAlignment start)
   */
  void
  computeTransformation (PointCloudSource& output, const Matrix4& guess) override;

private:
  struct Evaluation;

  /** One run of the loop: the similarity stage (no shape unknowns) or a shape phase. */
  struct Phase
  {
    bool shape = false;
    ShapePhase settings;           ///< the shape phase's components and weights
    RobustKernel::ConstPtr kernel; ///< the phase's IRLS kernel
  };

  void
  validateInputs () const;

  /** Throws InvalidInputError naming the pcl::Registration setter whose setting this class would not use. */
  void
  requireNoUnusedSettings () const;

  /** Throws InvalidInputError when the target's size says it is not in mm (guessLengthUnit against the model). */
  void
  requireMillimetreTarget () const;

  /** The starting similarity of \a guess's mode; records how it was found in the report. */
  Eigen::Matrix4d
  initialTransformation (const Matrix4& guess);

  /** Hands the target to the correspondence estimation, the rejectors and the target surface; picks the rejector
   *  chain (the user's, or the default one); the landmark rows. */
  void
  prepareEstimators ();

  /** The state at the initial similarity of \a guess, with the first phase's components at zero. */
  PoseShapeState
  initialState (const Matrix4& guess);

  /** The similarity stage, then the shape phases of effectiveShapeSchedule (unless the shape stage is off). */
  std::vector<Phase>
  phases () const;

  /** The solver of \a phase. */
  PoseShapeLeastSquares
  solver (const Phase& phase) const;

  /** Restacks \a state for \a phase's components and starts it in \a convergence with \a solver's prior standard
   *  deviations; false if no iterations are left. */
  bool
  startPhase (const Phase& phase, const PoseShapeLeastSquares& solver, int phases_left, PoseShapeState& state,
              MorphableConvergence& convergence);

  /** Iterates \a phase until \a convergence ends it; \a best is the phase's lowest-cost state. */
  void
  runPhase (const Phase& phase, const PoseShapeLeastSquares& solver, PoseShapeState& state, PoseShapeState& best,
            MorphableConvergence& convergence);

  /** Correspondences, rejection and IRLS weights (kernel \a loss) at \a state. */
  Evaluation
  evaluate (const PoseShapeState& state, const RobustKernel& kernel);

  /** The correspondence estimation's correspondences of \a ev's posed model, their distances on the target
   *  surface's (smoothed) points. */
  pcl::CorrespondencesPtr
  findCorrespondences (Evaluation& ev);

  /** \a correspondences through the rejector chain. */
  pcl::CorrespondencesPtr
  reject (pcl::CorrespondencesPtr correspondences, Evaluation& ev);

  /** Distances, error and IRLS weights of \a ev's kept correspondences. */
  void
  weigh (Evaluation& ev, const RobustKernel& kernel) const;

  /** The rows of \a ev: each kept correspondence with its weight and metric, then the landmarks. */
  std::vector<PoseShapeRow>
  rows (const Evaluation& ev) const;

  /** The posed model with normals as a blob, for estimations and rejectors that need source normals. */
  pcl::PCLPointCloud2::Ptr
  sourceBlob (Evaluation& ev) const;

  void
  visualize (const Evaluation& ev) const;

  /** The returned state (\a state, or \a best if its cost is lower), output, residuals and report. */
  void
  finish (PoseShapeState state, const PoseShapeState& best, const PoseShapeLeastSquares& solver,
          const MorphableConvergence& convergence, PointCloudSource& output);

  /** Output cloud, coefficients, vertices and transformation of \a state. */
  void
  store (const PoseShapeState& state, PointCloudSource& output);

  /** The report's fitness over \a ev's accepted correspondences, and the source cloud that makes
   *  pcl::Registration::getFitnessScore() agree with it (see the class). */
  void
  storeFitness (const Evaluation& ev, const PoseShapeState& state);

  MorphableModel::ConstPtr model_;
  ComponentSelection selection_;
  double lambda1_ = 0.1;
  double refinement_lambda1_ = 0.1;
  std::vector<ShapePhase> schedule_;
  double lambda2_ = MorphableIcpDefaults::shape_prior;
  ShapePrior prior_ = ShapePrior::inverse_std_dev;
  bool shape_stage_ = true;
  bool estimate_scale_ = true;
  int similarity_iterations_ = MorphableIcpDefaults::similarity_iterations;
  bool point_to_plane_ = MorphableIcpDefaults::point_to_plane;
  double tangential_weight_ = MorphableIcpDefaults::tangential_weight;
  RobustKernel::ConstPtr robust_kernel_ = std::make_shared<TukeyKernel> ();
  bool graduated_loss_ = false;
  bool area_weighting_ = false;
  Eigen::VectorXd vertex_area_weights_; ///< per model vertex, mean 1 (setModel)
  bool reject_boundary_ = true;
  bool reject_incompatible_normals_ = true;
  std::optional<Eigen::Vector3d> viewpoint_;        ///< setTargetViewpoint's
  std::optional<Eigen::Vector3d> target_viewpoint_; ///< the viewpoint in force for the prepared target
  double max_sigma_ = 8.0;
  int rising_iterations_ = 3;
  LandmarkPositions landmarks_;
  double landmark_weight_ = MorphableIcpDefaults::landmark_weight;
  InitialAlignmentStrategy::ConstPtr initial_alignment_ = makeInitialAlignment ("auto");

  PointCloudTargetConstPtr no_target_; ///< the placeholder target until setInputTarget
  /** The source search tree pcl::Registration made: another one came from setSearchMethodSource. */
  typename Base::KdTreeReciprocalPtr own_source_tree_;

  TargetSurface::Ptr target_surface_;
  bool target_prepared_ = false;
  CorrespondenceRejectorTargetBoundary::Ptr boundary_rejector_;
  CorrespondenceRejectorNormalCompatibility::Ptr normal_rejector_;
  std::vector<pcl::registration::CorrespondenceRejector::Ptr> chain_; ///< the rejectors of this align()
  std::vector<PoseShapeRow> landmark_rows_;

  Eigen::VectorXd coefficients_;    ///< mm along the components
  Eigen::VectorXd coefficients_sd_; ///< the same in prior standard deviations
  Eigen::Matrix3Xd fitted_vertices_;
  Eigen::VectorXd vertex_residuals_;
  IcpReport report_;
};

} // namespace morphreg

// Bodies in impl/morphable_icp.hpp (include it for other target point types); instantiated in the library for:
extern template class morphreg::MorphableICP<pcl::PointXYZ, float>;
extern template class morphreg::MorphableICP<pcl::PointNormal, float>;
extern template class morphreg::MorphableICP<pcl::PointXYZRGBNormal, float>;

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file pose_shape_least_squares.h
 *  \brief The Gauss-Newton solver of every fit of X = s R (mu + M m) + t to weighted point rows: MorphableICP,
 *  PhotoFitting and the similarity-only refinement of the coarse and global starts (no shape unknowns).
 */
#include <morphreg/model/morphable_model.h>

#include <Eigen/Core>

#include <limits>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief The unknowns and priors of a PoseShapeLeastSquares. */
struct PoseShapeSettings
{
  ComponentSelection components;  ///< the shape unknowns (none selected, or no regions: similarity only)
  double smoothness_weight = 0.1; ///< lambda_1: Gamma across overlapping regions (>= 0)
  double prior_weight = 3.0;      ///< lambda_2: weight of Lambda (>= 0)
  ShapePrior prior = ShapePrior::inverse_std_dev; ///< Lambda: coefficients penalised in mm or in standard deviations
  /** Trust region: one update moves no coefficient by more than this many prior standard deviations (> 0), so a
   *  step on the first, still sliding correspondences cannot throw the shape far outside the prior. */
  double max_step_sigma = 3.0;
  /** |m_i| <= coefficient_limit sigma_i after every update (> 0; infinity: no limit). */
  double coefficient_limit = std::numeric_limits<double>::infinity ();
  bool estimate_scale = true; ///< false keeps s fixed (a rigid fit)
  /** Weight the data rows by 1 / s^2 of the step's start, so residuals count in model units whatever the data's
   *  scale (the photo fits, whose normalised frame has no unit). */
  bool model_units = false;
  /** Halve a coefficient update that reverses the previous one (in prior standard deviations): the correspondences
   *  of a region over a scan hole can otherwise flip between two sets, and the shape between two states. */
  bool damp_reversals = false;

  /** \brief Throws InvalidInputError, naming \a who, unless the weights are finite and >= 0 and the trust region
   *  and the coefficient limit > 0.
   *  \param[in] who the fit the settings belong to, for the message
   */
  void
  validate (const std::string& who) const;
};

/** \brief \a weight if it is finite and >= 0; else InvalidInputError naming \a what (every prior weight setter).
 *  \param[in] weight the value given
 *  \param[in] what the setting, for the message
 *  \return \a weight
 */
double
requirePriorWeight (double weight, const std::string& what);

/** \brief The state of a fit: the similarity as log s, R and t, the coefficients of \a selection and the model-frame
 *  vertices (mu + M m) of the solver's slots. */
struct PoseShapeState
{
  double log_scale = 0.0;                                  ///< log s: the scale stays positive through any update
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity (); ///< R
  Eigen::Vector3d translation = Eigen::Vector3d::Zero ();  ///< t (mm for mm data)
  ComponentSelection selection;                            ///< the components the coefficients belong to
  Eigen::VectorXd coefficients;                            ///< m, stacked as \a selection (mm along the basis)
  Eigen::Matrix3Xd vertices;                               ///< mu + M m of each solver slot (3 x slots, model frame)
  Eigen::VectorXd last_step; ///< the last accepted coefficient update, in prior standard deviations (damping)

  /** \brief The similarity's scale.
   *  \return s = exp (log_scale)
   */
  double
  scale () const;

  /** \brief s R v + t of every slot's vertex.
   *  \return the posed vertices (3 x slots), where the fit places them in the data frame
   */
  Eigen::Matrix3Xd
  posed () const;

  /** \brief The similarity [s R | t].
   *  \return the 4 x 4 matrix mapping the model frame to the data frame
   */
  Eigen::Matrix4d
  similarity () const;
};

/** \brief One residual block: the vertex of solver slot \a slot pulled to \a target with the 3 x 3 metric \a metric
 *  (weight times identity, per-axis weights on the diagonal, or a point-to-plane n n^T). */
struct PoseShapeRow
{
  int slot;               ///< the solver slot whose vertex is pulled
  Eigen::Vector3d target; ///< where it is pulled to (data frame)
  Eigen::Matrix3d metric; ///< W: the 3 x 3 weight of the residual r = posed vertex - target
};

/** \brief Gauss-Newton over (log s, rotation increment, t, m) for the cost
 *  sum_rows r^T W r (times 1 / s^2 with model_units) + lambda_1^2 |Gamma m|^2 + lambda_2^2 |Lambda m|^2.
 *  The normal equations are summed per row over the columns of that vertex's regions only (no dense Jacobian), in
 *  parallel with OpenMP for large shape problems. A step solves them by LDLT (coefficients at the limit that the
 *  descent pushes outwards held fixed), scales the update into the trust region, damps a reversal, projects onto the
 *  coefficient limit and backtracks (halving) until the cost with the same rows does not rise.
 */
class PoseShapeLeastSquares
{
public:
  /** \brief A similarity-only solver: the rows' slots index the state's fixed vertices.
   *  \param[in] estimate_scale false keeps s fixed
   */
  explicit PoseShapeLeastSquares (bool estimate_scale = true);

  /** \brief A solver over \a model's vertices \a slots (empty: every vertex, slot = vertex index).
   *  \param[in] model the model; must outlive the solver
   *  \param[in] slots the model vertex of each slot, or empty for all
   *  \param[in] settings components and priors (validated; the components against the model)
   */
  PoseShapeLeastSquares (const MorphableModel& model, std::vector<int> slots, const PoseShapeSettings& settings);

  /** \brief The model vertex of each slot.
   *  \return the model vertex indices, in slot order
   */
  const std::vector<int>&
  slots () const
  {
    return slots_;
  }

  /** \brief Prior standard deviations of the fitted coefficients.
   *  \return one sigma per selected component (empty for a similarity-only solver)
   */
  const Eigen::VectorXd&
  sigma () const
  {
    return sigma_;
  }

  /** \brief The unknowns and priors the solver was built with.
   *  \return the validated settings
   */
  const PoseShapeSettings&
  settings () const
  {
    return settings_;
  }

  /** \brief The model-frame vertices of the slots for \a coefficients of the settings' components.
   *  \param[in] coefficients the stacked coefficients of the settings' components (mm)
   *  \return mu + M m of each slot (3 x slots)
   */
  Eigen::Matrix3Xd
  vertices (const Eigen::VectorXd& coefficients) const;

  /** \brief A state at the similarity \a similarity with \a coefficients (stacked as the components).
   *  \param[in] similarity the start [s R | t], model frame to data frame
   *  \param[in] coefficients the start coefficients of the settings' components (mm)
   *  \return the state, its slot vertices generated
   */
  PoseShapeState
  state (const Eigen::Matrix4d& similarity, const Eigen::VectorXd& coefficients) const;

  /** \brief The cost of \a state for \a rows (weighted by \a inverse_scale2 when model_units; <= 0: from \a state).
   *  \param[in] state the state evaluated
   *  \param[in] rows the residual blocks
   *  \param[in] inverse_scale2 1 / s^2 weighting the data rows with model_units (<= 0: taken from \a state)
   *  \return the data term plus the priors' terms (mm^2 for mm data)
   */
  double
  cost (const PoseShapeState& state, const std::vector<PoseShapeRow>& rows, double inverse_scale2 = 0.0) const;

  /** \brief One update of \a state for fixed \a rows; the state is unchanged if no step length lowers the cost.
   *  \param[in,out] state the state updated in place
   *  \param[in] rows the residual blocks, fixed for the step
   *  \return false if the normal equations could not be solved
   */
  bool
  step (PoseShapeState& state, const std::vector<PoseShapeRow>& rows) const;

private:
  bool
  hasShape () const
  {
    return sigma_.size () > 0;
  }

  /** J^T W J and J^T W r of \a rows at \a state (7 + P unknowns). */
  void
  normalEquations (const PoseShapeState& state, const std::vector<PoseShapeRow>& rows, double inverse_scale2,
                   Eigen::MatrixXd& hessian, Eigen::VectorXd& gradient) const;

  /** Adds the prior, fixes s when it is not estimated, holds coefficients at the limit; the solved update. */
  bool
  solve (const PoseShapeState& state, Eigen::MatrixXd& hessian, Eigen::VectorXd& gradient,
         Eigen::VectorXd& delta) const;

  /** Trust region and reversal damping of \a delta; returns the coefficient update in prior standard deviations. */
  Eigen::VectorXd
  limitStep (const PoseShapeState& state, Eigen::VectorXd& delta) const;

  /** \a state moved by \a delta (coefficients projected onto the limit, vertices regenerated). */
  PoseShapeState
  moved (const PoseShapeState& state, const Eigen::VectorXd& delta) const;

  const MorphableModel* model_ = nullptr;
  std::vector<int> slots_;
  bool all_vertices_ = false;
  PoseShapeSettings settings_;
  Eigen::VectorXd sigma_;
  Eigen::MatrixXd prior_; ///< lambda_1^2 Gamma^T Gamma + lambda_2^2 Lambda^2 (P x P)
  int max_columns_ = 7;   ///< the most Jacobian columns one row can have
};

/** \brief The one rule for too few correspondences. Each iteration of a fit counts its point rows (the
 *  correspondences left after rejection, plus landmark rows) and, if they are fewer than \a needed, throws
 *  TooFewCorrespondencesError naming \a who, the counts and what to check: MorphableICP needs as many rows as
 *  unknowns (7, or 6 without scale, plus the phase's coefficients); PhotoFitting needs 3 outline rows (the
 *  landmarks and the prior fix the rest). The coarse and global starts score many hypotheses: one left with fewer
 *  rows than the similarity's 7 unknowns stops refining and loses on its score instead.
 *  \param[in] rows the point rows of this iteration
 *  \param[in] needed the fewest rows the fit accepts
 *  \param[in] who the fit, for the message
 *  \param[in] counts what the rows are made of, for the message
 *  \param[in] hint what to check, for the message
 */
void
requireEnoughRows (size_t rows, size_t needed, const std::string& who, const std::string& counts,
                   const std::string& hint);
} // namespace morphreg

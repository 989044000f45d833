#pragma once
// Private to src/photo: Gauss-Newton over a similarity and shape coefficients for weighted point rows on a subset of
// model vertices (the two-view fits' profile and landmark rows, the TPS-ICP's vertex rows).
#include <morphreg/model/morphable_model.h>

#include <Eigen/Core>

#include <vector>

namespace morphreg
{
namespace detail
{
/** The model vertices some rows constrain, with their mean and shape rows, and the shape prior. */
struct ShapeProblem
{
  ShapeProblem (const MorphableModel& model, const ComponentSelection& selection, std::vector<int> vertices,
                double lambda1, double lambda2, ShapePrior prior,
                double coefficient_limit);

  /** The constrained vertices (3 x K, model frame) for \a coefficients. */
  Eigen::Matrix3Xd
  vertexPositions (const Eigen::VectorXd& coefficients) const;

  std::vector<int> vertices;
  Eigen::Matrix3Xd mean;
  std::vector<Eigen::Matrix3Xd> shape_rows; ///< M_i of each constrained vertex (3 x P)
  Eigen::MatrixXd prior;                    ///< lambda_1^2 Gamma^T Gamma + lambda_2^2 Lambda^2
  Eigen::VectorXd sigma;                    ///< prior standard deviations of the coefficients
  double coefficient_limit; ///< |c_i| <= coefficient_limit sigma_i after each step (infinity: no limit)
};

/** The unknowns X = s R v + t, with the constrained vertices v of the current shape (model frame). */
struct PoseShapeState
{
  double log_scale = 0.0;
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity ();
  Eigen::Vector3d translation = Eigen::Vector3d::Zero ();
  Eigen::VectorXd coefficients;
  Eigen::Matrix3Xd vertices;

  double
  scale () const;

  /** s R v + t of the constrained vertices. */
  Eigen::Matrix3Xd
  posed () const;
};

/** One residual block: a constrained vertex (its column in the problem), its target and per-axis weights. */
struct WeightedRow
{
  Eigen::Index slot;
  Eigen::Vector3d target;
  Eigen::Vector3d weight;
};

/** Mean squared motion (model mm^2) of the constrained vertices below which an iteration loop has converged. */
constexpr double kPoseShapeMotionEpsilon = 1e-6;

/** One Gauss-Newton update of \a state on fixed \a rows (squared residuals weighted by 1 / s^2 of \a state, so in
 *  model mm^2), with the shape prior and coefficients when \a shape (projected onto the coefficient limit's box), and
 *  backtracking on that cost. False if the normal equations cannot be solved.
 */
bool
poseShapeStep (const ShapeProblem& problem, PoseShapeState& state, const std::vector<WeightedRow>& rows, bool shape);

/** Mean squared motion (model mm^2) of the constrained vertices between \a before (posed) and \a state. */
double
poseShapeMotion (const Eigen::Matrix3Xd& before, const PoseShapeState& state);
} // namespace detail
} // namespace morphreg

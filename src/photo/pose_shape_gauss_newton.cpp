#include "pose_shape_gauss_newton.h"

#include <morphreg/registration/similarity_shape_step.h>

#include <Eigen/Cholesky>

#include <cmath>

namespace morphreg
{
namespace detail
{
namespace
{
/** The cost of \a state for fixed \a rows weighted by \a inverse_scale2, plus the shape prior when \a shape. */
double
objective (const ShapeProblem& problem, const PoseShapeState& state, const std::vector<WeightedRow>& rows,
           double inverse_scale2, bool shape)
{
  const Eigen::Matrix3Xd posed = state.posed ();
  double sum = 0.0;
  for (const WeightedRow& row : rows)
    sum += (row.target - posed.col (row.slot)).cwiseAbs2 ().dot (row.weight);
  sum *= inverse_scale2;
  if (shape)
    sum += state.coefficients.dot (problem.prior * state.coefficients);
  return sum;
}
/** Removes from the normal equations (\a hessian, \a descent = J^T r - prior m) every coefficient that sits at the
 *  coefficient limit and that the descent direction pushes further out: its step is 0, so the projection onto the
 *  limit cannot undo the rest of the step (an active-set Gauss-Newton step).
 */
void
holdCoefficientsAtTheLimit (const ShapeProblem& problem, const Eigen::VectorXd& coefficients, Eigen::MatrixXd& hessian,
                            Eigen::VectorXd& descent)
{
  if (!std::isfinite (problem.coefficient_limit))
    return;
  for (Eigen::Index i = 0; i < coefficients.size (); ++i) {
    const double bound = problem.coefficient_limit * problem.sigma[i];
    const Eigen::Index k = 7 + i;
    if (std::abs (coefficients[i]) >= (1.0 - 1e-9) * bound && descent[k] * coefficients[i] > 0.0) {
      const double diagonal = hessian (k, k);
      hessian.row (k).setZero ();
      hessian.col (k).setZero ();
      hessian (k, k) = diagonal > 0.0 ? diagonal : 1.0;
      descent[k] = 0.0;
    }
  }
}
} // namespace

ShapeProblem::ShapeProblem (const MorphableModel& model, const ComponentSelection& selection,
                            std::vector<int> constrained, double lambda1, double lambda2, ShapePrior kind,
                            double limit)
  : vertices (std::move (constrained)),
    prior (shapePriorMatrix (model, selection, lambda1, lambda2, kind)),
    sigma (model.variances (selection).cwiseSqrt ()),
    coefficient_limit (limit)
{
  mean.resize (3, static_cast<Eigen::Index> (vertices.size ()));
  for (size_t k = 0; k < vertices.size (); ++k) {
    mean.col (static_cast<Eigen::Index> (k)) = model.meanVertex (vertices[k]);
    shape_rows.push_back (model.shapeRows (vertices[k], selection));
  }
}

Eigen::Matrix3Xd
ShapeProblem::vertexPositions (const Eigen::VectorXd& coefficients) const
{
  Eigen::Matrix3Xd positions = mean;
  for (size_t k = 0; k < shape_rows.size (); ++k)
    positions.col (static_cast<Eigen::Index> (k)) += shape_rows[k] * coefficients;
  return positions;
}

double
PoseShapeState::scale () const
{
  return std::exp (log_scale);
}

Eigen::Matrix3Xd
PoseShapeState::posed () const
{
  return (scale () * rotation * vertices).colwise () + translation;
}

bool
poseShapeStep (const ShapeProblem& problem, PoseShapeState& state, const std::vector<WeightedRow>& rows, bool shape)
{
  const Eigen::Index p = shape ? state.coefficients.size () : 0;
  const Eigen::Index dim = 7 + p;
  const Eigen::Matrix3d sr = state.scale () * state.rotation;
  const double inverse_scale2 = 1.0 / (state.scale () * state.scale ());
  Eigen::MatrixXd hessian = Eigen::MatrixXd::Zero (dim, dim);
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero (dim);
  Eigen::Matrix<double, 3, Eigen::Dynamic> jacobian (3, dim);
  for (const WeightedRow& row : rows) {
    const Eigen::Vector3d rotated = sr * state.vertices.col (row.slot);
    const Eigen::Vector3d residual = row.target - rotated - state.translation;
    jacobian.leftCols<7> () = similarityJacobian (rotated);
    if (shape)
      jacobian.rightCols (p).noalias () = sr * problem.shape_rows[row.slot];
    const Eigen::Matrix<double, 3, Eigen::Dynamic> weighted = (inverse_scale2 * row.weight).asDiagonal () * jacobian;
    hessian.noalias () += weighted.transpose () * jacobian;
    gradient.noalias () += weighted.transpose () * residual;
  }
  if (shape) {
    hessian.bottomRightCorner (p, p) += problem.prior;
    gradient.tail (p) -= problem.prior * state.coefficients;
  }
  if (shape)
    holdCoefficientsAtTheLimit (problem, state.coefficients, hessian, gradient);
  hessian.diagonal ().array () += 1e-12 * std::max (1.0, hessian.diagonal ().maxCoeff ());
  const Eigen::LDLT<Eigen::MatrixXd> solver (hessian);
  Eigen::VectorXd delta = solver.solve (gradient);
  if (solver.info () != Eigen::Success || !delta.allFinite ())
    return false;
  if (shape)
    limitShapeStep (delta, problem.sigma);
  const double current = objective (problem, state, rows, inverse_scale2, shape);
  for (double alpha = 1.0; alpha > 1e-2; alpha *= 0.5) {
    PoseShapeState candidate = state;
    const Eigen::VectorXd d = alpha * delta;
    updateSimilarity (d.head<7> (), candidate.log_scale, candidate.rotation, candidate.translation);
    if (shape) {
      candidate.coefficients += d.tail (p);
      if (std::isfinite (problem.coefficient_limit)) {
        const Eigen::VectorXd bound = problem.coefficient_limit * problem.sigma;
        candidate.coefficients = candidate.coefficients.cwiseMin (bound).cwiseMax (-bound);
      }
      candidate.vertices = problem.vertexPositions (candidate.coefficients);
    }
    if (objective (problem, candidate, rows, inverse_scale2, shape) <= current) {
      state = std::move (candidate);
      break;
    }
  }
  return true;
}

double
poseShapeMotion (const Eigen::Matrix3Xd& before, const PoseShapeState& state)
{
  return (state.posed () - before).colwise ().squaredNorm ().mean () / (state.scale () * state.scale ());
}
} // namespace detail
} // namespace morphreg

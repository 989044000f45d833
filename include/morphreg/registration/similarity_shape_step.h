#pragma once
/** \file similarity_shape_step.h
 *  \brief Gauss-Newton pieces shared by the fits of s R (mu + M m) + t to data (MorphableICP, TwoViewFitting): the
 *  similarity's Jacobian and update, the shape prior matrix and the per-update trust region on the coefficients.
 */
#include <morphreg/model/morphable_model.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace morphreg
{
namespace detail
{
/** Largest change of one shape coefficient per Gauss-Newton update, in prior standard deviations. */
constexpr double kMaxShapeStep = 3.0;

inline Eigen::Matrix3d
skew (const Eigen::Vector3d& v)
{
  Eigen::Matrix3d s;
  s << 0, -v.z (), v.y (), v.z (), 0, -v.x (), -v.y (), v.x (), 0;
  return s;
}

/** \brief 3 x 7 Jacobian of s R x + t at \a rotated = s R x with respect to (log s, a rotation increment theta
 *  applied as exp([theta]_x) R, t).
 */
inline Eigen::Matrix<double, 3, 7>
similarityJacobian (const Eigen::Vector3d& rotated)
{
  Eigen::Matrix<double, 3, 7> jacobian;
  jacobian.col (0) = rotated;
  jacobian.middleCols<3> (1) = -skew (rotated);
  jacobian.rightCols<3> ().setIdentity ();
  return jacobian;
}

/** \brief Applies the update \a d = (log s, theta, t) of similarityJacobian's parameters; the rotation is
 *  re-orthonormalised.
 */
inline void
updateSimilarity (const Eigen::Matrix<double, 7, 1>& d, double& log_scale, Eigen::Matrix3d& rotation,
                  Eigen::Vector3d& translation)
{
  log_scale += d[0];
  const Eigen::Vector3d theta = d.segment<3> (1);
  const double angle = theta.norm ();
  if (angle > 0.0)
    rotation = Eigen::AngleAxisd (angle, theta / angle).toRotationMatrix () * rotation;
  rotation = Eigen::Quaterniond (rotation).normalized ().toRotationMatrix ();
  translation += d.tail<3> ();
}

/** \brief Trust region: scales the whole update \a delta (shape coefficients last, with prior standard deviations
 *  \a sigma) so that no coefficient moves by more than kMaxShapeStep standard deviations.
 */
inline void
limitShapeStep (Eigen::VectorXd& delta, const Eigen::VectorXd& sigma)
{
  const Eigen::Index p = sigma.size ();
  if (p == 0)
    return;
  const double largest = delta.tail (p).cwiseQuotient (sigma).cwiseAbs ().maxCoeff ();
  if (largest > kMaxShapeStep)
    delta *= kMaxShapeStep / largest;
}

/** \brief The shape prior's normal-equation block lambda_1^2 Gamma^T Gamma + lambda_2^2 Lambda^2 (P x P) for
 *  \a selection (thesis eq. 40-42).
 */
inline Eigen::MatrixXd
shapePriorMatrix (const MorphableModel& model, const ComponentSelection& selection, double lambda1, double lambda2,
                  ShapePrior prior)
{
  const MorphableModel::RowMatrix gamma = model.gammaMatrix (selection);
  Eigen::MatrixXd matrix = lambda1 * lambda1 * (gamma.transpose () * gamma);
  matrix.diagonal () += lambda2 * lambda2 * model.lambdaDiagonal (selection, prior).cwiseAbs2 ();
  return matrix;
}
} // namespace detail
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/warp/impl/tps_kernel.hpp>
#include <morphreg/warp/impl/landmark_pairs.h>
#include <morphreg/warp/impl/tps_solver.h>

#include <Eigen/Cholesky>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace morphreg
{
namespace detail
{
namespace
{
/** Landmarks must be reproduced to this fraction of their extent: an interpolating spline hits them exactly
 *  (docs/method.md, "Thin plate splines"). */
constexpr double kResidualTolerance = 1e-9;
/** Above this relative residual, one step of iterative refinement is taken before the final check. */
constexpr double kRefineTolerance = 1e-13;

/** The system L [W; A] = [Y; 0] reduced to the null space of P^T (W = Q2 g) and solved by Cholesky:
 *  (sign Q2^T K Q2 + lambda I) g = sign Q2^T Y is positive definite for distinct, non-flat landmarks;
 *  then R A = Q1^T Y - Q1^T K Q2 g. One n x n matrix is the only large allocation.
 */
template <int D>
class NullSpaceSystem
{
public:
  /** \a centred: n x D landmarks minus their mean. */
  NullSpaceSystem (const Eigen::MatrixXd& centred, double lambda) : lambda_ (lambda)
  {
    const Eigen::Index n = centred.rows ();
    Eigen::MatrixXd p (n, D + 1);
    p << Eigen::VectorXd::Ones (n), centred;
    qr_.compute (p);
    q_k_q_.resize (n, n);
#pragma omp parallel for schedule(static) if (double(n) * double(n) > kTpsParallelPairs)
    for (Eigen::Index j = 0; j < n; ++j) {
      double* column = q_k_q_.col (j).data ();
#pragma omp simd
      for (Eigen::Index i = 0; i < n; ++i) {
        double r2 = 0.0;
        for (int k = 0; k < D; ++k) {
          const double d = centred.data ()[k * n + i] - centred.data ()[k * n + j];
          r2 += d * d;
        }
        column[i] = TpsKernel<D>::value (r2);
      }
    }
    q_k_q_.applyOnTheLeft (qr_.householderQ ().adjoint ());
    q_k_q_.applyOnTheRight (qr_.householderQ ());
    auto reduced = q_k_q_.bottomRightCorner (n - D - 1, n - D - 1);
    reduced *= double (TpsKernel<D>::sign);
    reduced.diagonal ().array () += lambda;
    Eigen::LLT<Eigen::Ref<Eigen::MatrixXd>> cholesky (reduced); // in place: the factor replaces the lower triangle
    positive_definite_ = cholesky.info () == Eigen::Success;
    condition_ = positive_definite_ ? 1.0 / cholesky.rcond () : std::numeric_limits<double>::infinity ();
  }

  bool
  positiveDefinite () const
  {
    return positive_definite_;
  }

  /** Estimated 1-norm condition number of the reduced (Cholesky) system. */
  double
  condition () const
  {
    return condition_;
  }

  /** W (n x D) and the centred affine part A ((D+1) x D) for right-hand side \a y (n x D). */
  void
  solve (const Eigen::MatrixXd& y, Eigen::MatrixXd& w, Eigen::MatrixXd& a) const
  {
    const Eigen::Index m = q_k_q_.rows () - D - 1;
    const Eigen::MatrixXd qy = qr_.householderQ ().adjoint () * y;
    const Eigen::MatrixXd g = solveReduced (double (TpsKernel<D>::sign) * qy.bottomRows (m));
    w = Eigen::MatrixXd::Zero (q_k_q_.rows (), D);
    w.bottomRows (m) = g;
    w.applyOnTheLeft (qr_.householderQ ());
    a = qr_.matrixQR ()
            .topLeftCorner (D + 1, D + 1)
            .template triangularView<Eigen::Upper> ()
            .solve (qy.topRows (D + 1) - q_k_q_.topRightCorner (D + 1, m) * g);
  }

  /** sign trace(W^T K W) = |L^T g|^2 - lambda |g|^2 with g = Q2^T W. */
  double
  bendingEnergy (const Eigen::MatrixXd& w) const
  {
    const Eigen::Index m = q_k_q_.rows () - D - 1;
    if (m == 0)   // D + 1 landmarks: the spline is affine and bends nothing (and Eigen's empty triangular product would
      return 0.0; // bind a reference to the null data of its zero-size result)
    const Eigen::MatrixXd g = (qr_.householderQ ().adjoint () * w).bottomRows (m);
    const Eigen::MatrixXd lt_g = factor ().adjoint () * g;
    return lt_g.squaredNorm () - lambda_ * g.squaredNorm ();
  }

private:
  Eigen::TriangularView<const Eigen::Block<const Eigen::MatrixXd>, Eigen::Lower>
  factor () const
  {
    const Eigen::Index m = q_k_q_.rows () - D - 1;
    return q_k_q_.bottomRightCorner (m, m).template triangularView<Eigen::Lower> ();
  }

  Eigen::MatrixXd
  solveReduced (Eigen::MatrixXd b) const
  {
    factor ().solveInPlace (b);
    factor ().adjoint ().solveInPlace (b);
    return b;
  }

  double lambda_;
  Eigen::HouseholderQR<Eigen::MatrixXd> qr_;
  Eigen::MatrixXd q_k_q_; ///< Q^T K Q; its lower-right block holds the Cholesky factor
  bool positive_definite_ = false;
  double condition_ = 0.0;
};

/** Y - (f(P) + sign lambda W): the residual of the full system at the landmarks (n x D). */
template <int D>
Eigen::MatrixXd
landmarkResidual (const TpsCoefficients<double, D>& c, const Eigen::MatrixXd& y, double lambda)
{
  const Eigen::Matrix<double, D, Eigen::Dynamic> points = c.landmarks.transpose ();
  Eigen::Matrix<double, D, Eigen::Dynamic> values (D, points.cols ());
  evaluateTps<double, D> (c, points, values);
  return y - values.transpose () - double (TpsKernel<D>::sign) * lambda * c.weights;
}

template <int D>
TpsFit
fitDistinct (const Eigen::MatrixXd& landmarks, const Eigen::MatrixXd& y, double affine_condition,
             const TpsFitOptions& options)
{
  const Eigen::RowVectorXd centre = landmarks.colwise ().mean ();
  const NullSpaceSystem<D> system (landmarks.rowwise () - centre, options.regularization);
  const double condition = std::max (system.condition (), affine_condition);
  std::ostringstream msg;
  msg << options.caller << ": the spline system of " << landmarks.rows () << " landmarks is ";
  if (!system.positiveDefinite () || !(condition <= options.max_condition_number)) {
    msg << "ill-conditioned (condition estimate " << condition << ", limit " << options.max_condition_number
        << "); landmarks nearly coincide or are nearly flat";
    throw NumericalError (msg.str ());
  }

  TpsCoefficients<double, D> c;
  c.landmarks = landmarks;
  Eigen::MatrixXd w = Eigen::MatrixXd::Zero (y.rows (), D), a = Eigen::MatrixXd::Zero (D + 1, D);
  Eigen::MatrixXd residual = y;
  const double scale = std::max (boundingBoxDiagonal (y.transpose ()), boundingBoxDiagonal (landmarks.transpose ()));
  // The solve, then one step of iterative refinement when the residual is above round-off.
  for (int step = 0; step < 2 && (step == 0 || residual.rowwise ().norm ().maxCoeff () > kRefineTolerance * scale);
       ++step) {
    Eigen::MatrixXd dw, da;
    system.solve (residual, dw, da);
    w += dw;
    a += da;
    c.weights = w;
    c.affine = a;
    c.affine.row (0) -= centre * a.bottomRows (D); // back from centred coordinates
    residual = landmarkResidual (c, y, options.regularization);
  }
  const double worst = residual.rowwise ().norm ().maxCoeff ();
  if (!(worst <= kResidualTolerance * scale)) {
    msg << "too ill-conditioned to reproduce the landmarks (residual " << worst << " against extent " << scale
        << ", condition estimate " << condition << ")";
    throw NumericalError (msg.str ());
  }

  TpsFit fit;
  fit.landmarks = landmarks;
  fit.weights = c.weights;
  fit.affine = c.affine;
  fit.bending_energy = system.bendingEnergy (w);
  fit.condition_estimate = condition;
  return fit;
}

} // namespace

TpsFit
fitThinPlateSpline (const Eigen::MatrixXd& source, const Eigen::MatrixXd& target, const TpsFitOptions& options)
{
  const LandmarkPairs pairs = distinctLandmarkPairs (source, target, options.caller, "thin plate spline");
  const Eigen::Index d = source.rows ();
  TpsFit fit = d == 3 ? fitDistinct<3> (pairs.source, pairs.target, pairs.affine_condition, options)
                      : fitDistinct<2> (pairs.source, pairs.target, pairs.affine_condition, options);
  fit.merged = pairs.merged;
  return fit;
}

} // namespace detail
} // namespace morphreg

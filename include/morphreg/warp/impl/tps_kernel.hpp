// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file tps_kernel.hpp
 *  \brief The thin plate spline kernels and the blocked, vectorised (OpenMP SIMD + threads) evaluation of
 *  f(x) = A^T [1; x] + sum_i W_i U(|x - p_i|) and of its Jacobian. Internal to ThinPlateSpline.
 */
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <type_traits>

namespace morphreg
{
namespace detail
{
/** \brief The radial basis U of a Dim-dimensional thin plate spline, written in terms of r^2 (no sqrt in 2D). */
template <int Dim>
struct TpsKernel;

/** \brief 3D: U(r) = r. -U is conditionally positive definite, so the bending energy is -trace(W^T K W). */
template <>
struct TpsKernel<3>
{
  /** +1 if the kernel matrix is positive definite on the affine null space, -1 if negative definite. */
  static constexpr int sign = -1;

  template <typename T>
  static T
  value (T r2)
  {
    return std::sqrt (r2);
  }

  /** \brief g with grad_x U(|x - p|) = g(r^2) (x - p); 0 at r = 0 (the gradient's subgradient choice). */
  template <typename T>
  static T
  gradientFactor (T r2)
  {
    return r2 > T (0) ? T (1) / std::sqrt (r2) : T (0);
  }
};

/** \brief 2D: U(r) = r^2 log r^2 (U(0) = 0); conditionally positive definite of order 2. */
template <>
struct TpsKernel<2>
{
  static constexpr int sign = 1;

  template <typename T>
  static T
  value (T r2)
  {
    return r2 > T (0) ? r2 * std::log (r2) : T (0);
  }

  template <typename T>
  static T
  gradientFactor (T r2)
  {
    return r2 > T (0) ? T (2) * (std::log (r2) + T (1)) : T (0);
  }
};

/** \brief The coefficients of a fitted spline in the layout the evaluation wants: one contiguous column per
 *  coordinate (structure of arrays) so the loop over landmarks vectorises.
 */
template <typename Scalar, int Dim>
struct TpsCoefficients
{
  Eigen::Matrix<Scalar, Eigen::Dynamic, Dim> landmarks; ///< n x Dim, p_i^T per row
  Eigen::Matrix<Scalar, Eigen::Dynamic, Dim> weights;   ///< n x Dim, W
  Eigen::Matrix<Scalar, Dim + 1, Dim> affine;           ///< (Dim+1) x Dim, A
};

/** \brief Below this many point-landmark pairs a call stays on one thread (thread start-up costs more). */
constexpr double kTpsParallelPairs = 2e5;

#if defined(__GNUC__)
#define MORPHREG_TPS_INLINE inline __attribute__ ((always_inline))
#else
#define MORPHREG_TPS_INLINE inline
#endif

/** \brief f(x) for one point: the sum over landmarks runs as one SIMD reduction per coordinate. Always inlined, so
 *  the loop is compiled for the caller's instruction set (see evaluateTpsBlock).
 */
template <typename Scalar, int Dim>
MORPHREG_TPS_INLINE Eigen::Matrix<Scalar, Dim, 1>
evaluateTpsPoint (const TpsCoefficients<Scalar, Dim>& c, const Scalar* x)
{
  const Eigen::Index n = c.landmarks.rows ();
  const Scalar* p[Dim];
  const Scalar* w[Dim];
  for (int k = 0; k < Dim; ++k) {
    p[k] = c.landmarks.col (k).data ();
    w[k] = c.weights.col (k).data ();
  }
  Scalar s0 = 0, s1 = 0, s2 = 0;
  if constexpr (Dim == 3) {
#pragma omp simd reduction(+ : s0, s1, s2)
    for (Eigen::Index i = 0; i < n; ++i) {
      const Scalar dx = x[0] - p[0][i], dy = x[1] - p[1][i], dz = x[2] - p[2][i];
      const Scalar u = TpsKernel<3>::value (dx * dx + dy * dy + dz * dz);
      s0 += u * w[0][i];
      s1 += u * w[1][i];
      s2 += u * w[2][i];
    }
  }
  else {
#pragma omp simd reduction(+ : s0, s1)
    for (Eigen::Index i = 0; i < n; ++i) {
      const Scalar dx = x[0] - p[0][i], dy = x[1] - p[1][i];
      const Scalar u = TpsKernel<2>::value (dx * dx + dy * dy);
      s0 += u * w[0][i];
      s1 += u * w[1][i];
    }
  }
  const Scalar sums[3] = {s0, s1, s2};
  Eigen::Matrix<Scalar, Dim, 1> result = c.affine.row (0).transpose ();
  for (int k = 0; k < Dim; ++k)
    result[k] += sums[k] + c.affine.col (k).tail (Dim).dot (Eigen::Map<const Eigen::Matrix<Scalar, Dim, 1>> (x));
  return result;
}

/** \brief The Jacobian df/dx (Dim x Dim) at one point. */
template <typename Scalar, int Dim>
Eigen::Matrix<Scalar, Dim, Dim>
evaluateTpsJacobian (const TpsCoefficients<Scalar, Dim>& c, const Scalar* x)
{
  const Eigen::Index n = c.landmarks.rows ();
  // J(k, l) = A(1 + l, k) + sum_i W(i, k) g(r_i^2) (x_l - p_il)
  Eigen::Matrix<Scalar, Dim, Dim> jacobian = c.affine.bottomRows (Dim).transpose ();
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::Matrix<Scalar, Dim, 1> d;
    for (int l = 0; l < Dim; ++l)
      d[l] = x[l] - c.landmarks (i, l);
    const Scalar g = TpsKernel<Dim>::gradientFactor (d.squaredNorm ());
    jacobian.noalias () += (g * c.weights.row (i).transpose ()) * d.transpose ();
  }
  return jacobian;
}

/** \brief f at \a count points (x, y, z interleaved) into \a result, for the double 3D spline. Compiled once per
 *  x86-64 ISA level and chosen at load time (GCC function multi-versioning) unless the build already targets this
 *  CPU: the landmark loop then runs 8 or 4 wide in an ordinary -O3 build instead of SSE2's 2.
 */
void
evaluateTpsBlock (const TpsCoefficients<double, 3>& c, const double* points, Eigen::Index count, double* result);

/** \brief Points per call of evaluateTpsBlock: enough to hide the dispatch, few enough to share among threads. */
constexpr Eigen::Index kTpsBlockPoints = 256;

/** \brief f at every column of \a points (Dim x m) into \a result (Dim x m); threads over points. */
template <typename Scalar, int Dim>
void
evaluateTps (const TpsCoefficients<Scalar, Dim>& c,
             const Eigen::Ref<const Eigen::Matrix<Scalar, Dim, Eigen::Dynamic>>& points,
             Eigen::Ref<Eigen::Matrix<Scalar, Dim, Eigen::Dynamic>> result)
{
  const Eigen::Index m = points.cols ();
  const bool parallel = double (m) * double (c.landmarks.rows ()) > kTpsParallelPairs;
  if constexpr (std::is_same<Scalar, double>::value && Dim == 3) {
    if (points.outerStride () == 3 && result.outerStride () == 3) {
      // Contiguous blocks of points per thread: the landmark arrays stay in that core's cache.
#pragma omp parallel for schedule(static) if (parallel)
      for (Eigen::Index block = 0; block < m; block += kTpsBlockPoints)
        evaluateTpsBlock (c, points.col (block).data (), std::min (kTpsBlockPoints, m - block),
                          result.col (block).data ());
      return;
    }
  }
#pragma omp parallel for schedule(static) if (parallel)
  for (Eigen::Index j = 0; j < m; ++j) {
    const Eigen::Matrix<Scalar, Dim, 1> x = points.col (j);
    result.col (j) = evaluateTpsPoint (c, x.data ());
  }
}

} // namespace detail
} // namespace morphreg

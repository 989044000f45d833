// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Deterministic landmark sets and warps for the thin plate spline tests.
#include <Eigen/Core>

#include <cmath>
#include <random>

namespace morphreg
{
namespace test
{
/** \a n points uniform in a box of edge \a size (mm) centred at \a offset, reproducible from \a seed. */
template <int Dim = 3>
Eigen::Matrix<double, Dim, Eigen::Dynamic>
randomLandmarks (int n, unsigned seed, double size = 200.0, double offset = 0.0)
{
  std::mt19937 engine (seed);
  std::uniform_real_distribution<double> coordinate (-0.5 * size, 0.5 * size);
  Eigen::Matrix<double, Dim, Eigen::Dynamic> points (Dim, n);
  for (int j = 0; j < n; ++j)
    for (int k = 0; k < Dim; ++k)
      points (k, j) = offset + coordinate (engine);
  return points;
}

/** A smooth, clearly non-affine deformation of the columns of \a points (a few mm of bending). */
template <int Dim>
Eigen::Matrix<double, Dim, Eigen::Dynamic>
bend (const Eigen::Matrix<double, Dim, Eigen::Dynamic>& points)
{
  Eigen::Matrix<double, Dim, Eigen::Dynamic> result = points;
  for (Eigen::Index j = 0; j < points.cols (); ++j) {
    result (0, j) += 8.0 * std::sin (points (1, j) / 40.0);
    result (1, j) += 6.0 * std::cos (points (0, j) / 55.0) + 0.1 * points (0, j);
    if (Dim == 3)
      result (Dim - 1, j) += 5.0 * std::sin ((points (0, j) + points (1, j)) / 70.0);
  }
  return result;
}

/** Largest column distance between \a a and \a b. */
template <typename A, typename B>
double
maxColumnDistance (const A& a, const B& b)
{
  return (a - b).colwise ().norm ().maxCoeff ();
}

/** Bounding-box diagonal of the columns of \a points. */
template <typename A>
double
extent (const A& points)
{
  return (points.rowwise ().maxCoeff () - points.rowwise ().minCoeff ()).norm ();
}
} // namespace test
} // namespace morphreg

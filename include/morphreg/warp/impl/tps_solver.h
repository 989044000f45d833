// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file tps_solver.h
 *  \brief The thin plate spline fit in double precision (validation, merging, null-space solve), shared by every
 *  ThinPlateSpline<Scalar, Dim>. Internal; use ThinPlateSpline.
 */
#include <Eigen/Core>

#include <string>

namespace morphreg
{
namespace detail
{
/** \brief Parameters of one fit. */
struct TpsFitOptions
{
  double regularization = 0.0;       ///< lambda >= 0 (0: exact interpolation)
  double max_condition_number = 0.0; ///< larger estimates are a NumericalError
  std::string caller;                ///< prefix of error messages, e.g. "ThinPlateSpline::fit"
};

/** \brief A fitted spline in double precision, landmarks merged. */
struct TpsFit
{
  Eigen::MatrixXd landmarks; ///< n x d distinct source landmarks
  Eigen::MatrixXd weights;   ///< n x d, W
  Eigen::MatrixXd affine;    ///< (d+1) x d, A
  double bending_energy = 0.0;
  double condition_estimate = 0.0;
  Eigen::Index merged = 0; ///< landmark pairs dropped as duplicates of an earlier pair
};

/** \brief Fits the d-dimensional (d = rows of \a source, 2 or 3) spline mapping the columns of \a source to those of
 *  \a target. Throws InvalidInputError for degenerate input and NumericalError for an ill-conditioned system.
 */
TpsFit
fitThinPlateSpline (const Eigen::MatrixXd& source, const Eigen::MatrixXd& target, const TpsFitOptions& options);

} // namespace detail
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file robust_kernels.h
 *  \brief The robust (IRLS) kernels of the registrations: weights of residual distances and their automatic width.
 */
#include <vector>

namespace morphreg
{
/** \brief Robust (IRLS) weighting of the correspondence residuals. */
enum class RobustLoss
{
  none,  ///< plain least squares
  huber, ///< weight min(1, c / d)
  tukey  ///< weight (1 - (d / c)^2)^2 inside c, 0 beyond
};

/** \brief The IRLS weight of a residual distance.
 *  \param[in] loss the kernel
 *  \param[in] distance the residual distance d (>= 0)
 *  \param[in] width the kernel width c (> 0)
 *  \return the weight in [0, 1]
 */
double
robustWeight (RobustLoss loss, double distance, double width);

/** \brief The kernel width: \a scale if > 0, else 1.345 (Huber) or 4.685 (Tukey) times the robust standard
 *  deviation 1.4826 MAD of \a distances (their median absolute value; at least 1e-6).
 *  \param[in] loss the kernel
 *  \param[in] distances the residual distances
 *  \param[in] scale a fixed width, or <= 0 for the automatic one
 *  \return the width c
 */
double
robustKernelWidth (RobustLoss loss, const std::vector<double>& distances, double scale);
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file procrustes.h
 *  \brief Generalised Procrustes alignment of shapes in correspondence (rigid: rotation and translation).
 */
#include <Eigen/Core>

#include <vector>

namespace morphreg
{
/** \brief Rigidly aligns every shape (3 x N, same N) to their common mean, iterating until the mean settles.
 *  The mean is kept in the frame of the first shape. Scale is not removed: head size is part of the shape
 *  variation a head model must describe. Throws InvalidInputError for fewer than two shapes or mismatched sizes.
 *  \param[in,out] shapes the shapes, aligned in place
 *  \param[in] max_iterations the most alignment rounds
 *  \param[in] tolerance the rounds stop when the mean moves less than this (relative)
 */
void
alignGeneralisedProcrustes (std::vector<Eigen::Matrix3Xd>& shapes, int max_iterations = 50, double tolerance = 1e-9);

/** \brief As above for shapes stored as the columns of \a shapes (3N x M, x y z interleaved per point), aligned in
 *  place: the layout of a PCA data matrix, which then needs no copy. Throws InvalidInputError for fewer than two
 *  columns or a row count that is not a multiple of 3.
 *  \param[in,out] shapes one shape per column, aligned in place
 *  \param[in] max_iterations the most alignment rounds
 *  \param[in] tolerance the rounds stop when the mean moves less than this (relative)
 */

void
alignGeneralisedProcrustes (Eigen::MatrixXd& shapes, int max_iterations = 50, double tolerance = 1e-9);

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file pca.h
 *  \brief Principal component analysis of a centred data matrix (one training shape per column), by a thin SVD
 *  or by the M x M Gram matrix of Turk & Pentland, whichever suits the matrix shape.
 */
#include <Eigen/Core>

#include <vector>

namespace morphreg
{
/** \brief How to compute the PCA of a 3N x M data matrix. */
enum class PcaMethod
{
  automatic, ///< Gram matrix when 3N >= 4M (few, large shapes), thin SVD otherwise
  thin_svd,  ///< Eigen::BDCSVD of the data matrix
  gram       ///< eigen-decomposition of D^T D; the basis is checked and re-orthonormalised if needed
};

/** \brief Orthonormal principal directions (columns, by decreasing variance) and their variances. */
struct PcaBasis
{
  Eigen::MatrixXd basis;     ///< one orthonormal column per component
  Eigen::VectorXd variances; ///< sample variances: squared singular value / (M - 1)
};

/** \brief PCA of \a centred (rows: coordinates, columns: M >= 2 centred samples), keeping the leading
 *  components chosen by componentsToKeep (\a max_components, \a explained_fraction); only those are formed.
 *  Directions whose singular value is at rounding-error level are dropped, so with no limit the basis spans exactly
 *  the data. Throws InvalidInputError for fewer than two samples, non-finite data or a fraction outside (0, 1].
 *  \param[in] centred the centred data matrix
 *  \param[in] method Gram matrix, thin SVD or the cheaper of the two
 *  \param[in] max_components at most this many components (<= 0: no limit)
 *  \param[in] explained_fraction the fewest components explaining this fraction of the variance
 *  \return the basis and variances
 */
PcaBasis
computePca (const Eigen::MatrixXd& centred, PcaMethod method = PcaMethod::automatic, int max_components = 0,
            double explained_fraction = 1.0);

/** \brief PCA of the rows of several vertex sets of one data matrix at once (the regions of a model, which may
 *  overlap, and the whole mesh): \a centred has 3 rows (x, y, z) per vertex and one centred sample per column; each
 *  set lists vertex indices, and its basis has 3 rows per listed vertex in that order. Same method choice,
 *  truncation and results as computePca on each set's rows, but the work is shared: the rows are grouped into blocks
 *  of vertices that belong to the same sets, each block's Gram matrix is formed once and summed into the Gram matrix
 *  of every set that contains it. \a centred is taken by value and reordered in place (move it in to save memory).
 *  Throws InvalidInputError as computePca does, and for an empty set, a vertex out of range or listed twice.
 *  \param[in] centred the centred data matrix, 3 rows per vertex
 *  \param[in] vertex_sets the vertex indices of each set
 *  \param[in] method as computePca
 *  \param[in] max_components as computePca, per set
 *  \param[in] explained_fraction as computePca, per set
 *  \return one basis per set, in the order of \a vertex_sets
 */
std::vector<PcaBasis>
computeVertexSetPcas (Eigen::MatrixXd centred, const std::vector<std::vector<int>>& vertex_sets,
                      PcaMethod method = PcaMethod::automatic, int max_components = 0, double explained_fraction = 1.0);

/** \brief The number of leading components to keep: at most \a max_components (<= 0: no limit) and the fewest
 *  whose cumulative variance reaches \a explained_fraction (in (0, 1]) of the total.
 *  \param[in] variances the component variances, decreasing
 *  \param[in] max_components the limit on the count
 *  \param[in] explained_fraction the share of the variance to explain
 *  \return the number of components
 */
int
componentsToKeep (const Eigen::VectorXd& variances, int max_components, double explained_fraction);

/** \brief Cumulative explained-variance fractions of \a variances (non-decreasing, last entry 1).
 *  \param[in] variances the component variances
 *  \return entry k: the share of the total variance in components 0..k
 */

Eigen::VectorXd
explainedVariance (const Eigen::VectorXd& variances);

} // namespace morphreg

#pragma once
/** \file pca.h
 *  \brief Principal component analysis of a centred data matrix (one training shape per column), by a thin SVD
 *  or by the M x M Gram matrix of Turk & Pentland, whichever suits the matrix shape.
 */
#include <Eigen/Core>

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
  Eigen::MatrixXd basis;
  Eigen::VectorXd variances; ///< sample variances: squared singular value / (M - 1)
};

/** \brief PCA of \a centred (rows: coordinates, columns: M >= 2 centred samples), keeping the leading
 *  components chosen by componentsToKeep (\a max_components, \a explained_fraction); only those are formed.
 *  Directions whose singular value is at rounding-error level are dropped, so with no limit the basis spans exactly
 *  the data. Throws InvalidInputError for fewer than two samples, non-finite data or a fraction outside (0, 1].
 */
PcaBasis
computePca (const Eigen::MatrixXd& centred, PcaMethod method = PcaMethod::automatic, int max_components = 0,
            double explained_fraction = 1.0);

/** \brief The number of leading components to keep: at most \a max_components (<= 0: no limit) and the fewest
 *  whose cumulative variance reaches \a explained_fraction (in (0, 1]) of the total.
 */
int
componentsToKeep (const Eigen::VectorXd& variances, int max_components, double explained_fraction);

/** \brief Cumulative explained-variance fractions of \a variances (non-decreasing, last entry 1). */
Eigen::VectorXd
explainedVariance (const Eigen::VectorXd& variances);

} // namespace morphreg

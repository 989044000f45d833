#include <morphreg/common/error.h>
#include <morphreg/model/pca.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>

namespace morphreg
{
namespace
{
constexpr double kEps = std::numeric_limits<double>::epsilon ();
/** Largest |U^T U - I| accepted before the Gram basis is re-orthonormalised. */
constexpr double kOrthonormalityTolerance = 1e-10;

void
requireFraction (double fraction, const std::string& who)
{
  if (!(fraction > 0.0 && fraction <= 1.0))
    throw InvalidInputError (who + ": explained-variance fraction must be in (0, 1], got " + std::to_string (fraction));
}

PcaBasis
pcaBySvd (const Eigen::MatrixXd& centred, int max_components, double explained_fraction)
{
  const Eigen::BDCSVD<Eigen::MatrixXd> svd (centred, Eigen::ComputeThinU);
  const Eigen::VectorXd& sigma = svd.singularValues ();
  const double cut = sigma.size () ? sigma[0] * kEps * static_cast<double> (std::max (centred.rows (), centred.cols ())) : 0.0;
  Eigen::Index rank = 0;
  while (rank < sigma.size () && sigma[rank] > cut)
    ++rank;
  const Eigen::VectorXd variances = sigma.head (rank).cwiseAbs2 () / static_cast<double> (centred.cols () - 1);
  const int keep = componentsToKeep (variances, max_components, explained_fraction);
  return {svd.matrixU ().leftCols (keep), variances.head (keep)};
}

/** Largest entry of |U^T U - I|. */
double
orthonormalityError (const Eigen::MatrixXd& u, Eigen::MatrixXd& gram)
{
  gram.setZero (u.cols (), u.cols ());
  gram.selfadjointView<Eigen::Lower> ().rankUpdate (u.transpose ());
  gram = gram.selfadjointView<Eigen::Lower> ();
  return (gram - Eigen::MatrixXd::Identity (u.cols (), u.cols ())).cwiseAbs ().maxCoeff ();
}

PcaBasis
pcaByGram (const Eigen::MatrixXd& centred, int max_components, double explained_fraction)
{
  const Eigen::Index m = centred.cols ();
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero (m, m);
  gram.selfadjointView<Eigen::Lower> ().rankUpdate (centred.transpose ());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen (gram.selfadjointView<Eigen::Lower> ());
  if (eigen.info () != Eigen::Success)
    throw NumericalError ("computePca: eigen-decomposition of the Gram matrix failed");
  // Eigenvalues ascending; an eigenvalue of D^T D is only known to about eps * lambda_max * M.
  const Eigen::VectorXd lambda = eigen.eigenvalues ().reverse ();
  const double cut = lambda[0] * 100.0 * kEps * static_cast<double> (m);
  Eigen::Index rank = 0;
  while (rank < m && lambda[rank] > cut)
    ++rank;
  // Only the kept components are formed: U = D V diag(1 / sigma).
  const Eigen::Index keep = componentsToKeep (lambda.head (rank), max_components, explained_fraction);
  const Eigen::MatrixXd v = eigen.eigenvectors ().rowwise ().reverse ().leftCols (keep);
  PcaBasis pca;
  pca.basis = (centred * v) * lambda.head (keep).cwiseSqrt ().cwiseInverse ().asDiagonal ();
  pca.variances = lambda.head (keep) / static_cast<double> (m - 1);
  // Small components amplify rounding errors of the Gram matrix: check, and re-orthonormalise by Cholesky-QR.
  double error = orthonormalityError (pca.basis, gram);
  for (int pass = 0; pass < 3 && error > kOrthonormalityTolerance; ++pass) {
    const Eigen::LLT<Eigen::MatrixXd> llt (gram);
    if (llt.info () != Eigen::Success)
      return pcaBySvd (centred, max_components, explained_fraction);
    pca.basis = llt.matrixU ().solve<Eigen::OnTheRight> (pca.basis);
    error = orthonormalityError (pca.basis, gram);
  }
  return error > kOrthonormalityTolerance ? pcaBySvd (centred, max_components, explained_fraction) : pca;
}
} // namespace

PcaBasis
computePca (const Eigen::MatrixXd& centred, PcaMethod method, int max_components, double explained_fraction)
{
  if (centred.cols () < 2)
    throw InvalidInputError ("computePca: at least two samples are needed, got " + std::to_string (centred.cols ()));
  if (centred.rows () == 0 || !centred.allFinite ())
    throw InvalidInputError ("computePca: the data matrix is empty or has non-finite values");
  if (method == PcaMethod::automatic)
    method = centred.rows () >= 4 * centred.cols () ? PcaMethod::gram : PcaMethod::thin_svd;
  requireFraction (explained_fraction, "computePca");
  return method == PcaMethod::gram ? pcaByGram (centred, max_components, explained_fraction)
                                   : pcaBySvd (centred, max_components, explained_fraction);
}

int
componentsToKeep (const Eigen::VectorXd& variances, int max_components, double explained_fraction)
{
  requireFraction (explained_fraction, "componentsToKeep");
  const auto available = static_cast<int> (variances.size ());
  int keep = available;
  if (explained_fraction < 1.0) {
    const Eigen::VectorXd explained = explainedVariance (variances);
    keep = 0;
    while (keep < available && explained[keep] < explained_fraction)
      ++keep;
    keep = std::min (keep + 1, available);
  }
  return max_components > 0 ? std::min (keep, max_components) : keep;
}

Eigen::VectorXd
explainedVariance (const Eigen::VectorXd& variances)
{
  Eigen::VectorXd cumulative (variances.size ());
  double sum = 0.0;
  for (Eigen::Index k = 0; k < variances.size (); ++k)
    cumulative[k] = (sum += variances[k]);
  return sum > 0.0 ? Eigen::VectorXd (cumulative / sum) : cumulative;
}

} // namespace morphreg

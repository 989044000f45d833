// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/model/pca.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

namespace morphreg
{
namespace
{
constexpr double kEps = std::numeric_limits<double>::epsilon ();
/** Largest |U^T U - I| accepted before the Gram basis is re-orthonormalised. */
constexpr double kOrthonormalityTolerance = 1e-10;
/** Rows per block of the large products (spread over the OpenMP threads). */
constexpr Eigen::Index kRowBlock = 512;

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
  const double cut =
      sigma.size () ? sigma[0] * kEps * static_cast<double> (std::max (centred.rows (), centred.cols ())) : 0.0;
  Eigen::Index rank = 0;
  while (rank < sigma.size () && sigma[rank] > cut)
    ++rank;
  const Eigen::VectorXd variances = sigma.head (rank).cwiseAbs2 () / static_cast<double> (centred.cols () - 1);
  const int keep = componentsToKeep (variances, max_components, explained_fraction);
  return {svd.matrixU ().leftCols (keep), variances.head (keep)};
}

// Large products run as independent blocks of rows spread over the OpenMP threads, each a single-threaded Eigen
// product: as fast as Eigen's own threading on idle cores, and far less sensitive to cores shared with other work.

Eigen::Index
numRowBlocks (Eigen::Index rows)
{
  return (rows + kRowBlock - 1) / kRowBlock;
}

/** A block of at most kRowBlock rows: rows source .. source + count of the data go to rows target .. of a basis. */
struct RowBlock
{
  Eigen::Index source, target, count;
};

/** Appends the blocks that send \a count rows from \a source on to \a target on. */
void
appendRowBlocks (Eigen::Index source, Eigen::Index target, Eigen::Index count, std::vector<RowBlock>& blocks)
{
  for (Eigen::Index done = 0; done < count; done += kRowBlock)
    blocks.push_back ({source + done, target + done, std::min (kRowBlock, count - done)});
}

/** Basis rows = data rows * \a weights, block by block in one parallel loop; \a target may be \a source's own
 *  storage when every block maps rows onto themselves.
 */
template <typename Target>
void
multiplyRowBlocks (const Eigen::MatrixXd& source, const std::vector<RowBlock>& blocks, const Eigen::MatrixXd& weights,
                   Target&& target)
{
#pragma omp parallel if (blocks.size() > 1)
  {
    Eigen::MatrixXd product;
#pragma omp for schedule(dynamic)
    for (std::size_t b = 0; b < blocks.size (); ++b) {
      product.noalias () = source.middleRows (blocks[b].source, blocks[b].count) * weights;
      target.middleRows (blocks[b].target, blocks[b].count) = product;
    }
  }
}

/** Largest entry of |U^T U - I|; \a gram receives U^T U. */
double
orthonormalityError (const Eigen::MatrixXd& u, Eigen::MatrixXd& gram)
{
  gram.setZero (u.cols (), u.cols ());
  if (u.cols () == 0) // no components (data without variation): trivially orthonormal
    return 0.0;
#pragma omp parallel if (u.rows() > kRowBlock)
  {
    Eigen::MatrixXd partial = Eigen::MatrixXd::Zero (u.cols (), u.cols ());
#pragma omp for schedule(dynamic) nowait
    for (Eigen::Index b = 0; b < numRowBlocks (u.rows ()); ++b) {
      const Eigen::Index row = b * kRowBlock, count = std::min (kRowBlock, u.rows () - row);
      partial.selfadjointView<Eigen::Lower> ().rankUpdate (u.middleRows (row, count).transpose ());
    }
#pragma omp critical
    gram += partial;
  }
  gram = gram.selfadjointView<Eigen::Lower> ();
  return (gram - Eigen::MatrixXd::Identity (u.cols (), u.cols ())).cwiseAbs ().maxCoeff ();
}

/** The kept components of a data matrix D from its Gram matrix D^T D (lower triangle filled): the basis is
 *  D * weights, weights = V diag(1 / sigma), and variances = sigma^2 / (M - 1).
 */
struct GramComponents
{
  Eigen::MatrixXd weights;
  Eigen::VectorXd variances;
};

GramComponents
gramComponents (const Eigen::MatrixXd& gram, int max_components, double explained_fraction)
{
  const Eigen::Index m = gram.cols ();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen (gram.selfadjointView<Eigen::Lower> ());
  if (eigen.info () != Eigen::Success)
    throw NumericalError ("computePca: eigen-decomposition of the Gram matrix failed");
  // Eigenvalues ascending; an eigenvalue of D^T D is only known to about eps * lambda_max * M.
  const Eigen::VectorXd lambda = eigen.eigenvalues ().reverse ();
  const double cut = lambda[0] * 100.0 * kEps * static_cast<double> (m);
  Eigen::Index rank = 0;
  while (rank < m && lambda[rank] > cut)
    ++rank;
  const Eigen::Index keep = componentsToKeep (lambda.head (rank), max_components, explained_fraction);
  GramComponents components;
  components.weights = eigen.eigenvectors ().rowwise ().reverse ().leftCols (keep) *
                       lambda.head (keep).cwiseSqrt ().cwiseInverse ().asDiagonal ();
  components.variances = lambda.head (keep) / static_cast<double> (m - 1);
  return components;
}

/** Cheap confirmation that U^T U = I to the tolerance: |U^T (U x) - x| <= tol * |x|_1 for a few fixed random
 *  +-1 vectors x (a bound every entry of U^T U - I within the tolerance satisfies).
 */
bool
probablyOrthonormal (const Eigen::MatrixXd& u)
{
  std::mt19937 random (1);
  const Eigen::MatrixXd x =
      Eigen::MatrixXd::NullaryExpr (u.cols (), 4, [&] () { return (random () & 1u) ? 1.0 : -1.0; });
  const Eigen::MatrixXd ux = u * x;
  const Eigen::MatrixXd residual = u.transpose () * ux - x;
  return residual.cwiseAbs ().maxCoeff () <= kOrthonormalityTolerance * static_cast<double> (u.cols ());
}

/** Small components amplify the rounding errors of the Gram matrix: checks \a basis and, if needed,
 *  re-orthonormalises it in place by Cholesky-QR. The basis is then already orthonormal to about 1e-6, so one pass
 *  brings it to rounding level; a random probe confirms that instead of another full U^T U. Should Cholesky-QR fail
 *  (a badly conditioned basis), Householder QR, which is unconditionally stable, takes over.
 */
void
makeOrthonormal (Eigen::MatrixXd& basis)
{
  Eigen::MatrixXd gram;
  double error = orthonormalityError (basis, gram);
  for (int pass = 0; pass < 2 && error > kOrthonormalityTolerance; ++pass) {
    const Eigen::LLT<Eigen::MatrixXd> llt (gram);
    if (llt.info () != Eigen::Success)
      break;
#pragma omp parallel for schedule(dynamic) if (basis.rows() > kRowBlock)
    for (Eigen::Index b = 0; b < numRowBlocks (basis.rows ()); ++b) {
      const Eigen::Index row = b * kRowBlock, count = std::min (kRowBlock, basis.rows () - row);
      llt.matrixU ().solveInPlace<Eigen::OnTheRight> (basis.middleRows (row, count));
    }
    if (probablyOrthonormal (basis))
      return;
    error = orthonormalityError (basis, gram);
  }
  if (error <= kOrthonormalityTolerance)
    return;
  const Eigen::HouseholderQR<Eigen::Ref<Eigen::MatrixXd>> qr (basis); // in place
  const Eigen::VectorXd signs = qr.matrixQR ().diagonal ().cwiseSign ();
  basis = (qr.householderQ () * Eigen::MatrixXd::Identity (basis.rows (), basis.cols ())) * signs.asDiagonal ();
}

PcaBasis
pcaByGram (const Eigen::MatrixXd& centred, int max_components, double explained_fraction)
{
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero (centred.cols (), centred.cols ());
  gram.selfadjointView<Eigen::Lower> ().rankUpdate (centred.transpose ());
  GramComponents components = gramComponents (gram, max_components, explained_fraction);
  PcaBasis pca;
  pca.basis.resize (centred.rows (), components.weights.cols ());
  std::vector<RowBlock> blocks;
  appendRowBlocks (0, 0, centred.rows (), blocks);
  multiplyRowBlocks (centred, blocks, components.weights, pca.basis);
  pca.variances = std::move (components.variances);
  makeOrthonormal (pca.basis);
  return pca;
}

bool
useGram (PcaMethod method, Eigen::Index rows, Eigen::Index cols)
{
  return method == PcaMethod::gram || (method == PcaMethod::automatic && rows >= 4 * cols);
}

void
requireData (const Eigen::MatrixXd& centred, const char* caller)
{
  if (centred.cols () < 2)
    throw InvalidInputError (std::string (caller) + ": at least two samples are needed, got " +
                             std::to_string (centred.cols ()));
  if (centred.rows () == 0 || !centred.allFinite ())
    throw InvalidInputError (std::string (caller) + ": the data matrix is empty or has non-finite values");
}

/** Vertices grouped by the vertex sets they belong to ("atoms": disjoint, each inside the same sets). */
struct VertexAtoms
{
  std::vector<int> order;                 ///< vertices, atom by atom (vertices in no set left out)
  std::vector<Eigen::Index> begin;        ///< first position in order of each atom, plus the end
  std::vector<std::vector<int>> atoms_of; ///< per vertex set: its atoms
};

VertexAtoms
groupIntoAtoms (Eigen::Index num_vertices, const std::vector<std::vector<int>>& vertex_sets)
{
  std::vector<std::vector<int>> member_of (static_cast<std::size_t> (num_vertices));
  for (std::size_t s = 0; s < vertex_sets.size (); ++s) {
    if (vertex_sets[s].empty ())
      throw InvalidInputError ("computeVertexSetPcas: vertex set " + std::to_string (s) + " is empty");
    for (int v : vertex_sets[s]) {
      if (v < 0 || v >= num_vertices)
        throw InvalidInputError ("computeVertexSetPcas: vertex set " + std::to_string (s) + " has vertex " +
                                 std::to_string (v) + ", outside [0, " + std::to_string (num_vertices) + ")");
      auto& sets = member_of[static_cast<std::size_t> (v)];
      if (!sets.empty () && sets.back () == static_cast<int> (s))
        throw InvalidInputError ("computeVertexSetPcas: vertex set " + std::to_string (s) + " lists vertex " +
                                 std::to_string (v) + " twice");
      sets.push_back (static_cast<int> (s));
    }
  }
  std::map<std::vector<int>, std::vector<int>> atoms;
  for (std::size_t v = 0; v < member_of.size (); ++v)
    if (!member_of[v].empty ())
      atoms[member_of[v]].push_back (static_cast<int> (v));
  VertexAtoms grouped;
  grouped.atoms_of.resize (vertex_sets.size ());
  for (const auto& [sets, vertices] : atoms) {
    for (int s : sets)
      grouped.atoms_of[static_cast<std::size_t> (s)].push_back (static_cast<int> (grouped.begin.size ()));
    grouped.begin.push_back (static_cast<Eigen::Index> (grouped.order.size ()));
    grouped.order.insert (grouped.order.end (), vertices.begin (), vertices.end ());
  }
  grouped.begin.push_back (static_cast<Eigen::Index> (grouped.order.size ()));
  return grouped;
}

/** Reorders the rows of \a basis, computed atom by atom (3 per vertex of \a atom_ids in atom order), in place into
 *  the order of \a vertex_set, a column at a time (no copy of the matrix: large fresh allocations are costly).
 */
void
reorderToSet (Eigen::MatrixXd& basis, const VertexAtoms& atoms, const std::vector<int>& atom_ids,
              const std::vector<int>& vertex_set, std::vector<Eigen::Index>& position)
{
  for (std::size_t k = 0; k < vertex_set.size (); ++k)
    position[static_cast<std::size_t> (vertex_set[k])] = static_cast<Eigen::Index> (k);
  std::vector<Eigen::Index> target;
  for (int a : atom_ids)
    for (Eigen::Index i = atoms.begin[a]; i < atoms.begin[a + 1]; ++i)
      target.push_back (3 * position[static_cast<std::size_t> (atoms.order[i])]);
  std::vector<double> buffer (static_cast<std::size_t> (basis.rows ()));
  Eigen::Map<Eigen::VectorXd> column (buffer.data (), basis.rows ());
  for (Eigen::Index c = 0; c < basis.cols (); ++c) {
    column = basis.col (c);
    for (std::size_t i = 0; i < target.size (); ++i)
      basis.col (c).segment<3> (target[i]) = column.segment<3> (3 * static_cast<Eigen::Index> (i));
  }
}
/** Reorders the rows of \a centred in place, atom by atom, so that every atom is one block of rows. */
void
reorderRowsByAtoms (Eigen::MatrixXd& centred, const VertexAtoms& atoms)
{
  std::vector<double> buffer (static_cast<std::size_t> (centred.rows ()));
  Eigen::Map<Eigen::VectorXd> column (buffer.data (), centred.rows ());
  for (Eigen::Index c = 0; c < centred.cols (); ++c) {
    column = centred.col (c);
    for (std::size_t i = 0; i < atoms.order.size (); ++i)
      centred.col (c).segment<3> (3 * static_cast<Eigen::Index> (i)) = column.segment<3> (3 * atoms.order[i]);
  }
}

/** Number of data rows of atom \a a (3 per vertex). */
Eigen::Index
atomRows (const VertexAtoms& atoms, int a)
{
  return 3 * (atoms.begin[static_cast<std::size_t> (a) + 1] - atoms.begin[static_cast<std::size_t> (a)]);
}

/** The rows of atom \a a of the atom-ordered data \a centred. */
Eigen::Block<const Eigen::MatrixXd>
atomBlock (const Eigen::MatrixXd& centred, const VertexAtoms& atoms, int a)
{
  return centred.middleRows (3 * atoms.begin[static_cast<std::size_t> (a)], atomRows (atoms, a));
}

/** The rows of the atoms \a atom_ids (\a num_rows in all) copied into one matrix. */
Eigen::MatrixXd
gatherAtoms (const Eigen::MatrixXd& centred, const VertexAtoms& atoms, const std::vector<int>& atom_ids,
             Eigen::Index num_rows)
{
  Eigen::MatrixXd local (num_rows, centred.cols ());
  Eigen::Index row = 0;
  for (int a : atom_ids) {
    local.middleRows (row, atomRows (atoms, a)) = atomBlock (centred, atoms, a);
    row += atomRows (atoms, a);
  }
  return local;
}

/** Each atom's Gram matrix: a set's Gram matrix is the sum of its atoms', so each row of the data enters once. */
std::vector<Eigen::MatrixXd>
atomGrams (const Eigen::MatrixXd& centred, const VertexAtoms& atoms)
{
  std::vector<Eigen::MatrixXd> grams (atoms.begin.size () - 1);
  for (std::size_t a = 0; a < grams.size (); ++a) {
    grams[a].setZero (centred.cols (), centred.cols ());
    grams[a].selfadjointView<Eigen::Lower> ().rankUpdate (
        atomBlock (centred, atoms, static_cast<int> (a)).transpose ());
  }
  return grams;
}

/** The order in which the sets are computed: a Gram-method set holding every atom (the whole mesh) goes last, its
 *  basis formed in place of the data matrix; \a in_place is its index (vertex_sets.size () if there is none).
 */
std::vector<std::size_t>
setSequence (const std::vector<std::vector<int>>& vertex_sets, const VertexAtoms& atoms, PcaMethod method,
             Eigen::Index num_samples, std::size_t& in_place)
{
  const std::size_t num_atoms = atoms.begin.size () - 1;
  in_place = vertex_sets.size ();
  for (std::size_t s = 0; s < vertex_sets.size (); ++s)
    if (atoms.atoms_of[s].size () == num_atoms &&
        useGram (method, 3 * static_cast<Eigen::Index> (vertex_sets[s].size ()), num_samples))
      in_place = s;
  std::vector<std::size_t> sequence;
  for (std::size_t s = 0; s < vertex_sets.size (); ++s)
    if (s != in_place)
      sequence.push_back (s);
  if (in_place < vertex_sets.size ())
    sequence.push_back (in_place);
  return sequence;
}

/** PCA of one set by its Gram matrix (the sum of \a grams over its atoms); with \a in_place, the basis overwrites
 *  \a centred (each block of D * weights replaces the rows it comes from, so no second 3N x M matrix is allocated).
 */
PcaBasis
setPcaByGram (Eigen::MatrixXd& centred, const VertexAtoms& atoms, const std::vector<int>& atom_ids,
              const std::vector<Eigen::MatrixXd>& grams, int max_components, double explained_fraction, bool in_place)
{
  Eigen::MatrixXd gram = Eigen::MatrixXd::Zero (centred.cols (), centred.cols ());
  for (int a : atom_ids)
    gram += grams[static_cast<std::size_t> (a)];
  GramComponents components = gramComponents (gram, max_components, explained_fraction);
  const Eigen::Index keep = components.weights.cols ();
  std::vector<RowBlock> blocks;
  Eigen::Index row = 0;
  for (int a : atom_ids) {
    appendRowBlocks (3 * atoms.begin[static_cast<std::size_t> (a)], row, atomRows (atoms, a), blocks);
    row += atomRows (atoms, a);
  }
  PcaBasis pca;
  if (in_place) {
    multiplyRowBlocks (centred, blocks, components.weights, centred.leftCols (keep));
    centred.conservativeResize (row, keep);
    pca.basis = std::move (centred);
  }
  else {
    pca.basis.resize (row, keep);
    multiplyRowBlocks (centred, blocks, components.weights, pca.basis);
  }
  pca.variances = std::move (components.variances);
  makeOrthonormal (pca.basis);
  return pca;
}
} // namespace

std::vector<PcaBasis>
computeVertexSetPcas (Eigen::MatrixXd centred, const std::vector<std::vector<int>>& vertex_sets, PcaMethod method,
                      int max_components, double explained_fraction)
{
  requireData (centred, "computeVertexSetPcas");
  requireFraction (explained_fraction, "computeVertexSetPcas");
  if (centred.rows () % 3 != 0)
    throw InvalidInputError ("computeVertexSetPcas: the data matrix has " + std::to_string (centred.rows ()) +
                             " rows, not 3 per vertex");
  const VertexAtoms atoms = groupIntoAtoms (centred.rows () / 3, vertex_sets);
  reorderRowsByAtoms (centred, atoms);
  const std::vector<Eigen::MatrixXd> grams = atomGrams (centred, atoms);
  std::size_t in_place = 0;
  const std::vector<std::size_t> sequence = setSequence (vertex_sets, atoms, method, centred.cols (), in_place);
  std::vector<Eigen::Index> position (static_cast<std::size_t> (centred.rows () / 3));
  std::vector<PcaBasis> pcas (vertex_sets.size ());
  for (std::size_t s : sequence) {
    const std::vector<int>& atom_ids = atoms.atoms_of[s];
    const Eigen::Index set_rows = 3 * static_cast<Eigen::Index> (vertex_sets[s].size ());
    if (useGram (method, set_rows, centred.cols ()))
      pcas[s] = setPcaByGram (centred, atoms, atom_ids, grams, max_components, explained_fraction, s == in_place);
    else
      pcas[s] = pcaBySvd (gatherAtoms (centred, atoms, atom_ids, set_rows), max_components, explained_fraction);
    reorderToSet (pcas[s].basis, atoms, atom_ids, vertex_sets[s], position);
  }
  return pcas;
}

PcaBasis
computePca (const Eigen::MatrixXd& centred, PcaMethod method, int max_components, double explained_fraction)
{
  requireData (centred, "computePca");
  requireFraction (explained_fraction, "computePca");
  return useGram (method, centred.rows (), centred.cols ()) ? pcaByGram (centred, max_components, explained_fraction)
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

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/mesh/cotangent_weights.h>

#include <algorithm>
#include <vector>

namespace morphreg
{
Eigen::SparseMatrix<double>
cotangentWeights (const TriangleMesh& mesh, double floor)
{
  std::vector<Eigen::Triplet<double>> halves;
  halves.reserve (static_cast<std::size_t> (6 * mesh.numTriangles ()));
  for (Eigen::Index t = 0; t < mesh.numTriangles (); ++t)
    for (int k = 0; k < 3; ++k) {
      const int i = mesh.triangles (k, t), j = mesh.triangles ((k + 1) % 3, t), o = mesh.triangles ((k + 2) % 3, t);
      const Eigen::Vector3d a = mesh.vertices.col (i) - mesh.vertices.col (o);
      const Eigen::Vector3d b = mesh.vertices.col (j) - mesh.vertices.col (o);
      const double half_cot = 0.5 * a.dot (b) / std::max (a.cross (b).norm (), 1e-12);
      halves.emplace_back (i, j, half_cot);
      halves.emplace_back (j, i, half_cot);
    }
  Eigen::SparseMatrix<double> weights (mesh.numVertices (), mesh.numVertices ());
  weights.setFromTriplets (halves.begin (), halves.end ()); // sums the two halves of an inner edge
  for (Eigen::Index k = 0; k < weights.outerSize (); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it (weights, k); it; ++it)
      it.valueRef () = std::max (it.value (), floor);
  return weights;
}

Eigen::SparseMatrix<double>
graphLaplacian (const Eigen::SparseMatrix<double>& weights)
{
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve (static_cast<std::size_t> (weights.nonZeros () + weights.rows ()));
  for (Eigen::Index k = 0; k < weights.outerSize (); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it (weights, k); it; ++it) {
      entries.emplace_back (it.row (), it.col (), -it.value ());
      entries.emplace_back (it.row (), it.row (), it.value ());
    }
  Eigen::SparseMatrix<double> laplacian (weights.rows (), weights.cols ());
  laplacian.setFromTriplets (entries.begin (), entries.end ());
  return laplacian;
}

} // namespace morphreg

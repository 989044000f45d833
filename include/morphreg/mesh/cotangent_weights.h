// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file cotangent_weights.h
 *  \brief The cotangent weights of a triangle mesh's edges, the usual discretisation of the Laplace-Beltrami
 *  operator, for sparse solvers on the mesh.
 */
#include <morphreg/mesh/triangle_mesh.h>

#include <Eigen/SparseCore>

namespace morphreg
{
/** \brief Symmetric edge weights w_ij = (cot alpha + cot beta) / 2 over the angles opposite the edge (one angle on
 *  a border edge), each at least \a floor: obtuse triangles give negative cotangents, which would make the Laplacian
 *  indefinite.
 *  \param[in] mesh the mesh (its vertices in the rest pose)
 *  \param[in] floor the smallest weight kept
 *  \return numVertices () x numVertices (), non-zero exactly on the edges
 */
Eigen::SparseMatrix<double>
cotangentWeights (const TriangleMesh& mesh, double floor = 1e-3);

/** \brief The Laplacian L = D - W of symmetric edge weights W (D: their row sums), positive semi-definite.
 *  \param[in] weights edge weights, e.g. cotangentWeights()
 *  \return the Laplacian
 */
Eigen::SparseMatrix<double>
graphLaplacian (const Eigen::SparseMatrix<double>& weights);

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file as_rigid_as_possible.h
 *  \brief As-rigid-as-possible surface refinement (Sorkine and Alexa 2007) towards given positions, with the sparse
 *  system factorised once.
 */
#include <morphreg/mesh/triangle_mesh.h>

#include <Eigen/SparseCholesky>

#include <memory>

namespace morphreg
{
/** \brief Moves the vertices of a rest mesh towards data positions while keeping each vertex's neighbourhood as close
 *  to a rotation of its rest shape as possible: minimises
 *  rigidity * sum_i sum_j w_ij |(x_i - x_j) - R_i (p_i - p_j)|^2 + sum_i c_i |x_i - d_i|^2
 *  over the positions x and one rotation R_i per vertex (p: rest positions, w: cotangent weights, d: data positions,
 *  c: data weights), alternating the best rotations for fixed positions and the best positions for fixed rotations.
 *  The positions' system (rigidity L + diag(c)) depends on the rest mesh and the weights only: it is factorised once
 *  (Eigen's SimplicialLDLT) on construction, and every iteration is three back-substitutions.
 */
class AsRigidAsPossible
{
public:
  using Ptr = std::shared_ptr<AsRigidAsPossible>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const AsRigidAsPossible>; ///< shared pointer to const

  /** \brief Builds and factorises the system. Throws InvalidInputError for a rigidity or a data weight that is
   *  negative or not finite, a weight count that differs from the vertex count, or no positive data weight (the
   *  positions would then be free to translate); NumericalError if the factorisation fails.
   *  \param[in] rest the mesh in its rest shape (the shape to keep locally)
   *  \param[in] rigidity the weight of the rigidity term against the data term (0: the data positions)
   *  \param[in] data_weights c_i, one per vertex, >= 0
   */
  AsRigidAsPossible (const TriangleMesh& rest, double rigidity, const Eigen::VectorXd& data_weights);

  /** \brief \a iterations alternations of rotations and positions, starting from \a data.
   *  \param[in] data the data positions d, one column per vertex (mm)
   *  \param[in] iterations the number of alternations (>= 0; 0 returns \a data)
   *  \return the refined positions
   */
  Eigen::Matrix3Xd
  refine (const Eigen::Matrix3Xd& data, int iterations) const;

private:
  /** The best rotation per vertex for the current \a positions. */
  std::vector<Eigen::Matrix3d>
  bestRotations (const Eigen::Matrix3Xd& positions) const;

  Eigen::Matrix3Xd rest_;
  Eigen::SparseMatrix<double> weights_;
  Eigen::VectorXd data_weights_;
  double rigidity_;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver_;
};

} // namespace morphreg

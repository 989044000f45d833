// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/cotangent_weights.h>
#include <morphreg/warp/as_rigid_as_possible.h>

#include <Eigen/SVD>

#include <cmath>
#include <string>

namespace morphreg
{
namespace
{
void
requireWeights (double rigidity, const Eigen::VectorXd& data_weights, Eigen::Index vertices)
{
  if (!(rigidity >= 0.0) || !std::isfinite (rigidity))
    throw InvalidInputError ("AsRigidAsPossible: the rigidity must be a finite number >= 0, got " +
                             std::to_string (rigidity));
  if (data_weights.size () != vertices)
    throw InvalidInputError ("AsRigidAsPossible: " + std::to_string (data_weights.size ()) + " data weights for " +
                             std::to_string (vertices) + " vertices");
  if (!data_weights.allFinite () || data_weights.minCoeff () < 0.0)
    throw InvalidInputError ("AsRigidAsPossible: data weights must be finite and >= 0");
  if (data_weights.maxCoeff () <= 0.0)
    throw InvalidInputError ("AsRigidAsPossible: at least one data weight must be positive");
}
} // namespace

AsRigidAsPossible::AsRigidAsPossible (const TriangleMesh& rest, double rigidity, const Eigen::VectorXd& data_weights)
  : rest_ (rest.vertices), data_weights_ (data_weights), rigidity_ (rigidity)
{
  validateMesh (rest, "as-rigid-as-possible rest mesh");
  requireWeights (rigidity, data_weights, rest.numVertices ());
  weights_ = cotangentWeights (rest);
  Eigen::SparseMatrix<double> system = rigidity * graphLaplacian (weights_);
  for (Eigen::Index i = 0; i < system.rows (); ++i)
    system.coeffRef (i, i) += data_weights (i); // every diagonal entry exists: each vertex has an edge
  solver_.compute (system);
  if (solver_.info () != Eigen::Success)
    throw NumericalError ("AsRigidAsPossible: the factorisation of the " + std::to_string (system.rows ()) + " x " +
                          std::to_string (system.rows ()) + " system failed");
}

std::vector<Eigen::Matrix3d>
AsRigidAsPossible::bestRotations (const Eigen::Matrix3Xd& positions) const
{
  std::vector<Eigen::Matrix3d> covariances (static_cast<std::size_t> (rest_.cols ()), Eigen::Matrix3d::Zero ());
  for (Eigen::Index k = 0; k < weights_.outerSize (); ++k)
    for (Eigen::SparseMatrix<double>::InnerIterator it (weights_, k); it; ++it)
      covariances[static_cast<std::size_t> (it.row ())] +=
          it.value () * (rest_.col (it.row ()) - rest_.col (it.col ())) *
          (positions.col (it.row ()) - positions.col (it.col ())).transpose ();
  for (Eigen::Matrix3d& covariance : covariances) {
    const Eigen::JacobiSVD<Eigen::Matrix3d> svd (covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
    Eigen::Matrix3d v = svd.matrixV ();
    if ((v * svd.matrixU ().transpose ()).determinant () < 0.0)
      v.col (2) *= -1.0; // a reflection: flip the axis of the smallest singular value
    covariance = v * svd.matrixU ().transpose ();
  }
  return covariances;
}

Eigen::Matrix3Xd
AsRigidAsPossible::refine (const Eigen::Matrix3Xd& data, int iterations) const
{
  if (data.cols () != rest_.cols () || !data.allFinite ())
    throw InvalidInputError ("AsRigidAsPossible::refine: " + std::to_string (data.cols ()) + " data positions for " +
                             std::to_string (rest_.cols ()) + " vertices, or a position that is not finite");
  const Eigen::Matrix3Xd weighted_data = data * data_weights_.asDiagonal ();
  Eigen::Matrix3Xd positions = data;
  for (int iteration = 0; iteration < iterations; ++iteration) {
    const std::vector<Eigen::Matrix3d> rotations = bestRotations (positions);
    Eigen::Matrix3Xd rhs = weighted_data;
    for (Eigen::Index k = 0; k < weights_.outerSize (); ++k)
      for (Eigen::SparseMatrix<double>::InnerIterator it (weights_, k); it; ++it)
        rhs.col (it.row ()) +=
            rigidity_ * 0.5 * it.value () *
            (rotations[static_cast<std::size_t> (it.row ())] + rotations[static_cast<std::size_t> (it.col ())]) *
            (rest_.col (it.row ()) - rest_.col (it.col ()));
    for (int axis = 0; axis < 3; ++axis)
      positions.row (axis) = solver_.solve (rhs.row (axis).transpose ()).transpose ();
  }
  return positions;
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
// A model read from a file is checked for consistency: a scaled basis, a repeated triangle corner, an absurd
// coordinate or copies of the mean that disagree are refused naming the part; a sound model passes.
#include <morphreg/common/error.h>
#include <morphreg/model/model_consistency.h>

#include "support/expect_error.h"

#include <gtest/gtest.h>

namespace
{
using morphreg::test::expectErrorContaining;

morphreg::MorphableModel::Ptr
tetrahedron (const Eigen::MatrixXd& basis, double first_coordinate = 0.0, int corner = 1)
{
  morphreg::TriangleMesh::Triangles triangles (3, 4);
  triangles << 0, 0, 0, 1, 1, 2, 3, 2, 2, 3, 1, 3;
  triangles (1, 0) = corner; // 1 in the sound tetrahedron
  Eigen::VectorXd mean (12);
  mean << first_coordinate, 0, 0, 100, 0, 0, 0, 100, 0, 0, 0, 100;
  return morphreg::MorphableModel::fromGlobalPca (triangles, mean, basis, Eigen::Vector2d (4.0, 1.0));
}

Eigen::MatrixXd
orthonormalBasis (double scale = 1.0)
{
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero (12, 2);
  basis (0, 0) = scale;
  basis (4, 1) = 1.0;
  return basis;
}

TEST (ModelConsistencyTest, ASoundModelPasses)
{
  EXPECT_NO_THROW (morphreg::requireConsistentModel (*tetrahedron (orthonormalBasis ()), "sound.h5"));
}

TEST (ModelConsistencyTest, EachInconsistencyIsNamed)
{
  expectErrorContaining<morphreg::FormatError> (
      [] { morphreg::requireConsistentModel (*tetrahedron (orthonormalBasis (1000.0)), "scaled.h5"); },
      "scaled.h5: the basis of region 'global' is not orthonormal: column 0 has length 1000");
  Eigen::MatrixXd skewed = orthonormalBasis ();
  skewed (0, 1) = 0.5;
  skewed.col (1).normalize ();
  expectErrorContaining<morphreg::FormatError> (
      [&] { morphreg::requireConsistentModel (*tetrahedron (skewed), "skewed.h5"); }, "have the dot product");
  expectErrorContaining<morphreg::FormatError> (
      [] { morphreg::requireConsistentModel (*tetrahedron (orthonormalBasis (), 0.0, 0), "degenerate.h5"); },
      "degenerate.h5: triangle 0 (0, 0, 2) repeats a vertex");
  expectErrorContaining<morphreg::FormatError> (
      [] { morphreg::requireConsistentModel (*tetrahedron (orthonormalBasis (), 1e30), "huge.h5"); },
      "huge.h5: the mean's vertex 0 has the coordinate");
}

TEST (ModelConsistencyTest, CopiesOfTheMeanMustAgreeToTheirPrecision)
{
  Eigen::VectorXd mean (6);
  mean << 0.0, 95.25, -120.5, 1e-9, 3.0, 1000.0;
  const Eigen::VectorXd as_float = mean.cast<float> ().cast<double> ();
  EXPECT_NO_THROW (morphreg::requireSameMean (mean, as_float, "m.h5", "the copies"));
  Eigen::VectorXd flipped = mean;
  flipped[4] *= 2.0;
  expectErrorContaining<morphreg::FormatError> (
      [&] { morphreg::requireSameMean (mean, flipped, "m.h5", "the copies"); },
      "m.h5: the copies disagree at vertex 1");
}
} // namespace

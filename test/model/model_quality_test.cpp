// SPDX-License-Identifier: BSD-3-Clause
#include "population.h"

#include <morphreg/common/error.h>
#include <morphreg/model/model_builder.h>
#include <morphreg/model/model_quality.h>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cmath>

using morphreg::MorphableModel;
using morphreg::TriangleMesh;

namespace
{
const std::vector<TriangleMesh>&
training ()
{
  static const std::vector<TriangleMesh> instance = morphreg::test::trainingMeshes (12);
  return instance;
}

MorphableModel::Ptr
trainingModel ()
{
  static const MorphableModel::Ptr model = morphreg::ModelBuilder ().buildGlobal (training ());
  return model;
}

/** A one-component model of a 4 x 4 grid (10 mm spacing, in the xy plane) whose component moves the vertices
 *  along z by +-1/4 in a checkerboard (not a rigid motion: alignment leaves it), with variance \a variance; its
 *  two training shapes lie at -sigma and +sigma along it. */
MorphableModel::Ptr
gridModel (double variance, std::vector<TriangleMesh>& shapes)
{
  const int side = 4, n = side * side;
  Eigen::Matrix3Xd mean (3, n);
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero (3 * n, 1);
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) {
      mean.col (i * side + j) = Eigen::Vector3d (10.0 * i, 10.0 * j, 0.0);
      basis (3 * (i * side + j) + 2, 0) = ((i + j) % 2 == 0 ? 0.25 : -0.25);
    }
  TriangleMesh::Triangles triangles (3, 2 * (side - 1) * (side - 1));
  for (int i = 0, t = 0; i + 1 < side; ++i)
    for (int j = 0; j + 1 < side; ++j) {
      const int v = i * side + j;
      triangles.col (t++) = Eigen::Vector3i (v, v + side, v + side + 1);
      triangles.col (t++) = Eigen::Vector3i (v, v + side + 1, v + 1);
    }
  const Eigen::Map<const Eigen::VectorXd> mean_vector (mean.data (), mean.size ());
  for (const double sign : {-1.0, 1.0}) {
    const Eigen::VectorXd shape = mean_vector + sign * std::sqrt (variance) * basis.col (0);
    shapes.push_back ({Eigen::Map<const Eigen::Matrix3Xd> (shape.data (), 3, n), triangles});
  }
  return MorphableModel::fromGlobalPca (triangles, mean_vector, basis, Eigen::VectorXd::Constant (1, variance));
}
} // namespace

TEST (ModelQualityTest, CompactnessRisesToOne)
{
  const Eigen::VectorXd share = morphreg::compactness (*trainingModel ());
  const Eigen::VectorXd& variances = trainingModel ()->globalVariances ();
  ASSERT_EQ (share.size (), variances.size ());
  EXPECT_NEAR (share[0], variances[0] / variances.sum (), 1e-12);
  for (Eigen::Index k = 1; k < share.size (); ++k)
    EXPECT_GE (share[k], share[k - 1]);
  EXPECT_NEAR (share[share.size () - 1], 1.0, 1e-12);
}

TEST (ModelQualityTest, TrainingMeshesAreReproducedWithAllComponents)
{
  const MorphableModel& model = *trainingModel ();
  const int all = static_cast<int> (model.globalVariances ().size ());
  EXPECT_LT (morphreg::generalisation (model, training (), all).mean, 1e-4);
  // Pose does not count: a training mesh turned and moved is still reproduced.
  TriangleMesh moved = training ()[3];
  const Eigen::Affine3d pose =
      Eigen::Translation3d (40.0, -7.0, 3.0) * Eigen::AngleAxisd (0.4, Eigen::Vector3d::UnitY ());
  moved.vertices = pose * moved.vertices;
  EXPECT_LT (morphreg::generalisation (model, {moved}, all).mean, 1e-4);
}

TEST (ModelQualityTest, GeneralisationOfUnseenHeadsFallsWithComponentsButStaysPositive)
{
  const MorphableModel& model = *trainingModel ();
  const std::vector<TriangleMesh> unseen = morphreg::test::trainingMeshes (6, 99);
  const int all = static_cast<int> (model.globalVariances ().size ());
  const double none = morphreg::generalisation (model, unseen, 0).mean;
  const double half = morphreg::generalisation (model, unseen, all / 2).mean;
  const double every = morphreg::generalisation (model, unseen, all).mean;
  EXPECT_GT (none, half);
  EXPECT_GT (half, every);
  EXPECT_GT (every, 1e-3); // unseen heads are not all in the span of 12 training heads
}

TEST (ModelQualityTest, SpecificityOfAGridModelMatchesItsExpectation)
{
  // Samples c ~ N(0, s^2) along a component moving each vertex by c / 4; the training shapes lie at c = -s and +s,
  // so the closest is at mean vertex distance | |c| - s | / 4, whose expectation is s / 4 * E| |z| - 1 | with
  // E| |z| - 1 | = 2 (2 Phi(1) + 2 phi(1) - phi(0) - 3/2) = 0.53538 (z standard normal).
  std::vector<TriangleMesh> shapes;
  const MorphableModel::Ptr model = gridModel (9.0, shapes);
  const double expected = 3.0 / 4.0 * 0.53538;
  const morphreg::QualityMeasure measured = morphreg::specificity (*model, shapes, 1, 4000, 1);
  // A sampling tolerance, not an accuracy bound: 4 % is about four standard errors (1 %) of a mean of 4000 samples.
  EXPECT_NEAR (measured.mean, expected, 0.04 * expected);
  // With no component every sample is the mean, at distance s / sqrt(n) of both training shapes.
  EXPECT_NEAR (morphreg::specificity (*model, shapes, 0, 10, 1).mean, 3.0 / 4.0, 1e-9);
  // Fixed seed: the same figure twice.
  EXPECT_EQ (morphreg::specificity (*model, shapes, 1, 100, 5).mean,
             morphreg::specificity (*model, shapes, 1, 100, 5).mean);
}

TEST (ModelQualityTest, BadArgumentsAreRefused)
{
  const MorphableModel& model = *trainingModel ();
  const int all = static_cast<int> (model.globalVariances ().size ());
  EXPECT_THROW (morphreg::generalisation (model, training (), all + 1), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::generalisation (model, {}, 1), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::specificity (model, training (), 1, 0, 1), morphreg::InvalidInputError);
  std::vector<TriangleMesh> grid_shapes;
  gridModel (1.0, grid_shapes);
  EXPECT_THROW (morphreg::specificity (model, grid_shapes, 1, 10, 1), morphreg::InvalidInputError);
}

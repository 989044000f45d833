// SPDX-License-Identifier: BSD-3-Clause
// The solver, the convergence rules and the boundary rejector on small problems with known answers.
#include <morphreg/common/error.h>
#include <morphreg/registration/correspondence_rejection_target_boundary.h>
#include <morphreg/registration/morphable_convergence.h>
#include <morphreg/fitting/pose_shape_least_squares.h>

#include <Eigen/Geometry>

#include <gtest/gtest.h>

#include <algorithm>
#include <memory>
#include <vector>

namespace
{
using morphreg::PoseShapeLeastSquares;
using morphreg::PoseShapeRow;
using morphreg::PoseShapeState;

TEST (PoseShapeLeastSquaresTest, SimilarityOnlyRecoversAKnownSimilarity)
{
  const Eigen::Matrix3Xd points = Eigen::Matrix3Xd::Random (3, 50) * 100.0;
  Eigen::Matrix4d truth = Eigen::Matrix4d::Identity ();
  truth.topLeftCorner<3, 3> () = 1.1 * Eigen::AngleAxisd (0.3, Eigen::Vector3d (1, 2, 3).normalized ()).matrix ();
  truth.topRightCorner<3, 1> () = Eigen::Vector3d (5, -10, 20);
  const Eigen::Matrix3Xd targets = (truth.topLeftCorner<3, 3> () * points).colwise () + truth.topRightCorner<3, 1> ();
  std::vector<PoseShapeRow> rows;
  for (int i = 0; i < points.cols (); ++i)
    rows.push_back ({i, targets.col (i), Eigen::Matrix3d::Identity ()});
  const PoseShapeLeastSquares solver;
  PoseShapeState state = solver.state (Eigen::Matrix4d::Identity (), Eigen::VectorXd ());
  state.vertices = points;
  for (int it = 0; it < 20; ++it)
    ASSERT_TRUE (solver.step (state, rows));
  EXPECT_LT ((state.similarity () - truth).norm (), 1e-6);
  EXPECT_LT (solver.cost (state, rows), 1e-12);
}

TEST (PoseShapeLeastSquaresTest, FixedScaleStaysFixedAndStepsNeverRaiseTheCost)
{
  const Eigen::Matrix3Xd points = Eigen::Matrix3Xd::Random (3, 30) * 50.0;
  std::vector<PoseShapeRow> rows;
  for (int i = 0; i < points.cols (); ++i)
    rows.push_back ({i, 2.0 * points.col (i) + Eigen::Vector3d (1, 2, 3), Eigen::Matrix3d::Identity ()});
  const PoseShapeLeastSquares solver (false);
  PoseShapeState state = solver.state (Eigen::Matrix4d::Identity (), Eigen::VectorXd ());
  state.vertices = points;
  double cost = solver.cost (state, rows);
  for (int it = 0; it < 10; ++it) {
    ASSERT_TRUE (solver.step (state, rows));
    const double next = solver.cost (state, rows);
    EXPECT_LE (next, cost);
    cost = next;
  }
  EXPECT_DOUBLE_EQ (state.scale (), 1.0);
}

TEST (PoseShapeLeastSquaresTest, TooFewRowsFollowOneRule)
{
  EXPECT_NO_THROW (morphreg::requireEnoughRows (7, 7, "test", "rows", "the input"));
  EXPECT_THROW (morphreg::requireEnoughRows (6, 7, "test", "rows", "the input"), morphreg::TooFewCorrespondencesError);
  morphreg::PoseShapeSettings settings;
  settings.smoothness_weight = -1.0;
  EXPECT_THROW (settings.validate ("test"), morphreg::InvalidInputError);
}

TEST (MorphableConvergenceTest, BudgetEpsilonsAndDivergence)
{
  morphreg::MorphableConvergence convergence (10, 1e-4, 0.0, 2.0, 2);
  convergence.startPhase (3, true, Eigen::VectorXd::Ones (1));
  int iterations = 0;
  while (!convergence.hasConverged ()) {
    ASSERT_TRUE (convergence.checkCost (1.0 - 0.1 * iterations));
    convergence.update (true, 1.0, Eigen::VectorXd::Zero (1));
    ++iterations;
  }
  EXPECT_EQ (iterations, 3);
  EXPECT_EQ (convergence.termination (), morphreg::IcpTermination::max_iterations);
  EXPECT_EQ (convergence.remaining (), 7);

  convergence.startPhase (5, true, Eigen::VectorXd::Ones (1));
  ASSERT_TRUE (convergence.checkCost (1.0));
  convergence.update (true, 1e-6, Eigen::VectorXd::Zero (1));
  EXPECT_TRUE (convergence.hasConverged ());
  EXPECT_EQ (convergence.termination (), morphreg::IcpTermination::transformation_converged);

  convergence.startPhase (5, true, Eigen::VectorXd::Ones (1));
  EXPECT_TRUE (convergence.checkCost (1.0));
  EXPECT_TRUE (convergence.improved ());
  EXPECT_TRUE (convergence.checkCost (2.0));
  EXPECT_FALSE (convergence.checkCost (2.0)) << "two rises in a row above 1.05 times the best";
  EXPECT_EQ (convergence.divergence (), morphreg::IcpDivergence::cost_rose);
  EXPECT_EQ (convergence.termination (), morphreg::IcpTermination::diverged);
}

TEST (MorphableConvergenceTest, PriorExceededAndUnsolvable)
{
  morphreg::MorphableConvergence prior (10, 1e-4, 0.0, 2.0, 3);
  prior.startPhase (5, true, Eigen::VectorXd::Ones (2));
  prior.checkCost (1.0);
  prior.update (true, 1.0, Eigen::Vector2d (0.0, 2.5));
  EXPECT_EQ (prior.divergence (), morphreg::IcpDivergence::prior_exceeded);
  morphreg::MorphableConvergence unsolvable (10, 1e-4, 0.0, 2.0, 3);
  unsolvable.startPhase (5, false, Eigen::VectorXd ());
  unsolvable.checkCost (1.0);
  unsolvable.update (false, 0.0, Eigen::VectorXd ());
  EXPECT_EQ (unsolvable.divergence (), morphreg::IcpDivergence::unsolvable);
  EXPECT_EQ (unsolvable.iterations (), 0);
}

TEST (CorrespondenceRejectorTargetBoundaryTest, RejectsTheBorderOfAPlaneAndSmoothsNothingAway)
{
  // A 21 x 21 grid in the plane z = 0: its border points are boundary points, its inner ones are not.
  Eigen::Matrix3Xd grid (3, 21 * 21);
  for (int y = 0; y < 21; ++y)
    for (int x = 0; x < 21; ++x)
      grid.col (y * 21 + x) = Eigen::Vector3d (x, y, 0.0);
  const auto search = [&grid] (pcl::index_t i, int k, pcl::Indices& indices, std::vector<float>& squared) {
    std::vector<std::pair<double, int>> order;
    for (Eigen::Index j = 0; j < grid.cols (); ++j)
      order.push_back ({(grid.col (j) - grid.col (i)).squaredNorm (), static_cast<int> (j)});
    std::partial_sort (order.begin (), order.begin () + k, order.end ());
    indices.clear ();
    squared.clear ();
    for (int n = 0; n < k; ++n) {
      indices.push_back (order[n].second);
      squared.push_back (static_cast<float> (order[n].first));
    }
  };
  auto surface = std::make_shared<morphreg::TargetSurface> ();
  surface->setInputTarget (grid, Eigen::Matrix3Xd (), search);
  morphreg::CorrespondenceRejectorTargetBoundary rejector (surface);
  pcl::Correspondences all;
  for (int i = 0; i < grid.cols (); ++i)
    all.emplace_back (i, i, 0.0f);
  pcl::Correspondences inside;
  rejector.getRemainingCorrespondences (all, inside);
  for (const pcl::Correspondence& c : inside) {
    const Eigen::Vector3d p = grid.col (c.index_match);
    EXPECT_TRUE (p.x () > 0 && p.x () < 20 && p.y () > 0 && p.y () < 20) << "border point kept: " << p.transpose ();
    EXPECT_LT ((surface->point (c.index_match) - p).norm (), 1e-9);
  }
  EXPECT_GT (inside.size (), 15u * 15u);
  morphreg::CorrespondenceRejectorTargetBoundary unset;
  EXPECT_THROW (unset.getRemainingCorrespondences (all, inside), morphreg::InvalidInputError);
}

} // namespace

// SPDX-License-Identifier: BSD-3-Clause
// Use case: warp one synthetic head onto another head's landmarks (the foundation's population).
#include <morphreg/warp/thin_plate_spline.h>
#include <morphreg/synthetic/head_generator.h>

#include "support/accuracy_bound.h"
#include "tps_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>

using morphreg::synthetic::HeadGenerator;

TEST (TpsTest, WarpsSyntheticHeadOntoAnotherHeadsLandmarks)
{
  const HeadGenerator generator;
  const auto heads = generator.population (4, 31);
  std::vector<int> ids;
  for (const auto& entry : generator.landmarks ())
    ids.push_back (entry.second);
  ASSERT_GE (ids.size (), 20u);
  const auto landmarks = [&] (const morphreg::TriangleMesh& mesh) {
    Eigen::Matrix3Xd points (3, ids.size ());
    for (std::size_t k = 0; k < ids.size (); ++k)
      points.col (k) = mesh.vertices.col (ids[k]);
    return points;
  };
  const morphreg::TriangleMesh& base = heads[0].mesh;
  double before_sum = 0.0, after_sum = 0.0, after_max = 0.0, ratio_max = 0.0;
  for (int other = 1; other < 4; ++other) {
    const morphreg::TriangleMesh& subject = heads[other].mesh;
    morphreg::ThinPlateSpline<double, 3> tps;
    tps.fit (landmarks (base), landmarks (subject));
    const morphreg::TriangleMesh warped = tps.transformMesh (base);
    EXPECT_LE (morphreg::test::maxColumnDistance (landmarks (warped), landmarks (subject)),
               1e-9 * morphreg::test::extent (subject.vertices));
    const double before = (base.vertices - subject.vertices).colwise ().norm ().mean ();
    const double after = (warped.vertices - subject.vertices).colwise ().norm ().mean ();
    std::cout << "head " << other << ": " << ids.size () << " landmarks, mean vertex error " << before << " -> "
              << after << " mm, max " << (warped.vertices - subject.vertices).colwise ().norm ().maxCoeff () << "\n";
    before_sum += before / 3.0;
    after_sum += after / 3.0;
    after_max = std::max (after_max, after);
    ratio_max = std::max (ratio_max, after / before);
  }
  // The warp leaves 1.65-3.96 mm (mean 2.95 mm) of the 3.09-6.74 mm (mean 5.36 mm) the base head lies from the others
  // (the no-op: the identity warp), at most 0.633 of it: landmarks alone cannot fix the shape between them.
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, after_sum, 3.4);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, after_max, 4.5);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, ratio_max, 0.7);
  EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, before_sum, 3.4);
}

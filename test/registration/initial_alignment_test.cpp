// SPDX-License-Identifier: BSD-3-Clause
// robustCoarseSimilarity: a synthetic head's known pose recovered from a protocol scan (holes, noise, outliers),
// and clear errors for bad input.
#include "scan_protocol.h"

#include <morphreg/common/cloud_matrix.h>

#include <morphreg/common/error.h>
#include <morphreg/registration/initial_alignment.h>
#include <morphreg/synthetic/head_generator.h>

#include <pcl/search/kdtree.h>

#include "support/accuracy_bound.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

#include <atomic>

#include <Eigen/Geometry>

#include <cmath>
#include <limits>

namespace
{
/** The scan's points as columns. */
Eigen::Matrix3Xd
scanPoints (const morphreg::test::ProtocolScan& scan)
{
  return morphreg::pointsOf (*scan.cloud);
}
} // namespace

TEST (InitialAlignmentTest, RobustCoarseSimilarityRecoversTheProtocolPose)
{
  const morphreg::synthetic::HeadGenerator generator;
  const morphreg::TriangleMesh head = generator.sample (7).mesh;
  double worst_angle = 0.0, worst_scale = 0.0, worst_rms = 0.0;
  for (std::uint64_t seed : {11u, 12u, 13u, 14u}) {
    const auto scan = morphreg::test::simulateProtocolScan (head, generator.landmarks (), seed);
    const Eigen::Matrix4d found = morphreg::robustCoarseSimilarity (head.vertices, scanPoints (scan));

    const Eigen::Matrix3d true_linear = scan.pose.topLeftCorner<3, 3> ();
    const Eigen::Matrix3d found_linear = found.topLeftCorner<3, 3> ();
    const double true_scale = std::cbrt (true_linear.determinant ());
    const double found_scale = std::cbrt (found_linear.determinant ());
    const double angle_deg =
        Eigen::AngleAxisd ((found_linear / found_scale) * (true_linear / true_scale).transpose ()).angle () * 180.0 /
        M_PI;
    const Eigen::Matrix3Xd posed = (found_linear * head.vertices).colwise () + found.topRightCorner<3, 1> ();
    const double rms = std::sqrt ((posed - scan.truth).colwise ().squaredNorm ().mean ());
    std::printf ("[ coarse ] seed %d: %.2f degrees off, scale ratio %.4f, vertex RMS %.3f mm\n",
                 static_cast<int> (seed), angle_deg, found_scale / true_scale, rms);
    worst_angle = std::max (worst_angle, angle_deg);
    worst_scale = std::max (worst_scale, std::abs (found_scale / true_scale - 1.0));
    worst_rms = std::max (worst_rms, rms);
  }
  // The start only has to land in the fit's basin; measured: 2.05 degrees, 0.09 % of scale and 3.0 mm at worst.
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, worst_angle, 2.6) << "degrees off the true rotation";
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, worst_scale, 0.0011) << "relative scale error";
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, worst_rms, 3.2) << "vertex RMS against the posed truth (mm)";
}

TEST (InitialAlignmentTest, RobustCoarseSimilarityUsesTheCallersNeighbourSearch)
{
  const morphreg::synthetic::HeadGenerator generator;
  const morphreg::TriangleMesh head = generator.sample (7).mesh;
  const auto scan = morphreg::test::simulateProtocolScan (head, generator.landmarks (), 11);
  const Eigen::Matrix3Xd target = scanPoints (scan);
  pcl::search::KdTree<pcl::PointNormal> tree;
  tree.setInputCloud (scan.cloud);
  std::atomic<long> calls{0};
  const auto neighbours = [&] (Eigen::Index i, int k, pcl::Indices& indices, std::vector<float>& squared) {
    ++calls;
    tree.nearestKSearch ((*scan.cloud)[i], k, indices, squared);
  };
  const Eigen::Matrix4d own_tree = morphreg::robustCoarseSimilarity (head.vertices, target);
  const Eigen::Matrix4d callers_tree = morphreg::robustCoarseSimilarity (head.vertices, target, neighbours);
  EXPECT_EQ (calls.load (), target.cols ()) << "one neighbourhood query per target point";
  EXPECT_TRUE (callers_tree.isApprox (own_tree, 1e-9)) << callers_tree << "\nvs\n" << own_tree;
}

TEST (InitialAlignmentTest, RobustCoarseSimilarityRejectsBadInput)
{
  const morphreg::synthetic::HeadGenerator generator;
  const Eigen::Matrix3Xd head = generator.sample (7).mesh.vertices;
  EXPECT_THROW (morphreg::robustCoarseSimilarity (head, Eigen::Matrix3Xd (3, 0)), morphreg::InvalidInputError);
  Eigen::Matrix3Xd with_nan = head;
  with_nan (1, 100) = std::numeric_limits<double>::quiet_NaN ();
  EXPECT_THROW (morphreg::robustCoarseSimilarity (head, with_nan), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::robustCoarseSimilarity (with_nan, head), morphreg::InvalidInputError);
  const Eigen::Matrix3Xd same_point = Eigen::Matrix3Xd::Ones (3, 10);
  EXPECT_THROW (morphreg::robustCoarseSimilarity (head, same_point), morphreg::InvalidInputError);
  morphreg::CoarseAlignmentSettings settings;
  settings.inlier_fraction = 0.0;
  EXPECT_THROW (morphreg::robustCoarseSimilarity (head, head, settings), morphreg::InvalidInputError);
  settings = morphreg::CoarseAlignmentSettings ();
  settings.survivors = 0;
  EXPECT_THROW (morphreg::robustCoarseSimilarity (head, head, settings), morphreg::InvalidInputError);
  settings = morphreg::CoarseAlignmentSettings ();
  settings.screen_iterations = -1;
  EXPECT_THROW (morphreg::robustCoarseSimilarity (head, head, settings), morphreg::InvalidInputError);
}

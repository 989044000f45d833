// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private to the library: the trimmed similarity-only ICP and the closest-point helpers that the coarse start
// (initial_alignment.cpp) and the global start (global_alignment.cpp) share.
#include <pcl/point_types.h>
#include <pcl/search/kdtree.h>

#include <Eigen/Core>

#include <vector>

namespace morphreg
{
namespace detail
{
using PointTree = pcl::search::KdTree<pcl::PointXYZ>;

/** A k-d tree over the columns of \a points. */
PointTree::Ptr
pointTree (const Eigen::Matrix3Xd& points);

/** Every stride-th column of \a points, for about \a count columns. */
Eigen::Matrix3Xd
evenSamples (const Eigen::Matrix3Xd& points, int count);

/** \a points mapped by the similarity (or any affine 4 x 4) \a transform. */
Eigen::Matrix3Xd
transformed (const Eigen::Matrix4d& transform, const Eigen::Matrix3Xd& points);

/** Closest point of a tree (its index) and the distance, per query point. */
struct Closest
{
  std::vector<int> index;
  std::vector<double> distance;
};

/** Serial: callers run several hypotheses in parallel, each on a few thousand points (too few to share out). */
Closest
closestPoints (const PointTree& tree, const Eigen::Matrix3Xd& points);

/** Trimmed point-to-plane similarity-only ICP of \a samples onto \a target (the points of \a tree, with unit
 *  \a normals; their sign does not matter), from \a pose: up to \a iterations PoseShapeLeastSquares steps without
 *  shape unknowns (rotation and scale about \a centre), each on the \a inlier_fraction closest pairs as rows with
 *  the metric n n^T.
 */
Eigen::Matrix4d
refineSimilarity (const PointTree::Ptr& tree, const Eigen::Matrix3Xd& target, const Eigen::Matrix3Xd& normals,
                  const Eigen::Vector3d& centre, const Eigen::Matrix3Xd& samples, Eigen::Matrix4d pose, int iterations,
                  double inlier_fraction);

/** The similarity x -> scale R (x - from) + to. */
Eigen::Matrix4d
similarityAbout (double scale, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& from, const Eigen::Vector3d& to);

/** The uniform scale of the similarity \a transform (cube root of its linear part's determinant). */
double
similarityScale (const Eigen::Matrix4d& transform);

/** The rotation angle (radians) of the similarity \a transform. */
double
similarityAngle (const Eigen::Matrix4d& transform);

} // namespace detail
} // namespace morphreg

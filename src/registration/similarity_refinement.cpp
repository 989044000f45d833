// SPDX-License-Identifier: BSD-3-Clause
#include "similarity_refinement.h"

#include <morphreg/common/order_statistics.h>

#include <morphreg/registration/cached_correspondence_estimation.h>
#include <morphreg/fitting/pose_shape_least_squares.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>

namespace morphreg
{
namespace detail
{
namespace
{
/** Whether \a points are finite as the float coordinates the k-d tree takes (a diverging pose overflows them). */
bool
representable (const Eigen::Matrix3Xd& points)
{
  return (points.array ().abs () < 1e30).all ();
}

/** The closest points through \a estimation (on the tree's target), which caches what its last call found. */
Closest
closestPoints (CachedCorrespondenceEstimation<pcl::PointXYZ, pcl::PointXYZ>& estimation, const Eigen::Matrix3Xd& points)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  cloud->resize (points.cols ());
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    (*cloud)[i].getVector3fMap () = points.col (i).cast<float> ();
  estimation.setInputSource (cloud);
  pcl::Correspondences found;
  estimation.determineCorrespondences (found);
  Closest closest{std::vector<int> (points.cols ()), std::vector<double> (points.cols ())};
  for (const pcl::Correspondence& c : found) {
    closest.index[c.index_query] = c.index_match;
    closest.distance[c.index_query] = std::sqrt (static_cast<double> (c.distance));
  }
  return closest;
}

/** The state of \a pose with \a samples about the preimage of \a centre, so that the solver's rotation and scaling
 *  turn about \a centre; \a pivot is that preimage. */
PoseShapeState
aboutCentre (const PoseShapeLeastSquares& solver, const Eigen::Matrix4d& pose, const Eigen::Vector3d& centre,
             const Eigen::Matrix3Xd& samples, Eigen::Vector3d& pivot)
{
  pivot = pose.topLeftCorner<3, 3> ().inverse () * (centre - pose.topRightCorner<3, 1> ());
  PoseShapeState state = solver.state (pose, Eigen::VectorXd ());
  state.translation = centre;
  state.vertices = samples.colwise () - pivot;
  return state;
}
} // namespace

PointTree::Ptr
pointTree (const Eigen::Matrix3Xd& points)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  cloud->resize (points.cols ());
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    (*cloud)[i].getVector3fMap () = points.col (i).cast<float> ();
  PointTree::Ptr tree (new PointTree);
  tree->setInputCloud (cloud);
  return tree;
}

Eigen::Matrix3Xd
evenSamples (const Eigen::Matrix3Xd& points, int count)
{
  const Eigen::Index stride = std::max<Eigen::Index> (1, points.cols () / count);
  Eigen::Matrix3Xd samples (3, (points.cols () + stride - 1) / stride);
  for (Eigen::Index i = 0; i < samples.cols (); ++i)
    samples.col (i) = points.col (i * stride);
  return samples;
}

Eigen::Matrix3Xd
transformed (const Eigen::Matrix4d& transform, const Eigen::Matrix3Xd& points)
{
  return (transform.topLeftCorner<3, 3> () * points).colwise () + transform.topRightCorner<3, 1> ();
}

Closest
closestPoints (const PointTree& tree, const Eigen::Matrix3Xd& points)
{
  Closest closest{std::vector<int> (points.cols ()), std::vector<double> (points.cols ())};
  for (Eigen::Index i = 0; i < points.cols (); ++i) {
    pcl::PointXYZ query;
    query.getVector3fMap () = points.col (i).cast<float> ();
    pcl::Indices index (1);
    std::vector<float> squared (1);
    tree.nearestKSearch (query, 1, index, squared);
    closest.index[i] = index[0];
    closest.distance[i] = std::sqrt (static_cast<double> (squared[0]));
  }
  return closest;
}

Eigen::Matrix4d
refineSimilarity (const PointTree::Ptr& tree, const Eigen::Matrix3Xd& target, const Eigen::Matrix3Xd& normals,
                  const Eigen::Vector3d& centre, const Eigen::Matrix3Xd& samples, Eigen::Matrix4d pose, int iterations,
                  double inlier_fraction)
{
  const PoseShapeLeastSquares solver;
  // The samples move less each step, so the cached estimation skips most of the tree queries.
  CachedCorrespondenceEstimation<pcl::PointXYZ, pcl::PointXYZ> nearest;
  nearest.setInputTarget (tree->getInputCloud ());
  nearest.setSearchMethodTarget (tree, true);
  std::vector<PoseShapeRow> rows;
  for (int iteration = 0; iteration < iterations; ++iteration) {
    Eigen::Vector3d pivot;
    PoseShapeState state = aboutCentre (solver, pose, centre, samples, pivot);
    const Eigen::Matrix3Xd posed = state.posed ();
    if (!representable (posed))
      break;
    const Closest closest = closestPoints (nearest, posed);
    const double limit = trimmedLimit (closest.distance, inlier_fraction);
    rows.clear ();
    for (Eigen::Index i = 0; i < samples.cols (); ++i)
      if (closest.distance[i] <= limit) {
        const Eigen::Vector3d n = normals.col (closest.index[i]);
        rows.push_back ({static_cast<int> (i), target.col (closest.index[i]), n * n.transpose ()});
      }
    if (rows.size () < 7 || !solver.step (state, rows) || !representable (state.posed ()))
      break; // too few rows (see requireEnoughRows), singular or diverging: this hypothesis stops here
    const double motion = (state.posed () - posed).colwise ().squaredNorm ().mean ();
    pose = state.similarity ();
    pose.topRightCorner<3, 1> () -= pose.topLeftCorner<3, 3> () * pivot;
    if (motion < 1e-12)
      break;
  }
  return pose;
}

Eigen::Matrix4d
similarityAbout (double scale, const Eigen::Matrix3d& rotation, const Eigen::Vector3d& from, const Eigen::Vector3d& to)
{
  Eigen::Matrix4d similarity = Eigen::Matrix4d::Identity ();
  similarity.topLeftCorner<3, 3> () = scale * rotation;
  similarity.topRightCorner<3, 1> () = to - scale * rotation * from;
  return similarity;
}

double
similarityScale (const Eigen::Matrix4d& transform)
{
  return std::cbrt (transform.topLeftCorner<3, 3> ().determinant ());
}

double
similarityAngle (const Eigen::Matrix4d& transform)
{
  const Eigen::Matrix3d linear = transform.topLeftCorner<3, 3> ();
  return Eigen::AngleAxisd (Eigen::Matrix3d (linear / similarityScale (transform))).angle ();
}

} // namespace detail
} // namespace morphreg

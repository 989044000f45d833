// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/common/order_statistics.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/registration/initial_alignment.h>

#include "similarity_refinement.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <pcl/search/kdtree.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace morphreg
{
namespace
{
using detail::closestPoints;
using detail::evenSamples;
using detail::PointTree;
using detail::pointTree;
using detail::similarityAbout;
using detail::transformed;

/** Centroid and covariance of the 90 % of \a points nearest to their coordinate-wise median. */
struct RobustMoments
{
  Eigen::Vector3d centroid;
  Eigen::Matrix3d covariance;
};

RobustMoments
trimmedMoments (const Eigen::Matrix3Xd& points)
{
  const Eigen::Matrix3Xd kept = pointsNearMedian (points, 0.9, 4);
  const Eigen::Vector3d centroid = kept.rowwise ().mean ();
  const Eigen::Matrix3Xd centred = kept.colwise () - centroid;
  return {centroid, centred * centred.transpose () / static_cast<double> (kept.cols ())};
}

/** Eigenvectors of \a covariance as columns, by decreasing eigenvalue. */
Eigen::Matrix3d
principalAxes (const Eigen::Matrix3d& covariance)
{
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (covariance);
  return solver.eigenvectors ().rowwise ().reverse ();
}

void
requirePoints (const Eigen::Matrix3Xd& points, Eigen::Index minimum, const std::string& what)
{
  if (points.cols () < minimum)
    throw InvalidInputError (what + ": " + std::to_string (points.cols ()) + " points, at least " +
                             std::to_string (minimum) + " needed");
  if (!points.allFinite ())
    throw InvalidInputError (what + ": points are not finite");
}

/** Robust centroids and the scale matching the trimmed RMS spreads of \a source and \a target. */
struct CoarseFrame
{
  RobustMoments from, to;
  double scale;
};

CoarseFrame
coarseFrame (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target, const std::string& what)
{
  requirePoints (source, 4, what + " (source)");
  requirePoints (target, 4, what + " (target)");
  CoarseFrame frame{trimmedMoments (source), trimmedMoments (target), 0.0};
  if (frame.from.covariance.trace () <= 0.0 || frame.to.covariance.trace () <= 0.0)
    throw InvalidInputError (what + ": the points have no spread");
  frame.scale = std::sqrt (frame.to.covariance.trace () / frame.from.covariance.trace ());
  return frame;
}

/** The proper rotations taking the principal axes of \a from onto those of \a to (matched by extent), in every
 *  sign variant of determinant +1; the first is the one whose axes agree in sign with the source's. */
std::vector<Eigen::Matrix3d>
principalAxisRotations (const Eigen::Matrix3d& from, const Eigen::Matrix3d& to)
{
  const Eigen::Matrix3d axes_from = principalAxes (from);
  Eigen::Matrix3d axes_to = principalAxes (to);
  for (int k = 0; k < 3; ++k)
    if (axes_to.col (k).dot (axes_from.col (k)) < 0.0)
      axes_to.col (k) *= -1.0;
  if ((axes_to * axes_from.transpose ()).determinant () < 0.0)
    axes_to.col (2) *= -1.0;
  std::vector<Eigen::Matrix3d> rotations;
  for (const Eigen::Vector3d& flip : {Eigen::Vector3d (1, 1, 1), Eigen::Vector3d (-1, -1, 1),
                                      Eigen::Vector3d (-1, 1, -1), Eigen::Vector3d (1, -1, -1)})
    rotations.push_back (axes_to * flip.asDiagonal () * axes_from.transpose ());
  return rotations;
}

/** The points of \a target not isolated (their 12th nearest neighbour within 3x the median such distance: drops
 *  scattered outliers) and their unit normals from the principal axes of those 12 neighbours. */
struct SurfacePoints
{
  Eigen::Matrix3Xd points, normals;
};

SurfacePoints
surfacePoints (const Eigen::Matrix3Xd& target, const TargetNeighbourSearch& target_neighbours)
{
  const int k = static_cast<int> (std::min<Eigen::Index> (12, target.cols ()));
  Eigen::Matrix3Xd normals (3, target.cols ());
  std::vector<double> reach (target.cols ());
#pragma omp parallel for schedule(static)
  for (Eigen::Index i = 0; i < target.cols (); ++i) {
    pcl::Indices index;
    std::vector<float> squared;
    target_neighbours (i, k, index, squared);
    Eigen::Matrix3Xd neighbours (3, index.size ());
    for (size_t j = 0; j < index.size (); ++j)
      neighbours.col (j) = target.col (index[j]);
    normals.col (i) = fitPlane (neighbours).normal;
    reach[i] = std::sqrt (static_cast<double> (*std::max_element (squared.begin (), squared.end ())));
  }
  const double limit = 3.0 * trimmedLimit (reach, 0.5);
  SurfacePoints surface{Eigen::Matrix3Xd (3, target.cols ()), Eigen::Matrix3Xd (3, target.cols ())};
  Eigen::Index kept = 0;
  for (Eigen::Index i = 0; i < target.cols (); ++i)
    if (reach[i] <= limit) {
      surface.points.col (kept) = target.col (i);
      surface.normals.col (kept++) = normals.col (i);
    }
  surface.points.conservativeResize (3, kept);
  surface.normals.conservativeResize (3, kept);
  return surface;
}

/** Trimmed mean of the closest-point distances samples -> target and target samples -> posed samples. */
double
symmetricScore (const PointTree& tree, const Eigen::Matrix3Xd& samples, const Eigen::Matrix3Xd& target_samples,
                const Eigen::Matrix4d& pose, double fraction)
{
  const Eigen::Matrix3Xd posed = transformed (pose, samples);
  const double forward = trimmedMean (closestPoints (tree, posed).distance, fraction);
  const double backward = trimmedMean (closestPoints (*pointTree (posed), target_samples).distance, fraction);
  return 0.5 * (forward + backward);
}

void
requireSettings (const CoarseAlignmentSettings& settings)
{
  if (!(settings.sample_points >= 4) || settings.refine_iterations < 0 || settings.screen_iterations < 0 ||
      settings.survivors < 1 || !(settings.inlier_fraction > 0.0) || !(settings.inlier_fraction <= 1.0) ||
      !(settings.tie_tolerance >= 0.0) || !std::isfinite (settings.hypothesis_angle_deg))
    throw InvalidInputError ("robustCoarseSimilarity: the settings need sample_points >= 4, refine_iterations >= 0, "
                             "screen_iterations >= 0, survivors >= 1, "
                             "0 < inlier_fraction <= 1, tie_tolerance >= 0 and a finite hypothesis_angle_deg");
}
} // namespace

Eigen::Matrix4d
similarityFromLandmarks (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target)
{
  requirePoints (source, 3, "similarityFromLandmarks (source)");
  requirePoints (target, 3, "similarityFromLandmarks (target)");
  if (source.cols () != target.cols ())
    throw InvalidInputError ("similarityFromLandmarks: " + std::to_string (source.cols ()) + " source and " +
                             std::to_string (target.cols ()) + " target landmarks");
  for (const Eigen::Matrix3Xd* points : {&source, &target}) {
    const Eigen::Matrix3Xd centred = points->colwise () - points->rowwise ().mean ();
    const Eigen::JacobiSVD<Eigen::Matrix3Xd> svd (centred);
    if (svd.singularValues ()[1] <= 1e-9 * std::max (1.0, svd.singularValues ()[0]))
      throw InvalidInputError ("similarityFromLandmarks: the landmarks are collinear or coincide");
  }
  return Eigen::umeyama (source, target, true);
}

Eigen::Matrix4d
coarseSimilarity (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target, double max_rotation_deg)
{
  const CoarseFrame frame = coarseFrame (source, target, "coarseSimilarity");
  Eigen::Matrix3d rotation = principalAxisRotations (frame.from.covariance, frame.to.covariance).front ();
  if (Eigen::AngleAxisd (rotation).angle () > max_rotation_deg * M_PI / 180.0)
    rotation.setIdentity ();
  return similarityAbout (frame.scale, rotation, frame.from.centroid, frame.to.centroid);
}

Eigen::Matrix4d
robustCoarseSimilarity (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                        const CoarseAlignmentSettings& settings)
{
  requirePoints (target, 4, "robustCoarseSimilarity (target)");
  const auto tree = pointTree (target);
  const auto neighbours = [&tree, &target] (Eigen::Index i, int k, pcl::Indices& indices, std::vector<float>& squared) {
    pcl::PointXYZ query;
    query.getVector3fMap () = target.col (i).cast<float> ();
    tree->nearestKSearch (query, k, indices, squared);
  };
  return robustCoarseSimilarity (source, target, neighbours, settings);
}

Eigen::Matrix4d
robustCoarseSimilarity (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                        const TargetNeighbourSearch& target_neighbours, const CoarseAlignmentSettings& settings)
{
  requireSettings (settings);
  requirePoints (target, 4, "robustCoarseSimilarity (target)");
  const SurfacePoints surface = surfacePoints (target, target_neighbours);
  const CoarseFrame frame = coarseFrame (source, surface.points, "robustCoarseSimilarity");
  std::vector<Eigen::Matrix3d> rotations{Eigen::Matrix3d::Identity ()};
  const double tilt = settings.hypothesis_angle_deg * M_PI / 180.0;
  for (int axis = 0; axis < 3; ++axis)
    for (double sign : {-1.0, 1.0})
      rotations.push_back (Eigen::AngleAxisd (sign * tilt, Eigen::Vector3d::Unit (axis)).toRotationMatrix ());
  for (const Eigen::Matrix3d& rotation : principalAxisRotations (frame.from.covariance, frame.to.covariance))
    rotations.push_back (rotation);

  const PointTree::Ptr tree = pointTree (surface.points);
  const Eigen::Matrix3Xd samples = evenSamples (source, settings.sample_points);
  const Eigen::Matrix3Xd target_samples = evenSamples (surface.points, settings.sample_points);
  const auto count = static_cast<long> (rotations.size ());
  std::vector<Eigen::Matrix4d> poses (count);
  std::vector<double> scores (count);
  for (long h = 0; h < count; ++h)
    poses[h] = similarityAbout (frame.scale, rotations[h], frame.from.centroid, frame.to.centroid);
  // Refines and scores the hypotheses \a active by \a iterations steps each, in parallel (each one serially).
  const auto refine = [&] (const std::vector<long>& active, int iterations) {
#pragma omp parallel for schedule(dynamic, 1)
    for (std::size_t k = 0; k < active.size (); ++k) {
      const long h = active[k];
      poses[h] = detail::refineSimilarity (tree, surface.points, surface.normals, frame.to.centroid, samples, poses[h],
                                           iterations, settings.inlier_fraction);
      scores[h] = symmetricScore (*tree, samples, target_samples, poses[h], settings.inlier_fraction);
    }
  };
  // Screening: every hypothesis a few steps; then only the best-scoring ones run the remaining steps.
  std::vector<long> active (count);
  std::iota (active.begin (), active.end (), 0L);
  const int screening = std::min (settings.screen_iterations, settings.refine_iterations);
  refine (active, screening);
  std::sort (active.begin (), active.end (), [&scores] (long a, long b) { return scores[a] < scores[b]; });
  active.resize (std::min<std::size_t> (active.size (), static_cast<std::size_t> (settings.survivors)));
  refine (active, settings.refine_iterations - screening);

  const double best = scores[*std::min_element (active.begin (), active.end (),
                                                [&scores] (long a, long b) { return scores[a] < scores[b]; })];
  long chosen = active.front ();
  double smallest_angle = std::numeric_limits<double>::infinity ();
  for (const long h : active) {
    const double angle = detail::similarityAngle (poses[h]);
    if (scores[h] <= best * (1.0 + settings.tie_tolerance) && angle < smallest_angle) {
      smallest_angle = angle;
      chosen = h;
    }
  }
  return poses[chosen];
}

} // namespace morphreg

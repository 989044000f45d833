// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file target_surface.h
 *  \brief The registration target as a surface: per point its neighbourhood's plane, the point projected onto it
 *  (smoothing), a normal and whether it lies on the surface's boundary. Shared by MorphableICP's row weights and
 *  CorrespondenceRejectorTargetBoundary, so both see the same points.
 */
#include <pcl/correspondence.h>
#include <pcl/types.h>

#include <Eigen/Core>

#include <cmath>
#include <functional>
#include <optional>
#include <memory>
#include <vector>

namespace morphreg
{
/** \brief Whether TargetSurface projects the target points onto their neighbourhood's plane. */
enum class TargetSmoothing
{
  off,      ///< the raw points: clean scans, where a plane through a curved, sparse neighbourhood only pulls inwards
  on,       ///< the projected points: noisy scans, whose noise then averages out
  automatic ///< on when the target is noisy: its median plane residual is over kNoisyTargetRatio of the
            ///< neighbourhood's radius (depth cameras: about 0.23; laser and photogrammetry scans: 0.02-0.12)
};

/** \brief The noise of a target above which automatic smoothing is on: the median, over points, of the RMS distance
 *  of a point's k nearest neighbours from their plane over the distance to the k-th neighbour. */
constexpr double kNoisyTargetRatio = 0.15;

/** \brief Computed lazily, once per target point when it first becomes a correspondence: the \a k nearest
 *  neighbours' least-squares plane; the point projected onto it (with smoothing; scan noise then averages out instead
 *  of pulling a fit towards the nearest noisy points); the target's own normal where it has a valid one, else the
 *  plane's, turned outwards (see setViewpoint); and the boundary flag: the largest angular gap between the neighbours around the point, in that plane,
 *  exceeds 90 degrees (hole borders, isolated outliers).
 */
class TargetSurface
{
public:
  using Ptr = std::shared_ptr<TargetSurface>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const TargetSurface>; ///< shared pointer to const
  /** \brief The k nearest target points of target point \a index (its indices and squared distances). */
  using NeighbourSearch = std::function<void (pcl::index_t index, int k, pcl::Indices&, std::vector<float>&)>;

  /** \brief Sets the target and forgets what was computed.
   *  \param[in] points the target points (3 x N)
   *  \param[in] normals their normals (3 x N; non-finite or zero where unknown), or empty
   *  \param[in] search the k-nearest-neighbour search over \a points
   */
  void
  setInputTarget (Eigen::Matrix3Xd points, Eigen::Matrix3Xd normals, NeighbourSearch search);

  /** \brief Where the sensor stood (the target's frame), or none: estimated normals are turned towards it, or
   *  (without one) away from the target's centroid, so that normals agree in sign with a model's outward ones; given
   *  normals are kept (all turned over when most of them point towards the centroid). Forgets what was computed.
   *  \param[in] viewpoint the sensor's position, e.g. the origin of a depth camera's organised cloud
   */
  void
  setViewpoint (std::optional<Eigen::Vector3d> viewpoint);

  /** \brief The neighbourhood size k (>= 4; default 20); forgets what was computed when it changes.
   *  \param[in] k the target points each plane is fitted to: more smooth more and flag fewer boundary points
   */
  void
  setNeighbours (int k);

  /** \brief The neighbourhood size k.
   *  \return the target points each plane is fitted to
   */
  int
  getNeighbours () const
  {
    return neighbours_;
  }

  /** \brief Project the points onto their neighbourhood's plane: on, off or automatic (the default: on for a noisy
   *  target, see TargetSmoothing); forgets what was computed when it changes.
   *  \param[in] smoothing the mode
   */
  void
  setSmoothing (TargetSmoothing smoothing);

  /** \brief Project the points onto their neighbourhood's plane (true) or keep the raw points (false).
   *  \param[in] enabled true to average out scan noise, false to keep the raw points
   */
  void
  setSmoothing (bool enabled)
  {
    setSmoothing (enabled ? TargetSmoothing::on : TargetSmoothing::off);
  }

  /** \brief Whether the points are projected onto their neighbourhood's plane (for the automatic mode: what it
   *  decided for this target, measuring its noise if not done yet).
   *  \return true if smoothing is on
   */
  bool
  getSmoothing ();

  /** \brief The target's noise ratio (see kNoisyTargetRatio), measured on up to 500 points spread over the target;
   *  NaN until measured (the automatic mode measures it on the first compute).
   *  \return the ratio
   */
  double
  getNoiseRatio () const
  {
    return noise_ratio_;
  }

  /** \brief Computes the target points of \a correspondences (their index_match) not computed yet, and sets each
   *  correspondence's distance to the squared distance from \a source (3 x source size) to the surface point.
   *  \param[in,out] correspondences the correspondences
   *  \param[in] source the source points the correspondences' index_query refers to
   */
  void
  compute (pcl::Correspondences& correspondences, const Eigen::Matrix3Xd& source);

  /** \brief Computes the target points of \a correspondences not computed yet (distances untouched).
   *  \param[in] correspondences the correspondences whose index_match points are needed
   */
  void
  compute (const pcl::Correspondences& correspondences);

  /** \brief The (smoothed) target point \a index; valid once computed.
   *  \param[in] index the target point
   *  \return its position, projected onto its plane when smoothing is on
   */
  Eigen::Vector3d
  point (pcl::index_t index) const
  {
    return points_.col (index);
  }

  /** \brief The unit normal of target point \a index; valid where hasNormal.
   *  \param[in] index the target point
   *  \return the given normal where valid, else its plane's normal
   */
  Eigen::Vector3d
  normal (pcl::index_t index) const
  {
    return normals_.col (index);
  }

  /** \brief Whether target point \a index has a finite normal (given or from its plane); valid once computed.
   *  \param[in] index the target point
   *  \return true if normal(index) may be used, e.g. for point-to-plane rows
   */
  bool
  hasNormal (pcl::index_t index) const
  {
    return has_normal_[static_cast<size_t> (index)] != 0;
  }

  /** \brief Whether target point \a index is a boundary point (or has no normal); valid once computed.
   *  \param[in] index the target point
   *  \return true if the point lies on a hole border, a scan edge or is isolated, so its pull is not trusted
   */
  bool
  isBoundary (pcl::index_t index) const
  {
    return boundary_[static_cast<size_t> (index)] != 0;
  }

private:
  /** Resets the per-point results. */
  void
  reset ();

  /** Plane, smoothed point, normal and boundary flag of target point \a index. */
  void
  computePoint (pcl::index_t index);

  /** Turns every given normal over when most point towards the centroid (a scan written with inward normals). */
  void
  turnGivenNormalsOutwards ();

  /** Measures the noise ratio and settles smoothing_ for the automatic mode (once per target). */
  void
  decideSmoothing ();

  Eigen::Matrix3Xd raw_points_;
  Eigen::Matrix3Xd given_normals_;
  Eigen::Vector3d centroid_ = Eigen::Vector3d::Zero (); ///< of the raw points
  std::optional<Eigen::Vector3d> viewpoint_;
  NeighbourSearch search_;
  int neighbours_ = 20;
  TargetSmoothing mode_ = TargetSmoothing::automatic;
  bool smoothing_ = false;   ///< what applies to this target (decided by decideSmoothing in the automatic mode)
  bool decided_ = false;     ///< smoothing_ is settled for this target
  double noise_ratio_ = NAN; ///< the target's noise over its neighbourhood's radius
  Eigen::Matrix3Xd points_;
  Eigen::Matrix3Xd normals_;
  std::vector<char> has_normal_;
  std::vector<char> boundary_;
  std::vector<char> ready_;
};
} // namespace morphreg

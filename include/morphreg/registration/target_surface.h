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

#include <functional>
#include <memory>
#include <vector>

namespace morphreg
{
/** \brief Computed lazily, once per target point when it first becomes a correspondence: the \a k nearest
 *  neighbours' least-squares plane; the point projected onto it (with smoothing; scan noise then averages out instead
 *  of pulling a fit towards the nearest noisy points); the target's own normal where it has a valid one, else the
 *  plane's; and the boundary flag: the largest angular gap between the neighbours around the point, in that plane,
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

  /** \brief Project the points onto their neighbourhood's plane (default on); forgets what was computed when it
   *  changes.
   *  \param[in] enabled true to average out scan noise, false to keep the raw points
   */
  void
  setSmoothing (bool enabled);

  /** \brief Whether the points are projected onto their neighbourhood's plane.
   *  \return true if smoothing is on
   */
  bool
  getSmoothing () const
  {
    return smoothing_;
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

  Eigen::Matrix3Xd raw_points_;
  Eigen::Matrix3Xd given_normals_;
  NeighbourSearch search_;
  int neighbours_ = 20;
  bool smoothing_ = true;
  Eigen::Matrix3Xd points_;
  Eigen::Matrix3Xd normals_;
  std::vector<char> has_normal_;
  std::vector<char> boundary_;
  std::vector<char> ready_;
};
} // namespace morphreg

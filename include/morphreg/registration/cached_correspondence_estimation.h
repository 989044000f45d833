// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file cached_correspondence_estimation.h
 *  \brief Nearest-neighbour correspondences as pcl::registration::CorrespondenceEstimation finds them, with the k-d
 *  tree queries spread over OpenMP threads and most of them skipped by an exact cache: a drop-in estimation for
 *  any PCL registration (MorphableICP's default; pcl::IterativeClosestPoint takes it too).
 */
#include <pcl/registration/correspondence_estimation.h>

#include <Eigen/Core>

#include <limits>
#include <vector>

namespace morphreg
{
/** \brief Each source point's nearest target point within the distance, in source-index order (the results of
 *  pcl::registration::CorrespondenceEstimation::determineCorrespondences, up to ties), found faster.
 *
 *  Each source point keeps the kCandidates target points its last tree query found and the distance R to the
 *  farthest of them: no other target point lies closer than R to where it was queried. After it has moved by d,
 *  its best candidate is still its nearest neighbour if no farther than R - d, and the tree is not queried. In the
 *  later iterations of a registration the points move little, so most queries are skipped. A new target or
 *  search tree empties the cache. Reciprocal correspondences are PCL's (not cached).
 */
template <typename PointSource, typename PointTarget, typename Scalar = float>
class CachedCorrespondenceEstimation
  : public pcl::registration::CorrespondenceEstimation<PointSource, PointTarget, Scalar>
{
public:
  using Ptr = pcl::shared_ptr<CachedCorrespondenceEstimation>;            ///< shared pointer
  using ConstPtr = pcl::shared_ptr<const CachedCorrespondenceEstimation>; ///< shared pointer to const
  /** \brief Shared pointer to PCL's estimation base, the type clone() returns. */
  using BasePtr = typename pcl::registration::CorrespondenceEstimationBase<PointSource, PointTarget, Scalar>::Ptr;

  /** Target points kept per source point: more widen the reach within which a moved point needs no query. */
  static constexpr int kCandidates = 8;

  /** \brief An estimation with an empty cache, named "CachedCorrespondenceEstimation" in PCL's messages. */
  CachedCorrespondenceEstimation ()
  {
    this->corr_name_ = "CachedCorrespondenceEstimation";
  }

  /** \brief Each source point's nearest target point, in source-index order, querying the tree only where the
   *  cache cannot prove the nearest point.
   *  \param[out] correspondences one per source point whose nearest target point lies within \a max_distance
   *  \param[in] max_distance the largest accepted point distance (mm for mm clouds)
   */
  void
  determineCorrespondences (pcl::Correspondences& correspondences,
                            double max_distance = std::numeric_limits<double>::max ()) override;

  /** \brief A copy with the same input, tree and cache, for PCL registrations that clone their estimation.
   *  \return the copy
   */
  BasePtr
  clone () const override
  {
    return Ptr (new CachedCorrespondenceEstimation (*this));
  }

  /** \brief Tree queries made since construction (a query per source point per call without the cache).
   *  \return the number of k-d tree queries, to measure how many the cache saves
   */
  long
  getTreeQueries () const
  {
    return tree_queries_;
  }

private:
  void
  resetCache (std::size_t points);

  /** Whether the cache proves which target point is nearest to source point \a i; if so, \a match and
   *  \a squared_distance are set.
   */
  bool
  fromCache (pcl::index_t i, pcl::index_t& match, float& squared_distance) const;

  /** Nearest target point of source point \a i from the tree (index, or -1 for none, and squared distance); its
   *  kCandidates nearest refill the cache.
   */
  void
  query (pcl::index_t i, pcl::index_t& match, float& squared_distance);

  /** Fewer tree queries than this in one call run on one thread. */
  static constexpr long kParallelQueries = 256;

  std::vector<Eigen::Vector3f> anchors_; ///< where each source point last queried the tree (NaN: never)
  std::vector<pcl::index_t> candidates_; ///< its kCandidates nearest target points then (-1: none)
  std::vector<float> reach_;             ///< the distance from the anchor to the farthest candidate
  long tree_queries_ = 0;
};

} // namespace morphreg

/// \cond
#define MORPHREG_DECLARE_CACHED_ESTIMATION(T)                                                                          \
  extern template class morphreg::CachedCorrespondenceEstimation<T, T, float>;
MORPHREG_DECLARE_CACHED_ESTIMATION (pcl::PointXYZ)
MORPHREG_DECLARE_CACHED_ESTIMATION (pcl::PointNormal)
MORPHREG_DECLARE_CACHED_ESTIMATION (pcl::PointXYZRGBNormal)
#undef MORPHREG_DECLARE_CACHED_ESTIMATION
/// \endcond

// SPDX-License-Identifier: BSD-3-Clause
#pragma once

#include <morphreg/registration/cached_correspondence_estimation.h>

#include <pcl/common/copy_point.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace morphreg
{
template <typename PointSource, typename PointTarget, typename Scalar>
void
CachedCorrespondenceEstimation<PointSource, PointTarget, Scalar>::determineCorrespondences (
    pcl::Correspondences& correspondences, double max_distance)
{
  const bool new_target = this->target_cloud_updated_;
  if (!this->initCompute ())
    return;
  this->target_cloud_updated_ = false; // seen: the cache below belongs to this target and tree
  if (new_target || this->input_->size () != anchors_.size ())
    resetCache (this->input_->size ());
  const pcl::Indices& indices = *this->indices_;
  const auto n = static_cast<long> (indices.size ());
  pcl::Indices matches (n);
  std::vector<float> distances (n);
  // The cache checks are cheap and serial; the tree queries left over are spread over the threads when they are
  // enough to be worth a fork-join (on a busy machine one costs a scheduler time slice).
  std::vector<long> misses;
  for (long i = 0; i < n; ++i)
    if (!fromCache (indices[i], matches[i], distances[i]))
      misses.push_back (i);
  const auto queries = static_cast<long> (misses.size ());
#pragma omp parallel for schedule(dynamic, 64) if (queries > kParallelQueries)
  for (long m = 0; m < queries; ++m)
    query (indices[misses[m]], matches[misses[m]], distances[misses[m]]);
  tree_queries_ += queries;
  const double max_squared = max_distance * max_distance;
  correspondences.clear ();
  correspondences.reserve (n);
  for (long i = 0; i < n; ++i)
    if (matches[i] >= 0 && !(distances[i] > max_squared))
      correspondences.emplace_back (indices[i], matches[i], distances[i]);
  this->deinitCompute ();
}

template <typename PointSource, typename PointTarget, typename Scalar>
void
CachedCorrespondenceEstimation<PointSource, PointTarget, Scalar>::resetCache (std::size_t points)
{
  anchors_.assign (points, Eigen::Vector3f::Constant (std::numeric_limits<float>::quiet_NaN ()));
  candidates_.assign (points * kCandidates, -1);
  reach_.assign (points, 0.0f);
}

template <typename PointSource, typename PointTarget, typename Scalar>
bool
CachedCorrespondenceEstimation<PointSource, PointTarget, Scalar>::fromCache (pcl::index_t i, pcl::index_t& match,
                                                                             float& squared_distance) const
{
  const Eigen::Vector3f position = (*this->input_)[i].getVector3fMap ();
  const float moved = (position - anchors_[i]).norm (); // NaN for a point never queried: the test below fails
  if (!(moved < reach_[i]))
    return false;
  const pcl::index_t* candidates = &candidates_[static_cast<std::size_t> (i) * kCandidates];
  float best = std::numeric_limits<float>::infinity ();
  for (int k = 0; k < kCandidates && candidates[k] >= 0; ++k) {
    const float d = (position - (*this->target_)[candidates[k]].getVector3fMap ()).squaredNorm ();
    if (d < best) {
      best = d;
      match = candidates[k];
    }
  }
  const float margin = reach_[i] - moved;
  squared_distance = best;
  return best <= margin * margin;
}

template <typename PointSource, typename PointTarget, typename Scalar>
void
CachedCorrespondenceEstimation<PointSource, PointTarget, Scalar>::query (pcl::index_t i, pcl::index_t& match,
                                                                         float& squared_distance)
{
  PointTarget point;
  pcl::copyPoint ((*this->input_)[i], point);
  pcl::Indices found;
  std::vector<float> squared;
  this->tree_->nearestKSearch (point, kCandidates, found, squared);
  anchors_[i] = point.getVector3fMap ();
  reach_[i] = 0.0f;
  match = -1;
  squared_distance = std::numeric_limits<float>::infinity ();
  if (found.empty ())
    return;
  const auto best = std::min_element (squared.begin (), squared.end ()) - squared.begin ();
  match = found[best];
  squared_distance = squared[best];
  pcl::index_t* candidates = &candidates_[static_cast<std::size_t> (i) * kCandidates];
  std::fill (candidates, candidates + kCandidates, -1);
  std::copy (found.begin (), found.end (), candidates);
  // Fewer than kCandidates found: they are the whole target, and no other point can come closer anywhere.
  reach_[i] = static_cast<int> (found.size ()) < kCandidates
                  ? std::numeric_limits<float>::infinity ()
                  : std::sqrt (*std::max_element (squared.begin (), squared.end ()));
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
// CachedCorrespondenceEstimation against pcl::registration::CorrespondenceEstimation on moving sources: the same
// correspondences, fewer k-d tree queries, a new target honoured, and a drop-in for pcl::IterativeClosestPoint.
#include <morphreg/registration/cached_correspondence_estimation.h>

#include <pcl/registration/correspondence_estimation.h>
#include <pcl/common/transforms.h>
#include <pcl/registration/icp.h>

#include <gtest/gtest.h>

#include <random>

namespace
{
using Cloud = pcl::PointCloud<pcl::PointXYZ>;
using Cached = morphreg::CachedCorrespondenceEstimation<pcl::PointXYZ, pcl::PointXYZ>;
using Plain = pcl::registration::CorrespondenceEstimation<pcl::PointXYZ, pcl::PointXYZ>;

/** \a n points on a bumpy sphere of radius 100 (a surface like a head's, with 1 mm noise). */
Cloud::Ptr
bumpySphere (int n, std::uint64_t seed)
{
  std::mt19937_64 rng (seed);
  std::normal_distribution<float> gauss;
  Cloud::Ptr cloud (new Cloud);
  for (int i = 0; i < n; ++i) {
    Eigen::Vector3f direction (gauss (rng), gauss (rng), gauss (rng));
    direction.normalize ();
    const float radius = 100.0f + 10.0f * std::sin (3.0f * direction.x ()) * std::cos (2.0f * direction.y ());
    pcl::PointXYZ p;
    p.getVector3fMap () = radius * direction + Eigen::Vector3f (gauss (rng), gauss (rng), gauss (rng));
    cloud->push_back (p);
  }
  return cloud;
}

/** Ours and PCL's estimation, given the same inputs. */
struct EstimationPair
{
  Cached cached;
  Plain plain;

  void
  setTarget (const Cloud::Ptr& target)
  {
    cached.setInputTarget (target);
    plain.setInputTarget (target);
  }

  void
  setSource (const Cloud::Ptr& source, const pcl::IndicesPtr& indices = nullptr)
  {
    for (Plain* estimation : {static_cast<Plain*> (&cached), &plain}) {
      estimation->setInputSource (source);
      if (indices)
        estimation->setIndicesSource (indices);
    }
  }

  /** Expects both to find the same correspondences: the same source points and squared distances (up to float
   *  rounding: FLANN sums the squares in its own order), so the same or an equally near target point.
   */
  void
  expectSame (double max_distance = std::numeric_limits<double>::max ())
  {
    pcl::Correspondences a, b;
    cached.determineCorrespondences (a, max_distance);
    plain.determineCorrespondences (b, max_distance);
    ASSERT_EQ (a.size (), b.size ());
    for (size_t c = 0; c < b.size (); ++c) {
      ASSERT_EQ (a[c].index_query, b[c].index_query);
      ASSERT_NEAR (a[c].distance, b[c].distance, 1e-5f * std::max (1.0f, b[c].distance))
          << "source point " << b[c].index_query;
    }
  }
};

/** Moves every point of \a cloud by a random step of about \a size (per axis). */
void
jitter (Cloud& cloud, float size, std::mt19937_64& rng)
{
  std::normal_distribution<float> gauss (0.0f, size);
  for (auto& p : cloud)
    p.getVector3fMap () += Eigen::Vector3f (gauss (rng), gauss (rng), gauss (rng));
}
} // namespace

TEST (CachedCorrespondenceEstimationTest, MatchesPclOnAMovingSourceWithFewerQueries)
{
  const Cloud::Ptr target = bumpySphere (20000, 1);
  Cloud::Ptr source = bumpySphere (2000, 2);
  EstimationPair pair;
  pair.setTarget (target);
  std::mt19937_64 rng (3);
  const std::vector<float> steps{5.0f, 2.0f, 0.5f, 0.2f, 0.05f, 0.01f, 0.01f, 3.0f, 0.02f, 0.0f};
  for (const float step : steps) {
    jitter (*source, step, rng);
    pair.setSource (source);
    for (const double max_distance : {std::numeric_limits<double>::max (), 2.0}) {
      SCOPED_TRACE ("step " + std::to_string (step) + ", max distance " + std::to_string (max_distance));
      pair.expectSame (max_distance);
    }
  }
  const long without_cache = 2 * static_cast<long> (steps.size () * source->size ());
  std::printf ("[ cached ] %ld tree queries of %ld\n", pair.cached.getTreeQueries (), without_cache);
  EXPECT_LT (pair.cached.getTreeQueries (), without_cache / 2) << "the small steps should mostly hit the cache";
}

TEST (CachedCorrespondenceEstimationTest, HonoursSourceIndicesAndANewTarget)
{
  const Cloud::Ptr source = bumpySphere (1000, 4);
  pcl::IndicesPtr every_third (new pcl::Indices);
  for (int i = 0; i < 1000; i += 3)
    every_third->push_back (i);
  EstimationPair pair;
  for (const std::uint64_t seed : {5, 6}) {
    pair.setTarget (bumpySphere (5000, seed));
    pair.setSource (source, every_third);
    SCOPED_TRACE ("target " + std::to_string (seed));
    pair.expectSame (3.0);
  }
}

TEST (CachedCorrespondenceEstimationTest, TargetSmallerThanTheCandidatesAndClone)
{
  const Cloud::Ptr target = bumpySphere (Cached::kCandidates - 3, 7);
  Cloud::Ptr source = bumpySphere (50, 8);
  EstimationPair pair;
  pair.setTarget (target);
  std::mt19937_64 rng (9);
  for (int round = 0; round < 3; ++round) {
    jitter (*source, 20.0f, rng);
    pair.setSource (source);
    pair.expectSame ();
  }
  EXPECT_EQ (pair.cached.getTreeQueries (), 50) << "the whole target is every point's candidate set: one query each";
  const auto copy = pair.cached.clone ();
  EXPECT_NE (std::dynamic_pointer_cast<Cached> (copy), nullptr);
}

TEST (CachedCorrespondenceEstimationTest, DropInForPclIterativeClosestPoint)
{
  const Cloud::Ptr target = bumpySphere (20000, 10);
  Cloud::Ptr source (new Cloud);
  const Eigen::Affine3f motion =
      Eigen::Translation3f (3.0f, -2.0f, 1.0f) * Eigen::AngleAxisf (0.08f, Eigen::Vector3f (1, 2, 3).normalized ());
  pcl::transformPointCloud (*bumpySphere (3000, 11), *source, motion);
  Eigen::Matrix4f results[2];
  for (const bool use_cache : {false, true}) {
    pcl::IterativeClosestPoint<pcl::PointXYZ, pcl::PointXYZ> icp;
    if (use_cache)
      icp.setCorrespondenceEstimation (Cached::Ptr (new Cached));
    icp.setInputSource (source);
    icp.setInputTarget (target);
    icp.setMaximumIterations (30);
    Cloud output;
    icp.align (output);
    results[use_cache ? 1 : 0] = icp.getFinalTransformation ();
  }
  EXPECT_TRUE (results[1].isApprox (results[0], 1e-5f)) << results[1] << "\nvs PCL's\n" << results[0];
}

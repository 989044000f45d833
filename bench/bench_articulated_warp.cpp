// SPDX-License-Identifier: BSD-3-Clause
// Re-posturing the MakeHuman bodies standing -> seated from their 51 major joints: morphreg::ArticulatedWarp (bone
// motions, geodesic skinning weights, linear blend skinning, as-rigid-as-possible refinement with its factorisation)
// next to the blended segmented thin plate spline (morphreg::SegmentedWarp, the settings of its test) in one run, on
// the same body; and the base body warped to the male subject from the 51 joints and 16 surface landmarks by
// morphreg::MovingLeastSquaresWarp next to the global thin plate spline of the same landmarks. Needs
// ../shared/data/makehuman_bodies. No external baseline: PCL and VTK have no skeleton-driven or moving least squares
// warp, so both comparisons are with morphreg's own simpler warps (label and counter "threads" say so).
#include "bench_report.h"

#include <morphreg/datasets/makehuman_bodies.h>
#include <morphreg/warp/articulated_warp.h>
#include <morphreg/warp/moving_least_squares_warp.h>
#include <morphreg/warp/segmented_warp.h>
#include <morphreg/warp/thin_plate_spline.h>

#include <benchmark/benchmark.h>

#include <filesystem>
#include <memory>

namespace
{
struct Body
{
  std::unique_ptr<morphreg::MakeHumanBodies> bodies;
  morphreg::TriangleMesh standing;
  morphreg::LandmarkPositions standing_joints, seated_joints;
  Eigen::Matrix3Xd base_landmarks, male_landmarks; ///< the 51 joints and the 16 surface landmarks, standing
};

/** The base body standing and its joints in both postures; null without the shared data. */
const Body*
body ()
{
  static const std::unique_ptr<Body> loaded = [] {
    const std::string folder = std::string (MORPHREG_SHARED_DATA_DIR) + "/makehuman_bodies";
    if (!std::filesystem::exists (folder + "/mh_joints.json"))
      return std::unique_ptr<Body> ();
    auto result = std::make_unique<Body> ();
    result->bodies = std::make_unique<morphreg::MakeHumanBodies> (folder);
    const auto& joints = result->bodies->majorJoints ();
    result->standing = result->bodies->loadMesh ("base", morphreg::BodyPose::standing);
    result->standing_joints = result->bodies->namedJoints ("base", morphreg::BodyPose::standing, joints);
    result->seated_joints = result->bodies->namedJoints ("base", morphreg::BodyPose::seated, joints);
    const auto standing = morphreg::BodyPose::standing;
    result->base_landmarks = result->bodies->jointAndSurfaceLandmarks ("base", standing, result->standing);
    const std::string male = "caucasian-male-young";
    result->male_landmarks =
        result->bodies->jointAndSurfaceLandmarks (male, standing, result->bodies->loadMesh (male, standing));
    return result;
  }();
  return loaded.get ();
}

Eigen::Matrix3Xd
columns (const morphreg::LandmarkPositions& points)
{
  Eigen::Matrix3Xd result (3, static_cast<Eigen::Index> (points.size ()));
  Eigen::Index k = 0;
  for (const auto& entry : points)
    result.col (k++) = entry.second;
  return result;
}

void
BM_ArticulatedWarp (benchmark::State& state)
{
  const Body* b = body ();
  if (!b)
    return state.SkipWithError ("../shared/data/makehuman_bodies is absent");
  for (auto _ : state) {
    morphreg::ArticulatedWarp warp (morphreg::makeHumanSkeleton (), b->bodies->segmentLabels (),
                                    b->bodies->segmentNames ());
    warp.setRigidity (static_cast<double> (state.range (0)));
    warp.setJoints (b->standing_joints, b->seated_joints);
    benchmark::DoNotOptimize (warp.warp (b->standing).vertices.data ());
  }
  state.counters["vertices"] = static_cast<double> (b->standing.numVertices ());
  morphreg::bench::reportNoExternalBaseline (state);
}

void
BM_SegmentedTps (benchmark::State& state)
{
  const Body* b = body ();
  if (!b)
    return state.SkipWithError ("../shared/data/makehuman_bodies is absent");
  const Eigen::Matrix3Xd source = columns (b->standing_joints), target = columns (b->seated_joints);
  for (auto _ : state) {
    morphreg::SegmentedWarp warp (b->bodies->segmentLabels (), 4);
    warp.setLandmarks (b->standing, source, target, {90.0, 90.0, 90.0, 90.0});
    const double widths[] = {100.0, 100.0, 400.0, 50.0};
    for (int s = 0; s < 4; ++s)
      warp.setSegmentBlendWidth (s, widths[s]);
    benchmark::DoNotOptimize (warp.warp (b->standing).vertices.data ());
  }
  morphreg::bench::reportNoExternalBaseline (state);
}

void
BM_BetweenSubjectsMls (benchmark::State& state)
{
  const Body* b = body ();
  if (!b)
    return state.SkipWithError ("../shared/data/makehuman_bodies is absent");
  for (auto _ : state) {
    morphreg::MovingLeastSquaresWarp warp;
    warp.setLandmarks (b->base_landmarks, b->male_landmarks);
    benchmark::DoNotOptimize (warp.warp (b->standing).vertices.data ());
  }
  morphreg::bench::reportNoExternalBaseline (state);
}

void
BM_BetweenSubjectsTps (benchmark::State& state)
{
  const Body* b = body ();
  if (!b)
    return state.SkipWithError ("../shared/data/makehuman_bodies is absent");
  for (auto _ : state) {
    morphreg::ThinPlateSpline<double, 3> tps;
    tps.fit (b->base_landmarks, b->male_landmarks);
    benchmark::DoNotOptimize (tps.transformMesh (b->standing).vertices.data ());
  }
  morphreg::bench::reportNoExternalBaseline (state);
}
} // namespace

// Arg: the rigidity (0: skinning alone, 1: the default refinement).
BENCHMARK (BM_ArticulatedWarp)->Arg (0)->Arg (1)->Apply (morphreg::bench::wallAndProcessCpuMs);
BENCHMARK (BM_SegmentedTps)->Apply (morphreg::bench::wallAndProcessCpuMs);
BENCHMARK (BM_BetweenSubjectsMls)->Apply (morphreg::bench::wallAndProcessCpuMs);
BENCHMARK (BM_BetweenSubjectsTps)->Apply (morphreg::bench::wallAndProcessCpuMs);

BENCHMARK_MAIN ();

// SPDX-License-Identifier: BSD-3-Clause
// Landmark-free registration of the real head-and-shoulders scan (../shared/data/real_head_scans, 82,360 points with
// normals) from an arbitrary similarity pose, against PCL's IterativeClosestPoint (default settings) aligning the
// same posed cloud back onto the original, started from the true pose: the global start alone (alignHeadGlobally)
// and the whole MorphableICP registration (ICT-FaceKit, 7 regions x 30 components, the README's real-scan settings).
#include "../test/real_scans/real_scan_support.h"

#include <morphreg/common/cloud_matrix.h>

#include <morphreg/registration/global_alignment.h>

#include <pcl/registration/icp.h>

#include <benchmark/benchmark.h>

#include <iostream>

namespace
{
using namespace morphreg::test;

struct Fixture
{
  pcl::PointCloud<pcl::PointNormal>::Ptr original, scan;
  Eigen::Matrix4d pose;
  Eigen::Matrix3Xd points, normals;

  Fixture () : original (leeScan82k ()), pose (randomPose (101))
  {
    scan = posed (*original, pose);
    points = morphreg::pointsOf (*scan);
    normals = morphreg::normalsOf (*scan);
    ictModel30 (); // built once, outside the timings
  }
};

const Fixture&
fixture ()
{
  static const Fixture f;
  return f;
}

#define REQUIRE_DATA(state)                                                                                            \
  if (!realScanDataAvailable ()) {                                                                                     \
    state.SkipWithError ("../shared/data (real head scan, ICT-FaceKit) is absent");                                    \
    return;                                                                                                            \
  }

/** The baseline: PCL's rigid ICP of the posed cloud back onto the original, from the true pose. */
void
BM_PclIcpFromTruePose (benchmark::State& state)
{
  REQUIRE_DATA (state);
  const Fixture& f = fixture ();
  for (auto _ : state) {
    pcl::IterativeClosestPoint<pcl::PointNormal, pcl::PointNormal> icp;
    icp.setInputSource (f.scan);
    icp.setInputTarget (f.original);
    pcl::PointCloud<pcl::PointNormal> output;
    icp.align (output, f.pose.inverse ().cast<float> ());
    benchmark::DoNotOptimize (output.size ());
  }
}
BENCHMARK (BM_PclIcpFromTruePose)->Unit (benchmark::kMillisecond)->UseRealTime ();

/** The global start alone. */
void
BM_GlobalStart (benchmark::State& state)
{
  REQUIRE_DATA (state);
  const Fixture& f = fixture ();
  const morphreg::MorphableModel& model = *ictModel30 ();
  const Eigen::Map<const Eigen::Matrix3Xd> mean (model.mean ().data (), 3, model.numVertices ());
  const morphreg::TriangleMesh mesh{mean, model.triangles ()};
  for (auto _ : state)
    benchmark::DoNotOptimize (morphreg::alignHeadGlobally (mesh, f.points, f.normals).confidence);
}
BENCHMARK (BM_GlobalStart)->Unit (benchmark::kMillisecond)->UseRealTime ();

/** The whole landmark-free registration: global start, similarity and shape stages. */
void
BM_RegistrationFromArbitraryPose (benchmark::State& state)
{
  REQUIRE_DATA (state);
  const Fixture& f = fixture ();
  for (auto _ : state) {
    morphreg::MorphableICP<pcl::PointNormal> icp;
    configureIctIcp (icp, ictModel30 ());
    icp.setInputTarget (f.scan);
    pcl::PointCloud<pcl::PointNormal> output;
    icp.align (output);
    state.counters["iterations"] = static_cast<double> (icp.getRegistrationReport ().history.size ());
  }
}
BENCHMARK (BM_RegistrationFromArbitraryPose)->Unit (benchmark::kMillisecond)->UseRealTime ()->Iterations (3);

} // namespace

BENCHMARK_MAIN ();

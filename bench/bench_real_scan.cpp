// SPDX-License-Identifier: BSD-3-Clause
// Landmark-free registration of the real head-and-shoulders scan (../shared/data/real_head_scans, 82,360 points with
// normals) from an arbitrary similarity pose: the global start alone (alignHeadGlobally) and the whole MorphableICP
// registration at `morphreg register`'s defaults (ICT-FaceKit, 7 regions x 30 components). Two baselines in the same
// process, both pcl::IterativeClosestPoint with PCL's default settings, its k-d tree build included:
//  - the rigid job a user would compare with: the model's mean (11,248 points) onto the posed scan, started from the
//    pose our registration finds (computed once, outside the timings);
//  - the scan job of issue 12: the posed cloud back onto the original cloud (82,360 onto 82,360), started from the
//    true pose.
// PCL's ICP runs on one thread, ours on the OpenMP threads (counter "threads").
#include "../test/real_scans/real_scan_support.h"
#include "bench_report.h"

#include <morphreg/common/cloud_matrix.h>

#include <morphreg/registration/global_alignment.h>
#include <morphreg/registration/registration_settings.h>

#include <pcl/registration/icp.h>

#include <benchmark/benchmark.h>

#include <iostream>

namespace
{
using namespace morphreg::test;

/** register's defaults for the ICT model. */
void
configureDefaults (morphreg::MorphableICP<pcl::PointNormal>& icp)
{
  morphreg::configureRegistration (icp, morphreg::RegistrationSettings (), ictModel30 ());
}

struct Fixture
{
  pcl::PointCloud<pcl::PointNormal>::Ptr original, scan, mean;
  Eigen::Matrix4d pose, fitted_pose;
  Eigen::Matrix3Xd points, normals;

  Fixture () : original (leeScan82k ()), pose (randomPose (101))
  {
    scan = posed (*original, pose);
    points = morphreg::pointsOf (*scan);
    normals = morphreg::normalsOf (*scan);
    const morphreg::MorphableModel& model = *ictModel30 (); // built once, outside the timings
    mean.reset (new pcl::PointCloud<pcl::PointNormal>);
    mean->resize (model.numVertices ());
    for (Eigen::Index i = 0; i < model.numVertices (); ++i)
      (*mean)[i].getVector3fMap () = model.meanVertex (static_cast<int> (i)).cast<float> ();
    morphreg::MorphableICP<pcl::PointNormal> icp;
    configureDefaults (icp);
    icp.setInputTarget (scan);
    pcl::PointCloud<pcl::PointNormal> output;
    icp.align (output);
    fitted_pose = icp.getFinalTransformation ().cast<double> ();
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

/** The rigid baseline: PCL's ICP of the model's mean onto the posed scan, from the pose our registration finds. */
void
BM_PclIcpOfTheMeanOntoTheScan (benchmark::State& state)
{
  REQUIRE_DATA (state);
  const Fixture& f = fixture ();
  for (auto _ : state) {
    pcl::IterativeClosestPoint<pcl::PointNormal, pcl::PointNormal> icp;
    icp.setInputSource (f.mean);
    icp.setInputTarget (f.scan);
    pcl::PointCloud<pcl::PointNormal> output;
    icp.align (output, f.fitted_pose.cast<float> ());
    benchmark::DoNotOptimize (output.size ());
  }
  morphreg::bench::reportThreads (state, 1);
}
BENCHMARK (BM_PclIcpOfTheMeanOntoTheScan)->Apply (morphreg::bench::wallAndProcessCpuMs);

/** The scan baseline (issue 12): PCL's rigid ICP of the posed cloud back onto the original, from the true pose. */
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
  morphreg::bench::reportThreads (state, 1);
}
BENCHMARK (BM_PclIcpFromTruePose)->Apply (morphreg::bench::wallAndProcessCpuMs);

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
  morphreg::bench::reportOpenMpThreads (state);
}
BENCHMARK (BM_GlobalStart)->Apply (morphreg::bench::wallAndProcessCpuMs);

/** The whole landmark-free registration: global start, similarity and shape stages. */
void
BM_RegistrationFromArbitraryPose (benchmark::State& state)
{
  REQUIRE_DATA (state);
  const Fixture& f = fixture ();
  for (auto _ : state) {
    morphreg::MorphableICP<pcl::PointNormal> icp;
    configureDefaults (icp);
    icp.setInputTarget (f.scan);
    pcl::PointCloud<pcl::PointNormal> output;
    icp.align (output);
    state.counters["iterations"] = static_cast<double> (icp.getRegistrationReport ().history.size ());
  }
  morphreg::bench::reportOpenMpThreads (state);
}
BENCHMARK (BM_RegistrationFromArbitraryPose)->Apply (morphreg::bench::wallAndProcessCpuMs)->Iterations (3);

} // namespace

BENCHMARK_MAIN ();

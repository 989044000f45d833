// SPDX-License-Identifier: BSD-3-Clause
// MorphableICP against pcl::IterativeClosestPoint on the same simulated scan: full align() and time per iteration.
// Model: the built-in synthetic population (120 heads, 9602 vertices, 7 regions x 10 components); scan: the
// ScanSimulator at about 100k points, both registrations started from the same similarity guess; PCL's ICP also with
// our CachedCorrespondenceEstimation, and MorphableICP also from its robust coarse start (no guess).
#include <morphreg/model/model_builder.h>
#include <morphreg/registration/cached_correspondence_estimation.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/scan_simulator.h>

#include <pcl/registration/icp.h>

#include <benchmark/benchmark.h>

namespace
{
struct Fixture
{
  morphreg::MorphableModel::ConstPtr model;
  pcl::PointCloud<pcl::PointNormal>::Ptr mean;
  morphreg::synthetic::SimulatedScan scan;
  Eigen::Matrix4f guess;

  Fixture ()
  {
    morphreg::synthetic::HeadGenerator generator;
    std::vector<morphreg::TriangleMesh> meshes;
    for (auto& head : generator.population (120, 1000))
      meshes.push_back (std::move (head.mesh));
    morphreg::ModelBuilderSettings settings;
    settings.max_components = 10;
    model = morphreg::ModelBuilder (settings).build (meshes, generator.regions ());
    mean = model->generateCloud<pcl::PointNormal> (Eigen::VectorXd::Zero (0),
                                                   morphreg::ComponentSelection (std::vector<int> (7, 0)));
    morphreg::synthetic::ScanSimulator::Parameters parameters;
    parameters.row_spacing = 1.1;
    scan = morphreg::synthetic::ScanSimulator (parameters).scan (generator.sample (500000).mesh, 3);
    guess = scan.head_to_scan.matrix ().cast<float> ();
  }
};

const Fixture&
fixture ()
{
  static const Fixture f;
  return f;
}

/** PCL's rigid ICP from the guess, with PCL's correspondence estimation or (cached = 1) ours. */
void
BM_PclIcpAlign (benchmark::State& state)
{
  const Fixture& f = fixture ();
  int iterations = 0;
  for (auto _ : state) {
    pcl::IterativeClosestPoint<pcl::PointNormal, pcl::PointNormal> icp;
    if (state.range (0) == 1)
      icp.setCorrespondenceEstimation (
          morphreg::CachedCorrespondenceEstimation<pcl::PointNormal, pcl::PointNormal>::Ptr (
              new morphreg::CachedCorrespondenceEstimation<pcl::PointNormal, pcl::PointNormal>));
    icp.setInputSource (f.mean);
    icp.setInputTarget (f.scan.cloud);
    iterations = 0;
    std::function<pcl::Registration<pcl::PointNormal, pcl::PointNormal>::UpdateVisualizerCallbackSignature> count =
        [&] (const pcl::PointCloud<pcl::PointNormal>&, const pcl::Indices&, const pcl::PointCloud<pcl::PointNormal>&,
             const pcl::Indices&) { ++iterations; };
    icp.registerVisualizationCallback (count);
    pcl::PointCloud<pcl::PointNormal> output;
    icp.align (output, f.guess);
    benchmark::DoNotOptimize (output.data ());
  }
  state.counters["iterations"] = iterations - 1; // the first call comes from registerVisualizationCallback
  state.counters["points"] = static_cast<double> (f.scan.cloud->size ());
}
BENCHMARK (BM_PclIcpAlign)->ArgName ("cached")->Arg (0)->Arg (1)->Unit (benchmark::kMillisecond)->UseRealTime ();

void
BM_MorphableIcpAlign (benchmark::State& state)
{
  const Fixture& f = fixture ();
  morphreg::IcpReport report;
  for (auto _ : state) {
    morphreg::MorphableICP<pcl::PointNormal> icp;
    icp.setModel (f.model);
    icp.setPointToPlane (true);
    icp.setInputTarget (f.scan.cloud);
    pcl::PointCloud<pcl::PointNormal> output;
    if (state.range (0) == 1)
      icp.align (output); // no guess: the robust coarse start
    else
      icp.align (output, f.guess);
    report = icp.getRegistrationReport ();
    benchmark::DoNotOptimize (output.data ());
  }
  double similarity = 0.0, shape = 0.0;
  for (const auto& it : report.history)
    (it.stage == morphreg::IcpStage::similarity ? similarity : shape) += it.seconds;
  state.counters["similarity_iterations"] = report.similarity_iterations;
  state.counters["shape_iterations"] = report.shape_iterations;
  state.counters["ms_per_similarity_iteration"] = 1e3 * similarity / std::max (1, report.similarity_iterations);
  state.counters["ms_per_shape_iteration"] = 1e3 * shape / std::max (1, report.shape_iterations);
}
BENCHMARK (BM_MorphableIcpAlign)
    ->ArgName ("coarse_start")
    ->Arg (0)
    ->Arg (1)
    ->Unit (benchmark::kMillisecond)
    ->UseRealTime ();

} // namespace

BENCHMARK_MAIN ();

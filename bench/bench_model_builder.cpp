// SPDX-License-Identifier: BSD-3-Clause
// Model building: ModelBuilder (global PCA + 7 region PCAs + blending) against a plain Eigen BDCSVD of
// the same centred data matrix, for 200 synthetic heads (9602 vertices) and 200 ICT samples (11248 vertices). The
// baseline is Eigen's, as neither PCL nor VTK builds shape models; it does less (one SVD, no regions), on Eigen's
// OpenMP products; the builder runs on the OpenMP threads (counter "threads" on both).
// Counters: peak_MiB = growth of the resident set's high-water mark during the timed runs (Linux clear_refs).
#include "bench_report.h"

#include <morphreg/datasets/ict_facekit.h>
#include <morphreg/model/ict_region_model.h>
#include <morphreg/model/model_builder.h>
#include <morphreg/model/procrustes.h>
#include <morphreg/synthetic/head_generator.h>

#include <Eigen/SVD>
#include <benchmark/benchmark.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace
{
constexpr int kSamples = 200;

/** Reads a "VmXXX:  123 kB" line of /proc/self/status, in MiB. */
double
statusMiB (const std::string& key)
{
  std::ifstream status ("/proc/self/status");
  for (std::string line; std::getline (status, line);)
    if (line.rfind (key + ":", 0) == 0)
      return std::stod (line.substr (key.size () + 1)) / 1024.0;
  return 0.0;
}

/** Resets the peak-RSS mark; returns the current RSS (MiB). */
double
resetPeak ()
{
  std::ofstream ("/proc/self/clear_refs") << "5";
  return statusMiB ("VmRSS");
}

struct Population
{
  std::vector<morphreg::TriangleMesh> meshes;
  morphreg::RegionLabels regions;
  Eigen::MatrixXd centred;         ///< unaligned
  Eigen::MatrixXd aligned_centred; ///< after generalised Procrustes, as ModelBuilder's default sees it
};

Eigen::MatrixXd
centredMatrix (const std::vector<morphreg::TriangleMesh>& meshes, bool align)
{
  std::vector<Eigen::Matrix3Xd> shapes;
  for (const auto& mesh : meshes)
    shapes.push_back (mesh.vertices);
  if (align)
    morphreg::alignGeneralisedProcrustes (shapes);
  Eigen::MatrixXd data (3 * meshes[0].numVertices (), static_cast<Eigen::Index> (meshes.size ()));
  for (size_t s = 0; s < shapes.size (); ++s)
    data.col (s) = Eigen::Map<const Eigen::VectorXd> (shapes[s].data (), data.rows ());
  data.colwise () -= data.rowwise ().mean ().eval ();
  return data;
}

const Population&
synthetic ()
{
  static const Population population = [] {
    Population p;
    const morphreg::synthetic::HeadGenerator generator;
    for (const auto& head : generator.population (kSamples, 1))
      p.meshes.push_back (head.mesh);
    for (int j = 0; j < morphreg::synthetic::kNumHeadRegions; ++j)
      p.regions.names.push_back (
          morphreg::synthetic::headRegionName (static_cast<morphreg::synthetic::HeadRegion> (j)));
    for (const auto label : generator.regionLabels ())
      p.regions.labels.push_back (static_cast<int> (label));
    p.centred = centredMatrix (p.meshes, false);
    p.aligned_centred = centredMatrix (p.meshes, true);
    return p;
  }();
  return population;
}

const std::string kIctDirectory = std::string (MORPHREG_SHARED_DATA_DIR) + "/ict_facekit";

const Population&
ict ()
{
  static const Population population = [] {
    Population p;
    const auto model = morphreg::loadIctFaceKit (kIctDirectory);
    std::mt19937_64 rng (1);
    for (int s = 0; s < kSamples; ++s)
      p.meshes.push_back (
          model->generateMesh (model->sampleCoefficients (rng, model->allComponents ()), model->allComponents ()));
    p.regions = morphreg::segmentByLandmarkGroups (model->meanMesh (), morphreg::ictRegionGroups (*model));
    p.centred = centredMatrix (p.meshes, false);
    p.aligned_centred = centredMatrix (p.meshes, true);
    return p;
  }();
  return population;
}

const Population*
population (int which, benchmark::State& state)
{
  if (which == 0)
    return &synthetic ();
  if (!std::filesystem::exists (kIctDirectory + "/ict_head_pca_basis.npy")) {
    state.SkipWithError ("ICT-FaceKit data absent (../shared/data/ict_facekit)");
    return nullptr;
  }
  return &ict ();
}

void
BM_ModelBuilder (benchmark::State& state)
{
  const Population* data = population (static_cast<int> (state.range (0)), state);
  if (!data)
    return;
  morphreg::ModelBuilderSettings settings;
  settings.align = state.range (1) != 0;
  settings.max_components = static_cast<int> (state.range (2));
  const morphreg::ModelBuilder builder (settings);
  const double base = resetPeak ();
  for (auto _ : state)
    benchmark::DoNotOptimize (builder.build (data->meshes, data->regions));
  state.counters["peak_MiB"] = statusMiB ("VmHWM") - base;
  state.counters["vertices"] = static_cast<double> (data->meshes[0].numVertices ());
  morphreg::bench::reportOpenMpThreads (state);
}

void
BM_EigenBdcSvdBaseline (benchmark::State& state)
{
  const Population* data = population (static_cast<int> (state.range (0)), state);
  if (!data)
    return;
  const Eigen::MatrixXd& centred = state.range (1) != 0 ? data->aligned_centred : data->centred;
  const double base = resetPeak ();
  for (auto _ : state) {
    Eigen::BDCSVD<Eigen::MatrixXd> svd (centred, Eigen::ComputeThinU);
    benchmark::DoNotOptimize (svd.matrixU ().data ());
  }
  state.counters["peak_MiB"] = statusMiB ("VmHWM") - base;
  state.counters["vertices"] = static_cast<double> (data->meshes[0].numVertices ());
  morphreg::bench::reportThreads (state, Eigen::nbThreads ());
}
} // namespace

// Arguments: population (0 = synthetic heads, 1 = ICT samples), Procrustes alignment (1 = on, the default; the
// baseline then decomposes the aligned data matrix, i.e. the same matrix the builder's PCA sees), and for the builder
// the components kept per region and globally (0 = all, 15 = the top of the thesis's 5-15 range). Each baseline runs
// right before the builder cases it is compared with, so that both see the same load on a shared machine.
BENCHMARK (BM_EigenBdcSvdBaseline)->Args ({0, 1})->Apply (morphreg::bench::wallAndProcessCpuMs)->Iterations (3);
BENCHMARK (BM_ModelBuilder)
    ->Args ({0, 1, 0})
    ->Args ({0, 1, 15})
    ->Apply (morphreg::bench::wallAndProcessCpuMs)
    ->Iterations (3);
BENCHMARK (BM_EigenBdcSvdBaseline)->Args ({0, 0})->Apply (morphreg::bench::wallAndProcessCpuMs)->Iterations (3);
BENCHMARK (BM_ModelBuilder)->Args ({0, 0, 0})->Apply (morphreg::bench::wallAndProcessCpuMs)->Iterations (3);
BENCHMARK (BM_EigenBdcSvdBaseline)->Args ({1, 1})->Apply (morphreg::bench::wallAndProcessCpuMs)->Iterations (3);
BENCHMARK (BM_ModelBuilder)
    ->Args ({1, 1, 0})
    ->Args ({1, 1, 15})
    ->Apply (morphreg::bench::wallAndProcessCpuMs)
    ->Iterations (3);
BENCHMARK (BM_EigenBdcSvdBaseline)->Args ({1, 0})->Apply (morphreg::bench::wallAndProcessCpuMs)->Iterations (3);
BENCHMARK (BM_ModelBuilder)->Args ({1, 0, 0})->Apply (morphreg::bench::wallAndProcessCpuMs)->Iterations (3);

BENCHMARK_MAIN ();

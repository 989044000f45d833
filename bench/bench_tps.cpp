// SPDX-License-Identifier: BSD-3-Clause
// Thin plate splines: morphreg::ThinPlateSpline against VTK's vtkThinPlateSplineTransform (SetBasisToR) in one run.
// Fit at n = 66, 500, 1000 landmarks (both), 2000 and 5000 (ours only: VTK's O(n^3) Jacobi takes many minutes);
// evaluation of 16k and 1M points at n = 66, 500, 1000. Wall-clock times; ours runs on all OpenMP threads, and its
// evaluation also on one (third argument 1), VTK's on one thread (counter "threads"); pairs/s = point-landmark pairs
// per second.
#include "bench_report.h"

#include <morphreg/warp/thin_plate_spline.h>

#include <benchmark/benchmark.h>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkThinPlateSplineTransform.h>

#include <cmath>
#include <random>

namespace
{
/** \a n landmarks spread over a body-sized box (mm) and their smoothly bent targets. */
struct Landmarks
{
  Eigen::Matrix3Xd source;
  Eigen::Matrix3Xd target;
};

Eigen::Matrix3Xd
randomPoints (Eigen::Index n, unsigned seed)
{
  std::mt19937 engine (seed);
  std::uniform_real_distribution<double> coordinate (-500.0, 500.0);
  Eigen::Matrix3Xd points (3, n);
  for (Eigen::Index j = 0; j < n; ++j)
    points.col (j) = Eigen::Vector3d (0.5 * coordinate (engine), 0.3 * coordinate (engine), 1.8 * coordinate (engine));
  return points;
}

Landmarks
makeLandmarks (Eigen::Index n)
{
  Landmarks landmarks{randomPoints (n, 1), {}};
  landmarks.target = landmarks.source;
  for (Eigen::Index j = 0; j < n; ++j)
    landmarks.target.col (j) += Eigen::Vector3d (20.0 * std::sin (landmarks.source (2, j) / 300.0),
                                                 10.0 * std::cos (landmarks.source (0, j) / 200.0), 0.0);
  return landmarks;
}

vtkNew<vtkPoints>
toVtkPoints (const Eigen::Matrix3Xd& points)
{
  vtkNew<vtkPoints> result;
  result->SetDataTypeToDouble ();
  result->SetNumberOfPoints (points.cols ());
  for (Eigen::Index j = 0; j < points.cols (); ++j)
    result->SetPoint (j, points.col (j).data ());
  return result;
}

void
fitVtk (vtkThinPlateSplineTransform& transform, vtkPoints* source, vtkPoints* target)
{
  transform.SetSourceLandmarks (source);
  transform.SetTargetLandmarks (target);
  transform.SetBasisToR ();
  transform.Modified ();
  transform.Update ();
}

void
BM_FitMorphreg (benchmark::State& state)
{
  const Landmarks landmarks = makeLandmarks (state.range (0));
  for (auto _ : state) {
    morphreg::ThinPlateSpline<double, 3> tps;
    tps.fit (landmarks.source, landmarks.target);
    benchmark::DoNotOptimize (tps.getWeights ().data ());
  }
  morphreg::bench::reportOpenMpThreads (state);
}

void
BM_FitVtk (benchmark::State& state)
{
  const Landmarks landmarks = makeLandmarks (state.range (0));
  auto source = toVtkPoints (landmarks.source);
  auto target = toVtkPoints (landmarks.target);
  for (auto _ : state) {
    vtkNew<vtkThinPlateSplineTransform> transform;
    fitVtk (*transform, source, target);
    double out[3];
    transform->TransformPoint (landmarks.source.col (0).data (), out);
    benchmark::DoNotOptimize (out);
  }
  morphreg::bench::reportThreads (state, 1);
}

void
BM_EvaluateMorphreg (benchmark::State& state)
{
  const Landmarks landmarks = makeLandmarks (state.range (0));
  const Eigen::Matrix3Xd queries = randomPoints (state.range (1), 2);
  morphreg::ThinPlateSpline<double, 3> tps;
  tps.fit (landmarks.source, landmarks.target);
  const morphreg::bench::OpenMpThreads threads (state, state.range (2) == 1 ? 1 : 0);
  for (auto _ : state) {
    const Eigen::Matrix3Xd warped = tps.evaluate (queries);
    benchmark::DoNotOptimize (warped.data ());
  }
  state.counters["pairs/s"] = benchmark::Counter (double (state.range (0)) * double (state.range (1)),
                                                  benchmark::Counter::kIsIterationInvariantRate);
}

void
BM_EvaluateVtk (benchmark::State& state)
{
  const Landmarks landmarks = makeLandmarks (state.range (0));
  auto queries = toVtkPoints (randomPoints (state.range (1), 2));
  auto source = toVtkPoints (landmarks.source);
  auto target = toVtkPoints (landmarks.target);
  vtkNew<vtkThinPlateSplineTransform> transform;
  fitVtk (*transform, source, target);
  for (auto _ : state) {
    vtkNew<vtkPoints> warped;
    warped->SetDataTypeToDouble ();
    transform->TransformPoints (queries, warped);
    benchmark::DoNotOptimize (warped->GetPoint (0));
  }
  state.counters["pairs/s"] = benchmark::Counter (double (state.range (0)) * double (state.range (1)),
                                                  benchmark::Counter::kIsIterationInvariantRate);
  morphreg::bench::reportThreads (state, 1);
}
} // namespace

BENCHMARK (BM_FitMorphreg)
    ->Arg (66)
    ->Arg (500)
    ->Arg (1000)
    ->Arg (2000)
    ->Arg (5000)
    ->Apply (morphreg::bench::wallAndProcessCpuMs);
BENCHMARK (BM_FitVtk)->Arg (66)->Apply (morphreg::bench::wallAndProcessCpuMs);
BENCHMARK (BM_FitVtk)->Arg (500)->Arg (1000)->Iterations (1)->Apply (morphreg::bench::wallAndProcessCpuMs);
BENCHMARK (BM_EvaluateMorphreg)
    ->ArgsProduct ({{66, 500, 1000}, {16384, 1 << 20}, {0, 1}})
    ->Apply (morphreg::bench::wallAndProcessCpuMs);
BENCHMARK (BM_EvaluateVtk)
    ->Args ({66, 16384})
    ->Args ({500, 16384})
    ->Args ({1000, 16384})
    ->Apply (morphreg::bench::wallAndProcessCpuMs);
BENCHMARK (BM_EvaluateVtk)
    ->Args ({66, 1 << 20})
    ->Args ({500, 1 << 20})
    ->Args ({1000, 1 << 20})
    ->Iterations (1)
    ->Apply (morphreg::bench::wallAndProcessCpuMs);
BENCHMARK_MAIN ();

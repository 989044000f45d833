// SPDX-License-Identifier: BSD-3-Clause
// The Python module's overhead on a full registration: morphreg.register (numpy in, result and report dict out)
// against the same fit through the C++ API, in one process (the interpreter is embedded), on the demo's data: the
// 150-head population (seed 1, 9602 vertices), its 7-region model with 20 components, and the scan of the held-out
// head (seed 151) by the default scanner; the registration settings are `morphreg register`'s defaults. No external
// baseline: the Python module is compared with morphreg's own C++ API (the label says so); both run on the OpenMP
// threads.
#include "bench_report.h"

#include <morphreg/common/cloud_matrix.h>
#include <morphreg/common/order_statistics.h>
#include <morphreg/model/model_builder.h>
#include <morphreg/registration/registration_result_json.h>
#include <morphreg/registration/registration_settings.h>
#include <morphreg/registration/scan_checks.h>
#include <morphreg/pipeline/scan_units.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/scan_simulator.h>

#include <benchmark/benchmark.h>

#include <pybind11/embed.h>
#include <pybind11/numpy.h>

#include <nlohmann/json.hpp>

#include <chrono>
#include <functional>
#include <vector>

namespace py = pybind11;

namespace
{
struct Fixture
{
  morphreg::MorphableModel::Ptr model;
  morphreg::synthetic::SimulatedScan scan;
};

const Fixture&
fixture ()
{
  static const Fixture f = [] {
    const morphreg::synthetic::HeadGenerator generator;
    std::vector<morphreg::TriangleMesh> meshes;
    for (auto& head : generator.population (150, 1))
      meshes.push_back (std::move (head.mesh));
    morphreg::ModelBuilderSettings settings;
    settings.max_components = 20;
    Fixture built;
    built.model = morphreg::ModelBuilder (settings).build (meshes, generator.regions ());
    built.scan = morphreg::synthetic::ScanSimulator ().scan (generator.sample (151).mesh, 151);
    return built;
  }();
  return f;
}

/** The fit through the C++ API, the steps morphreg.register takes: the scan checked and brought to mm, MorphableICP
 *  configured as `morphreg register` configures it, align(), and the result's report. */
void
cppRegistration (const Fixture& f)
{
  const morphreg::RegistrationSettings settings;
  auto scan = std::make_shared<pcl::PointCloud<pcl::PointNormal>> (*f.scan.cloud);
  morphreg::requireRegistrableScan (morphreg::pointsOf (*scan), "scan");
  morphreg::convertScanToMillimetres (*scan, settings.units, *f.model, "scan");
  morphreg::MorphableICP<pcl::PointNormal> icp;
  morphreg::configureRegistration (icp, settings, f.model);
  icp.setInputTarget (scan);
  pcl::PointCloud<pcl::PointNormal> output;
  icp.align (output);
  const nlohmann::json report = morphreg::registrationResultJson (icp, *f.model);
  benchmark::DoNotOptimize (report.size ());
}

void
BM_CppRegistration (benchmark::State& state)
{
  const Fixture& f = fixture ();
  for (auto _ : state)
    cppRegistration (f);
  state.counters["points"] = static_cast<double> (f.scan.cloud->size ());
  morphreg::bench::reportNoExternalBaseline (state);
}
BENCHMARK (BM_CppRegistration)->Unit (benchmark::kMillisecond)->UseRealTime ()->MinTime (5.0);

/** numpy (N, 3) float64 points of a 3 x N matrix. */
py::array_t<double>
toNumpy (const Eigen::Matrix3Xd& matrix)
{
  return py::array_t<double> ({static_cast<py::ssize_t> (matrix.cols ()), py::ssize_t{3}}, matrix.data ());
}

/** morphreg imported from the build tree, and the fixture's model, points and normals as Python objects. */
struct PythonCall
{
  py::object register_function, model;
  py::array_t<double> points, normals;

  explicit PythonCall (const Fixture& f)
  {
    py::module_::import ("sys").attr ("path").attr ("insert") (0, MORPHREG_PYTHON_PACKAGE_PARENT);
    register_function = py::module_::import ("morphreg").attr ("register");
    model = py::cast (f.model);
    points = toNumpy (morphreg::pointsOf (*f.scan.cloud));
    normals = toNumpy (morphreg::normalsOf (*f.scan.cloud));
  }

  /** The same fit through the Python module: morphreg.register (model, points, normals), default settings. */
  void
  operator() () const
  {
    const py::object result = register_function (model, points, normals);
    benchmark::DoNotOptimize (result.ptr ());
  }
};

void
BM_PythonRegistration (benchmark::State& state)
{
  const PythonCall call (fixture ());
  for (auto _ : state)
    call ();
  morphreg::bench::reportNoExternalBaseline (state);
}
BENCHMARK (BM_PythonRegistration)->Unit (benchmark::kMillisecond)->UseRealTime ()->MinTime (5.0);

double
secondsOf (const std::function<void ()>& run)
{
  const auto start = std::chrono::steady_clock::now ();
  run ();
  return std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
}

/** The two fits in pairs, alternating which goes first, so that the machine's drift hits both alike: the counters
 *  are the medians of the C++ and Python times and of the Python overhead per pair, (Python - C++) / C++. */
void
BM_PythonOverheadPaired (benchmark::State& state)
{
  const Fixture& f = fixture ();
  const PythonCall call (f);
  std::vector<double> cpp, python, overhead;
  for (auto _ : state) {
    const bool python_first = overhead.size () % 2 == 1;
    const double first = secondsOf ([&] { python_first ? call () : cppRegistration (f); });
    const double second = secondsOf ([&] { python_first ? cppRegistration (f) : call (); });
    cpp.push_back (python_first ? second : first);
    python.push_back (python_first ? first : second);
    overhead.push_back ((python.back () - cpp.back ()) / cpp.back ());
  }
  state.counters["cpp_ms"] = 1e3 * morphreg::median (cpp);
  state.counters["python_ms"] = 1e3 * morphreg::median (python);
  state.counters["overhead_pct"] = 100.0 * morphreg::median (overhead);
  morphreg::bench::reportNoExternalBaseline (state);
}
BENCHMARK (BM_PythonOverheadPaired)->Unit (benchmark::kMillisecond)->UseRealTime ()->Iterations (20);
} // namespace

int
main (int argc, char** argv)
{
  const py::scoped_interpreter interpreter;
  benchmark::Initialize (&argc, argv);
  benchmark::RunSpecifiedBenchmarks ();
  benchmark::Shutdown ();
  return 0;
}

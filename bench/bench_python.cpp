// The Python module's overhead on a full registration: morphreg.register (numpy in, result and report dict out)
// against the same fit through the C++ API, in one process (the interpreter is embedded), on the demo's data: the
// 150-head population (seed 1, 9602 vertices), its 7-region model with 20 components, and the scan of the held-out
// head (seed 151) by the default scanner; the registration settings are `morphreg register`'s defaults.
#include <morphreg/common/cloud_matrix.h>
#include <morphreg/model/model_builder.h>
#include <morphreg/registration/registration_result_json.h>
#include <morphreg/registration/registration_settings.h>
#include <morphreg/registration/scan_checks.h>
#include <morphreg/registration/scan_units.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/scan_simulator.h>

#include <benchmark/benchmark.h>

#include <pybind11/embed.h>
#include <pybind11/numpy.h>

#include <nlohmann/json.hpp>

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
BM_CppRegistration (benchmark::State& state)
{
  const Fixture& f = fixture ();
  const morphreg::RegistrationSettings settings;
  for (auto _ : state) {
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
  state.counters["points"] = static_cast<double> (f.scan.cloud->size ());
}
BENCHMARK (BM_CppRegistration)->Unit (benchmark::kMillisecond)->UseRealTime ()->MinTime (5.0);

/** numpy (N, 3) float64 points of a 3 x N matrix. */
py::array_t<double>
toNumpy (const Eigen::Matrix3Xd& matrix)
{
  return py::array_t<double> ({static_cast<py::ssize_t> (matrix.cols ()), py::ssize_t{3}}, matrix.data ());
}

/** The same fit through the Python module: morphreg.register (model, points, normals) with default settings. */
void
BM_PythonRegistration (benchmark::State& state)
{
  const Fixture& f = fixture ();
  py::module_::import ("sys").attr ("path").attr ("insert") (0, MORPHREG_PYTHON_PACKAGE_PARENT);
  const py::module_ morphreg_module = py::module_::import ("morphreg");
  const py::object model = py::cast (f.model);
  const py::array_t<double> points = toNumpy (morphreg::pointsOf (*f.scan.cloud));
  const py::array_t<double> normals = toNumpy (morphreg::normalsOf (*f.scan.cloud));
  const py::object register_function = morphreg_module.attr ("register");
  for (auto _ : state) {
    const py::object result = register_function (model, points, normals);
    benchmark::DoNotOptimize (result.ptr ());
  }
}
BENCHMARK (BM_PythonRegistration)->Unit (benchmark::kMillisecond)->UseRealTime ()->MinTime (5.0);
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

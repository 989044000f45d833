// `morphreg resample`: a scan + a model file -> the scan's surface in the model's topology. The scan is registered
// exactly as `register` does it, then ScanResampler moves the fitted mesh's vertices onto the scan along their normals
// and fills the holes; writes the resampled mesh (vertex colours: observed / filled), the fitted mesh and one JSON
// report (the registration's, with the resampling's coverage and holes).
#include "commands.h"
#include "option_checks.h"
#include "output_files.h"
#include "pipeline.h"

#include <morphreg/common/colour_map.h>
#include <morphreg/common/error.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/model_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/resampling/scan_resampler.h>

#include <chrono>
#include <filesystem>
#include <iostream>
#include <memory>

namespace morphreg
{
namespace tools
{
namespace
{
struct ResampleOptions
{
  RegisterOptions registration; ///< its out is the fitted mesh, its report the resampling's report
  std::string out = "resampled.ply";
  double ray_distance = 5.0;
  double normal_agreement = 60.0;
  int ring_width = 3;
  double max_hole_fraction = 0.5;
  double fill_smoothing = 1.0;
};

/** Observed vertices light grey, filled ones orange. */
VertexColours
stateColours (const std::vector<ResampledVertex>& state)
{
  VertexColours colours (3, static_cast<Eigen::Index> (state.size ()));
  for (std::size_t v = 0; v < state.size (); ++v)
    colours.col (static_cast<Eigen::Index> (v)) =
        state[v] == ResampledVertex::observed ? Rgb8 (200, 200, 200) : Rgb8 (240, 120, 20);
  return colours;
}

nlohmann::json
statisticsJson (const ResamplingStatistics& stats)
{
  nlohmann::json holes = nlohmann::json::array ();
  for (const ResamplingHole& hole : stats.holes)
    holes.push_back ({{"vertices", hole.vertices},
                      {"area_mm2", hole.area},
                      {"ring_vertices", hole.ring_vertices},
                      {"max_fill_mm", hole.max_fill},
                      {"folded_triangles", hole.folded_triangles}});
  return {{"vertices", stats.vertices},
          {"observed", stats.observed},
          {"filled", stats.filled},
          {"coverage", stats.coverage},
          {"observed_area_fraction", stats.observed_area},
          {"largest_hole_area_fraction", stats.largest_hole_area},
          {"folded_triangles", stats.folded_triangles},
          {"median_displacement_mm", stats.median_displacement},
          {"hole_count", stats.holes.size ()},
          {"holes", holes},
          {"timings_s", {{"rays", stats.ray_seconds}, {"fill", stats.fill_seconds}}}};
}

/** Resamples the scan into the fit's topology, writes the mesh and adds the statistics to \a report. A fit that failed
 *  its checks is not resampled (the report says so; register's exit code 4 follows). */
void
resampleFit (const ResampleOptions& options, const pcl::PointCloud<pcl::PointNormal>& scan, const TriangleMesh& fitted,
             nlohmann::json& report)
{
  if (!report["checks"]["passed"].get<bool> ()) {
    report["resampling"] = {{"status", "skipped"}, {"reason", "the fit failed its checks"}};
    report["resampled_mesh"] = nullptr;
    return;
  }
  const auto start = std::chrono::steady_clock::now ();
  ScanResampler resampler;
  resampler.setMaxDistance (options.ray_distance);
  resampler.setNormalAgreement (options.normal_agreement);
  resampler.setRingWidth (options.ring_width);
  resampler.setMaxHoleFraction (options.max_hole_fraction);
  resampler.setFillRegularization (options.fill_smoothing);
  resampler.setInputReference (fitted);
  ResamplingResult result;
  try {
    resampler.setInputScan (scan);
    result = resampler.resample ();
  }
  catch (const InvalidInputError& e) {
    throw InvalidInputError (options.registration.scan +
                             ": cannot be resampled into the model's topology: " + e.what ());
  }
  savePolygonMesh (options.out, toPolygonMesh (result.mesh, stateColours (result.state)));
  report["resampling"] = statisticsJson (result.statistics);
  report["resampling"]["status"] = "ok";
  report["resampling"]["settings"] = {{"ray_distance_mm", options.ray_distance},
                                      {"normal_agreement_deg", options.normal_agreement},
                                      {"ring_width", options.ring_width},
                                      {"max_hole_fraction", options.max_hole_fraction},
                                      {"fill_smoothing", options.fill_smoothing}};
  report["resampling"]["timings_s"]["total"] =
      std::chrono::duration<double> (std::chrono::steady_clock::now () - start).count ();
  report["resampled_mesh"] = options.out;
  if (!options.registration.quiet)
    std::cout << "resampled " << options.registration.scan << ": " << result.statistics.observed << " of "
              << result.statistics.vertices << " vertices observed (coverage " << result.statistics.coverage << "), "
              << result.statistics.filled << " filled in " << result.statistics.holes.size () << " holes; wrote "
              << options.out << " (vertex colours: grey observed, orange filled)\n";
}

void
runResample (ResampleOptions options)
{
  RegisterOptions& registration = options.registration;
  if (registration.out.empty ())
    registration.out = std::filesystem::path (options.out).replace_extension ().string () + "_fit.ply";
  if (registration.report.empty ())
    registration.report = std::filesystem::path (options.out).replace_extension (".json").string ();
  OutputFiles outputs ({options.out, registration.out, registration.report},
                       {registration.scan, registration.model, registration.landmarks});
  const MorphableModel::Ptr model = loadModel (registration.model);
  keepOnSuccessOrFitFailure (outputs, [&] {
    return registerScan (registration, model, nullptr, 0.0, std::cout, std::cerr,
                         [&] (const pcl::PointCloud<pcl::PointNormal>& scan, const TriangleMesh& fitted,
                              nlohmann::json& report) { resampleFit (options, scan, fitted, report); });
  });
}

void
addResamplingOptions (CLI::App* command, ResampleOptions& options)
{
  command
      ->add_option ("--ray-distance", options.ray_distance,
                    "farthest a vertex moves along its normal onto the scan (mm); beyond it the vertex is filled")
      ->check (positive ())
      ->capture_default_str ();
  command
      ->add_option ("--normal-agreement", options.normal_agreement,
                    "largest angle between a vertex normal and the scan's at the hit (degrees)")
      ->check (CLI::Range (1.0, 180.0))
      ->capture_default_str ();
  command->add_option ("--ring-width", options.ring_width, "rings of observed vertices around a hole that fill it")
      ->check (CLI::Range (1, 20))
      ->capture_default_str ();
  command
      ->add_option ("--max-hole-fraction", options.max_hole_fraction,
                    "largest share of the model's surface one hole may cover (else the scan is refused)")
      ->check (CLI::Range (0.01, 1.0))
      ->capture_default_str ();
  command->add_option ("--fill-smoothing", options.fill_smoothing, "thin plate spline smoothing of the fills (mm)")
      ->check (nonNegative ())
      ->capture_default_str ();
}
} // namespace

void
registerResampleCommand (CLI::App& app)
{
  auto options = std::make_shared<ResampleOptions> ();
  RegisterOptions& registration = options->registration;
  registration.out.clear ();
  CLI::App* command =
      app.add_subcommand ("resample", "register a scan (as register does) and resample it into the model's topology");
  command->add_option ("-s,--scan", registration.scan, "scan (.pcd .ply .obj .stl .off); its unit: see --units")
      ->required ();
  command->add_option ("-m,--model", registration.model, "model file (.h5, from build-model or statismo)")->required ();
  command->add_option ("-l,--landmarks", registration.landmarks, "landmarks on the scan to start the fit from");
  command->add_option ("-o,--out", options->out, "resampled mesh to write (PLY; colours: observed / filled)")
      ->capture_default_str ();
  command->add_option ("--fit-out", registration.out, "the model's fit to write (default: the --out path + _fit)");
  command->add_option ("--report", registration.report, "JSON report to write (default: the --out path with .json)");
  addResamplingOptions (command, *options);
  addRegistrationOptions (command, registration);
  command->add_flag ("-q,--quiet", registration.quiet, "no progress output");
  command->footer ("Exit codes as register's: 1 for a scan that cannot be resampled (no overlap with the fit, another "
                   "unit, a hole over more than --max-hole-fraction of the model), its outputs removed; 4 for a fit "
                   "that failed its checks (fit and report written, nothing resampled).");
  command->callback ([options] () { runResample (*options); });
}
} // namespace tools
} // namespace morphreg

// `morphreg warp`: a mesh warped by a thin plate spline from source to target landmarks, globally or by segments
// with blended seams; with --truth, the warp's error per vertex (colours of the output PLY) and in the report.
#include "commands.h"
#include "mesh_annotations.h"
#include "option_checks.h"
#include "output_files.h"
#include "progress.h"

#include <morphreg/common/error.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/warp/segmented_warp.h>
#include <morphreg/warp/warp_quality.h>
#include <morphreg/common/colour_map.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <iostream>
#include <memory>

namespace morphreg
{
namespace tools
{
namespace
{
struct WarpOptions
{
  std::string mesh, source, target, out = "warped.ply";
  std::string labels, truth, report;
  std::vector<double> blend{100.0};  ///< one for every segment, or one per segment
  std::vector<double> overlap{90.0}; ///< one for every segment, or one per segment
  double lambda = 0.0;
  bool quiet = false;
};

/** The landmark pairs present in both files, as matching columns; every name must be in both. */
std::pair<Eigen::Matrix3Xd, Eigen::Matrix3Xd>
landmarkPairs (const std::string& source_path, const std::string& target_path)
{
  const LandmarkPositions source = loadNamedPoints (source_path), target = loadNamedPoints (target_path);
  std::string missing;
  for (const auto& entry : source)
    if (!target.count (entry.first))
      missing += " " + entry.first;
  for (const auto& entry : target)
    if (!source.count (entry.first))
      missing += " " + entry.first;
  if (!missing.empty ())
    throw InvalidInputError ("warp: the landmark files " + source_path + " and " + target_path +
                             " must name the same landmarks; not in both:" + missing);
  requireOneTargetPerPoint (source, target, source_path, target_path);
  Eigen::Matrix3Xd from (3, static_cast<Eigen::Index> (source.size ())), to (3, from.cols ());
  Eigen::Index column = 0;
  for (const auto& [name, position] : source) {
    from.col (column) = position;
    to.col (column++) = target.at (name);
  }
  return {from, to};
}

/** The \a values of \a option: given once they apply to every segment; otherwise one value per segment. */
std::vector<double>
valuePerSegment (const std::vector<double>& values, int num_segments, const std::string& option)
{
  if (values.size () == 1)
    return std::vector<double> (static_cast<std::size_t> (num_segments), values.front ());
  if (values.size () != static_cast<std::size_t> (num_segments))
    throw InvalidInputError ("warp: " + option + " has " + std::to_string (values.size ()) + " values for " +
                             std::to_string (num_segments) + " segments; give one value or one per segment");
  return values;
}

/** Runs \a fit (the spline's or the segments' fit to the landmarks); a configuration it cannot use (too few,
 *  collinear or flat landmarks) is reported with both landmark files. */
template <typename Fit>
auto
fitToLandmarks (const WarpOptions& options, Fit fit) -> decltype (fit ())
{
  try {
    return fit ();
  }
  catch (const InvalidInputError& e) {
    throw InvalidInputError ("warp: the landmarks of " + options.source + " -> " + options.target + ": " + e.what ());
  }
}

TriangleMesh
warpMesh (const WarpOptions& options, const TriangleMesh& mesh, nlohmann::json& report)
{
  const auto [source, target] = landmarkPairs (options.source, options.target);
  report["landmarks"] = source.cols ();
  if (options.labels.empty ()) {
    ThinPlateSpline<double, 3> spline;
    spline.setRegularization (options.lambda);
    fitToLandmarks (options, [&] { spline.fit (source, target); });
    report["mode"] = "global";
    report["bending_energy"] = spline.bendingEnergy ();
    report["merged_landmarks"] = spline.mergedLandmarks ();
    return spline.transformMesh (mesh);
  }
  const RegionLabels segments = loadRegionLabels (options.labels, mesh.numVertices ());
  const int num_segments = static_cast<int> (segments.names.size ());
  SegmentedWarp warp (segments.labels, num_segments);
  warp.setRegularization (options.lambda);
  const std::vector<double> blend = valuePerSegment (options.blend, num_segments, "--blend");
  for (int s = 0; s < num_segments; ++s)
    warp.setSegmentBlendWidth (s, blend[static_cast<std::size_t> (s)]);
  const std::vector<double> overlap = valuePerSegment (options.overlap, num_segments, "--overlap");
  const auto subsets = fitToLandmarks (options, [&] { return warp.setLandmarks (mesh, source, target, overlap); });
  for (const auto& subset : subsets)
    report["segment_landmarks"].push_back (subset.size ());
  report["mode"] = "segmented";
  report["blend_width_mm"] = blend;
  for (double o : overlap) // an infinite overlap (JSON has no infinity): the segment takes every landmark
    report["overlap_mm"].push_back (std::isinf (o) ? nlohmann::json ("all") : nlohmann::json (o));
  return warp.warp (mesh);
}

void
runWarp (const WarpOptions& options)
{
  OutputFiles outputs ({options.out, options.report},
                       {options.mesh, options.source, options.target, options.labels, options.truth});
  const TriangleMesh mesh = loadTriangleMesh (options.mesh);
  nlohmann::json report = {{"units", "mm"}, {"mesh", options.mesh}, {"output", options.out}};
  const TriangleMesh warped = warpMesh (options, mesh, report);
  if (options.truth.empty ()) {
    saveTriangleMesh (options.out, warped);
  }
  else {
    const TriangleMesh truth = loadTriangleMesh (options.truth);
    requireSameTopology (mesh, truth, options.truth);
    const Eigen::VectorXd errors = (warped.vertices - truth.vertices).colwise ().norm ().transpose ();
    savePolygonMesh (options.out,
                     toPolygonMesh (warped, residualColours (errors, std::max (errors.maxCoeff (), 1e-9))));
    std::vector<int> labels (static_cast<std::size_t> (mesh.numVertices ()), 0);
    if (!options.labels.empty ())
      labels = loadRegionLabels (options.labels, mesh.numVertices ()).labels;
    const WarpQuality quality = evaluateWarp (warped, truth, labels, 100.0, &mesh);
    report["error_mm"] = {{"mean", quality.mean_error}, {"rms", quality.rms_error}, {"max", quality.max_error}};
    report["seam"] = quality.seam;
    report["band"] = quality.band;
    report["folded_in_band"] = quality.folded_in_band;
    if (!options.quiet)
      std::cout << "error against " << options.truth << ": mean " << quality.mean_error << " mm, max "
                << quality.max_error << " mm (vertex colours of " << options.out << ")\n";
  }
  if (!options.report.empty ())
    writeJsonFile (options.report, report);
  outputs.keep ();
  std::cout << "wrote " << options.out << '\n';
}
} // namespace

void
registerWarpCommand (CLI::App& app)
{
  auto options = std::make_shared<WarpOptions> ();
  CLI::App* command = app.add_subcommand ("warp", "warp a mesh with a 3D thin plate spline (global or segmented)");
  command->add_option ("-m,--mesh", options->mesh, "mesh to warp (.ply .obj .vtk .stl)")->required ();
  command->add_option ("-s,--source", options->source, "source landmarks on the mesh (.pp .json .csv)")->required ();
  command->add_option ("-t,--target", options->target, "target landmarks, same names (.pp .json .csv)")->required ();
  command->add_option ("-o,--out", options->out, "warped mesh to write")->capture_default_str ();
  command->add_option ("--labels", options->labels,
                       "segment per vertex, JSON {\"regions\": [names], \"labels\": [...]}: segmented warp");
  command
      ->add_option ("--blend", options->blend,
                    "how far each segment's warp reaches into its neighbours along the mesh (mm; one value, or one "
                    "per segment separated by commas; 0 = hard segments)")
      ->delimiter (',')
      ->check (nonNegative ())
      ->capture_default_str ();
  command
      ->add_option ("--overlap", options->overlap,
                    "landmarks join a segment at most this much farther (mm; one value, or one per segment "
                    "separated by commas; inf = every landmark)")
      ->delimiter (',')
      ->check (nonNegativeOrInfinite ())
      ->capture_default_str ();
  command->add_option ("--lambda", options->lambda, "TPS regularisation (0 = exact interpolation)")
      ->check (nonNegative ())
      ->capture_default_str ();
  command->add_option ("--truth", options->truth, "true target mesh (same topology): report the warp's error");
  command->add_option ("--report", options->report, "JSON report to write");
  command->add_flag ("-q,--quiet", options->quiet, "less output");
  command->callback ([options] () { runWarp (*options); });
}

} // namespace tools
} // namespace morphreg

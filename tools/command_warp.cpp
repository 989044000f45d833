// SPDX-License-Identifier: BSD-3-Clause
// `morphreg warp`: a mesh warped from source to target landmarks by a thin plate spline, globally or by segments
// with blended seams, by moving least squares (--method mls), or re-postured with rigid bones (--method
// articulated); with --truth, the warp's error per vertex (colours of the output PLY) and in the report.
#include "commands.h"
#include "mesh_output.h"
#include "option_checks.h"
#include "progress.h"
#include "provenance.h"

#include <morphreg/common/colour_map.h>
#include <morphreg/common/error.h>
#include <morphreg/common/length_unit.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/io/output_transaction.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/datasets/makehuman_bodies.h>
#include <morphreg/io/mesh_annotations.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/skeleton_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/warp/articulated_warp.h>
#include <morphreg/warp/limb_parts.h>
#include <morphreg/warp/moving_least_squares_warp.h>
#include <morphreg/warp/segmented_warp.h>
#include <morphreg/warp/warp_quality.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>
#include <memory>
#include <tuple>

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
  std::string method = "tps";
  std::string skeleton; ///< skeleton file of the articulated method; empty: MakeHuman's major joints
  std::string units = "mm";
  std::vector<double> blend{100.0};  ///< one for every segment, or one per segment
  std::vector<double> overlap{90.0}; ///< one for every segment, or one per segment
  double lambda = 0.0;
  double rigidity = 1.0, skinning_width = 30.0;
  double mls_falloff = 1.0;
  bool quiet = false;
};

/** A surface landmark of the articulated method must be a vertex of the mesh: within this distance (mm) of one. */
constexpr double kSurfaceLandmarkTolerance = 1.0;

/** The landmarks of both files (mm), checked to name the same points; every name must be in both. */
std::pair<LandmarkPositions, LandmarkPositions>
namedLandmarkPairs (const std::string& source_path, const std::string& target_path, double millimetres_per_unit)
{
  LandmarkPositions source = loadNamedPoints (source_path), target = loadNamedPoints (target_path);
  for (LandmarkPositions* points : {&source, &target})
    for (auto& entry : *points)
      entry.second *= millimetres_per_unit;
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
  return {source, target};
}

/** The landmark pairs as matching columns. */
std::pair<Eigen::Matrix3Xd, Eigen::Matrix3Xd>
landmarkColumns (const LandmarkPositions& source, const LandmarkPositions& target)
{
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

/** The inputs, in mm. */
struct WarpInputs
{
  TriangleMesh mesh;
  LandmarkPositions source, target;
};

TriangleMesh
globalWarp (const WarpOptions& options, const WarpInputs& inputs, nlohmann::json& report)
{
  const auto [source, target] = landmarkColumns (inputs.source, inputs.target);
  ThinPlateSpline<double, 3> spline;
  spline.setRegularization (options.lambda);
  fitToLandmarks (options, [&] { spline.fit (source, target); });
  report["mode"] = "global";
  report["bending_energy"] = spline.bendingEnergy ();
  report["merged_landmarks"] = spline.mergedLandmarks ();
  return spline.transformMesh (inputs.mesh);
}

TriangleMesh
segmentedWarp (const WarpOptions& options, const WarpInputs& inputs, nlohmann::json& report)
{
  const auto [source, target] = landmarkColumns (inputs.source, inputs.target);
  const RegionLabels segments = loadRegionLabels (options.labels, inputs.mesh.numVertices ());
  const int num_segments = static_cast<int> (segments.names.size ());
  SegmentedWarp warp (segments.labels, num_segments);
  warp.setRegularization (options.lambda);
  const std::vector<double> blend = valuePerSegment (options.blend, num_segments, "--blend");
  for (int s = 0; s < num_segments; ++s)
    warp.setSegmentBlendWidth (s, blend[static_cast<std::size_t> (s)]);
  const std::vector<double> overlap = valuePerSegment (options.overlap, num_segments, "--overlap");
  const auto subsets =
      fitToLandmarks (options, [&] { return warp.setLandmarks (inputs.mesh, source, target, overlap); });
  for (const auto& subset : subsets)
    report["segment_landmarks"].push_back (subset.size ());
  report["mode"] = "segmented";
  report["blend_width_mm"] = blend;
  for (double o : overlap) // an infinite overlap (JSON has no infinity): the segment takes every landmark
    report["overlap_mm"].push_back (std::isinf (o) ? nlohmann::json ("all") : nlohmann::json (o));
  return warp.warp (inputs.mesh);
}

TriangleMesh
movingLeastSquaresWarp (const WarpOptions& options, const WarpInputs& inputs, nlohmann::json& report)
{
  const auto [source, target] = landmarkColumns (inputs.source, inputs.target);
  MovingLeastSquaresWarp warp;
  warp.setFalloff (options.mls_falloff);
  fitToLandmarks (options, [&] { warp.setLandmarks (source, target); });
  report["mode"] = "moving_least_squares";
  report["falloff_exponent"] = options.mls_falloff;
  report["merged_landmarks"] = warp.mergedLandmarks ();
  return warp.warp (inputs.mesh);
}

Skeleton
chosenSkeleton (const WarpOptions& options)
{
  return options.skeleton.empty () ? makeHumanSkeleton () : loadSkeleton (options.skeleton);
}

/** Every landmark that names no joint of the skeleton pins the vertex it lies on; one off the mesh is an error. */
void
setSurfaceLandmarks (ArticulatedWarp& warp, const WarpOptions& options, const WarpInputs& inputs,
                     nlohmann::json& report)
{
  const std::vector<std::string> joints = warp.skeleton ().jointNames ();
  std::vector<int> vertices;
  std::vector<Eigen::Vector3d> targets;
  for (const auto& [name, position] : inputs.source) {
    if (std::binary_search (joints.begin (), joints.end (), name))
      continue;
    Eigen::Index vertex = 0;
    const double distance =
        std::sqrt ((inputs.mesh.vertices.colwise () - position).colwise ().squaredNorm ().minCoeff (&vertex));
    if (distance > kSurfaceLandmarkTolerance)
      throw InvalidInputError ("warp: landmark '" + name + "' of " + options.source +
                               " is no joint of the skeleton and not on the mesh (" + std::to_string (distance) +
                               " mm from its nearest vertex of " + options.mesh +
                               "); surface landmarks must lie on vertices");
    vertices.push_back (static_cast<int> (vertex));
    targets.push_back (inputs.target.at (name));
  }
  Eigen::Matrix3Xd target_columns (3, static_cast<Eigen::Index> (targets.size ()));
  for (std::size_t k = 0; k < targets.size (); ++k)
    target_columns.col (static_cast<Eigen::Index> (k)) = targets[k];
  warp.setSurfaceLandmarks (vertices, target_columns);
  report["surface_landmarks"] = vertices.size ();
}

TriangleMesh
articulatedWarp (const WarpOptions& options, const WarpInputs& inputs, nlohmann::json& report)
{
  if (options.labels.empty ())
    throw InvalidInputError ("warp --method articulated needs --labels: the segment of each vertex, which the "
                             "skeleton's bones carry");
  const RegionLabels segments = loadRegionLabels (options.labels, inputs.mesh.numVertices ());
  const std::string skeleton_name = options.skeleton.empty () ? "makehuman (built in)" : options.skeleton;
  std::unique_ptr<ArticulatedWarp> warp;
  try {
    warp = std::make_unique<ArticulatedWarp> (chosenSkeleton (options), segments.labels, segments.names);
  }
  catch (const InvalidInputError& e) {
    throw InvalidInputError ("warp: the skeleton " + skeleton_name + " does not fit the labels " + options.labels +
                             ": " + e.what ());
  }
  warp->setSkinningFalloff ({options.skinning_width, SkinningFalloff ().reach});
  warp->setRigidity (options.rigidity);
  fitToLandmarks (options, [&] { warp->setJoints (inputs.source, inputs.target); });
  setSurfaceLandmarks (*warp, options, inputs, report);
  report["mode"] = "articulated";
  report["skeleton"] = skeleton_name;
  report["bones"] = warp->skeleton ().numBones ();
  report["joints"] = warp->skeleton ().boneJointNames ().size ();
  report["rigidity"] = options.rigidity;
  report["skinning_width_mm"] = options.skinning_width;
  return warp->warp (inputs.mesh);
}

TriangleMesh
warpMesh (const WarpOptions& options, const WarpInputs& inputs, nlohmann::json& report)
{
  report["landmarks"] = inputs.source.size ();
  if (options.method == "articulated")
    return articulatedWarp (options, inputs, report);
  if (options.method == "mls")
    return movingLeastSquaresWarp (options, inputs, report);
  return options.labels.empty () ? globalWarp (options, inputs, report) : segmentedWarp (options, inputs, report);
}

/** A mesh file in the inputs' unit, in mm. */
TriangleMesh
loadMeshInMillimetres (const std::string& path, double millimetres_per_unit)
{
  TriangleMesh mesh = loadTriangleMesh (path);
  mesh.vertices *= millimetres_per_unit;
  return mesh;
}

/** The error against the truth: vertex colours and quality, the report's figures (with the limb parts for the
 *  articulated method) and a line on stdout; returns what the written mesh carries (meshContents). */
std::string
evaluateAgainstTruth (const WarpOptions& options, const WarpInputs& inputs, const TriangleMesh& warped,
                      nlohmann::json& report)
{
  const TriangleMesh truth = loadMeshInMillimetres (options.truth, millimetresPer (parseLengthUnit (options.units)));
  requireSameTopology (inputs.mesh, truth, options.truth);
  const Eigen::VectorXd errors = (warped.vertices - truth.vertices).colwise ().norm ().transpose ();
  const double colour_max = std::max (errors.maxCoeff (), 1e-9);
  savePolygonMesh (options.out, toPolygonMesh (warped, residualColours (errors, colour_max), errors));
  std::vector<int> labels (static_cast<std::size_t> (inputs.mesh.numVertices ()), 0);
  if (!options.labels.empty ())
    labels = loadRegionLabels (options.labels, inputs.mesh.numVertices ()).labels;
  const WarpQuality quality = evaluateWarp (warped, truth, labels, 100.0, &inputs.mesh);
  report["error_mm"] = {{"mean", quality.mean_error}, {"rms", quality.rms_error}, {"max", quality.max_error}};
  report["seam"] = quality.seam;
  report["band"] = quality.band;
  report["folded_in_band"] = quality.folded_in_band;
  report["folded_triangles"] = {{"warped", countFoldedTriangles (warped)}, {"truth", countFoldedTriangles (truth)}};
  if (options.method == "articulated")
    for (const LimbPartError& part : limbPartErrors (inputs.mesh, errors, chosenSkeleton (options), inputs.source))
      report["limb_parts"][part.part] = {
          {"bones", part.bones + "*"}, {"vertices", part.vertices}, {"max_error_mm", part.max_error}};
  if (!options.quiet)
    std::cout << "error against " << options.truth << ": mean " << quality.mean_error << " mm, max "
              << quality.max_error << " mm\n";
  std::ostringstream colours;
  colours << "error against the truth, 0-" << colour_max << " mm";
  return meshContents (options.out, colours.str (), "error against the truth in mm");
}

void
runWarp (const WarpOptions& options)
{
  OutputPlan plan;
  for (const auto& [input, role] : {std::pair (options.mesh, "--mesh"), std::pair (options.source, "--source"),
                                    std::pair (options.target, "--target"), std::pair (options.labels, "--labels"),
                                    std::pair (options.truth, "--truth"), std::pair (options.skeleton, "--skeleton")})
    plan.addInput (input, role);
  plan.addOutput (options.out, "--out");
  plan.addOptionalOutput (options.report, "--report");
  plan.check ();
  OutputTransaction outputs (plan.outputs ());
  const double millimetres_per_unit = millimetresPer (parseLengthUnit (options.units));
  WarpInputs inputs{loadMeshInMillimetres (options.mesh, millimetres_per_unit), {}, {}};
  std::tie (inputs.source, inputs.target) = namedLandmarkPairs (options.source, options.target, millimetres_per_unit);
  if (millimetres_per_unit != 1.0 && !options.quiet)
    std::cout << "units: the inputs are in " << options.units << ", converted to mm (the output is in mm)\n";
  nlohmann::json report = {{"status", "ok"},
                           {"units", "mm"},
                           {"input_units", options.units},
                           {"mesh", options.mesh},
                           {"output", options.out}};
  const TriangleMesh warped = warpMesh (options, inputs, report);
  std::string contents;
  if (options.truth.empty ())
    saveTriangleMesh (options.out, warped);
  else
    contents = ' ' + evaluateAgainstTruth (options, inputs, warped, report);
  if (!options.report.empty ())
    writeReport (options.report, report);
  outputs.commit ();
  std::cout << "wrote " << options.out << contents << '\n';
}

/** The articulated and moving least squares warps' settings, each in the range where its result means something. */
void
addArticulatedOptions (CLI::App* command, WarpOptions& options)
{
  command
      ->add_option ("--rigidity", options.rigidity,
                    "articulated: weight of the as-rigid-as-possible refinement (0 to 1000; beyond, the bones no "
                    "longer follow the landmarks)")
      ->check (inRange (0.0, 1000.0))
      ->capture_default_str ();
  command
      ->add_option ("--skinning-width", options.skinning_width,
                    "articulated: how fast a bone's weight falls along the mesh (mm, 0.1 to 10000)")
      ->check (inRange (0.1, 10000.0))
      ->capture_default_str ();
  command
      ->add_option ("--mls-falloff", options.mls_falloff,
                    "mls: landmark weights fall as 1 / distance^(2 a); larger a is more local (0.1 to 10)")
      ->check (inRange (0.1, 10.0))
      ->capture_default_str ();
}
} // namespace

void
registerWarpCommand (CLI::App& app)
{
  auto options = std::make_shared<WarpOptions> ();
  CLI::App* command = app.add_subcommand (
      "warp", "warp a mesh with a 3D thin plate spline (global or segmented) or re-posture it with rigid bones");
  command->add_option ("--mesh", options->mesh, "mesh to warp (.ply .obj .vtk .stl .off .gltf .glb)")->required ();
  command->add_option ("--source", options->source, "source landmarks on the mesh (.pp .json .csv)")->required ();
  command->add_option ("-t,--target", options->target, "target landmarks, same names (.pp .json .csv)")->required ();
  command
      ->add_option ("-o,--out", options->out,
                    meshOutputHelp ("warped mesh to write; with --truth", "error against the truth",
                                    "error against the truth in mm"))
      ->capture_default_str ();
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
  command
      ->add_option ("--method", options->method,
                    "tps: thin plate spline (by segments with --labels); articulated: rigid bones between the "
                    "landmarks that name joints of --skeleton, skinned by --labels, refined as rigid as possible; "
                    "other landmarks must lie on mesh vertices and pin them; mls: moving least squares, each point "
                    "follows the affine motion of its nearest landmarks (between subjects)")
      ->check (CLI::IsMember ({"tps", "articulated", "mls"}))
      ->capture_default_str ();
  command->add_option ("--skeleton", options->skeleton,
                       "articulated: skeleton JSON {\"bones\": [{\"name\", \"head\", \"tail\", \"segment\", "
                       "\"twist\": [from, to]}]} (default: MakeHuman's 51 major joints)");
  addArticulatedOptions (command, *options);
  command
      ->add_option ("--units", options->units,
                    "unit of the mesh, landmark and truth files (mm, cm, dm, m, in); converted to mm, and the "
                    "output is in mm")
      ->check (CLI::IsMember ({"mm", "cm", "dm", "m", "in"}))
      ->capture_default_str ();
  command->add_option ("--truth", options->truth, "true target mesh (same topology): report the warp's error");
  command->add_option ("--report", options->report, "JSON report to write");
  command->add_flag ("-q,--quiet", options->quiet, "less output");
  command->callback ([options] () { runWarp (*options); });
}

} // namespace tools
} // namespace morphreg

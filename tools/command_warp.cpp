// SPDX-License-Identifier: BSD-3-Clause
// `morphreg warp`: a mesh warped from source to target landmarks by a thin plate spline, globally or by segments
// with blended seams, by moving least squares (--method mls), or re-postured with rigid bones (--method
// articulated); with --truth, the warp's error per vertex (colours of the output PLY) and in the report.
#include "commands.h"
#include "mesh_output.h"
#include "option_checks.h"
#include "provenance.h"

#include <morphreg/common/colour_map.h>
#include <morphreg/common/error.h>
#include <morphreg/common/length_unit.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/io/output_transaction.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/pipeline/mesh_warping.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iostream>
#include <sstream>

namespace morphreg
{
namespace tools
{
namespace
{
/** The files, settings and outputs of `morphreg warp`; the warp's settings are the library's. */
struct WarpOptions
{
  MeshWarpFiles files;
  std::string out = "warped.ply";
  std::string truth, report;
  std::string method = "tps";
  std::string units = "mm";
  MeshWarpingSettings settings;
  bool quiet = false;
};

/** The error against the truth: the mesh written with it as vertex colours and quality, a line on stdout; returns
 *  what the written mesh carries (meshContents). */
std::string
saveWithTruthErrors (const WarpOptions& options, const MeshWarpInput& input, MeshWarpOutcome& outcome)
{
  const TriangleMesh truth = readWarpTruth (options.truth, parseLengthUnit (options.units));
  evaluateWarpAgainst (input, truth, options.truth, options.settings, outcome);
  const Eigen::VectorXd& errors = *outcome.truth_error;
  const double colour_max = std::max (errors.maxCoeff (), 1e-9);
  savePolygonMesh (options.out, toPolygonMesh (outcome.warped, residualColours (errors, colour_max), errors));
  const nlohmann::json& error = outcome.report["error_mm"];
  if (!options.quiet)
    std::cout << "error against " << options.truth << ": mean " << error["mean"].get<double> () << " mm, max "
              << error["max"].get<double> () << " mm\n";
  std::ostringstream colours;
  colours << "error against the truth, 0-" << colour_max << " mm";
  return meshContents (options.out, colours.str (), "error against the truth in mm");
}

void
runWarp (const WarpOptions& options)
{
  OutputPlan plan;
  for (const auto& [input, role] :
       {std::pair (options.files.mesh, "--mesh"), std::pair (options.files.source, "--source"),
        std::pair (options.files.target, "--target"), std::pair (options.files.segments, "--labels"),
        std::pair (options.truth, "--truth"), std::pair (options.files.skeleton, "--skeleton")})
    plan.addInput (input, role);
  plan.addOutput (options.out, "--out");
  plan.addOptionalOutput (options.report, "--report");
  plan.check ();
  OutputTransaction outputs (plan.outputs ());
  const LengthUnit unit = parseLengthUnit (options.units);
  const MeshWarpInput input = readMeshWarpInput (options.files, unit);
  if (unit != LengthUnit::millimetre && !options.quiet)
    std::cout << "units: the inputs are in " << options.units << ", converted to mm (the output is in mm)\n";
  MeshWarpOutcome outcome = warpMesh (input, options.settings);
  outcome.report.update ({{"input_units", options.units}, {"mesh", options.files.mesh}, {"output", options.out}});
  std::string contents;
  if (options.truth.empty ())
    saveTriangleMesh (options.out, outcome.warped);
  else
    contents = ' ' + saveWithTruthErrors (options, input, outcome);
  if (!options.report.empty ())
    writeReport (options.report, outcome.report);
  outputs.commit ();
  std::cout << "wrote " << options.out << contents << '\n';
}

/** The articulated and moving least squares warps' settings, each in the range where its result means something. */
void
addArticulatedOptions (CLI::App* command, WarpOptions& options)
{
  command
      ->add_option ("--rigidity", options.settings.rigidity,
                    "articulated: weight of the as-rigid-as-possible refinement (0 to 1000; beyond, the bones no "
                    "longer follow the landmarks)")
      ->check (inRange (0.0, 1000.0))
      ->capture_default_str ();
  command
      ->add_option ("--skinning-width", options.settings.skinning_width,
                    "articulated: how fast a bone's weight falls along the mesh (mm, 0.1 to 10000)")
      ->check (inRange (0.1, 10000.0))
      ->capture_default_str ();
  command
      ->add_option ("--mls-falloff", options.settings.mls_falloff,
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
  command->add_option ("--mesh", options->files.mesh, "mesh to warp (.ply .obj .vtk .stl .off .gltf .glb)")
      ->required ();
  command->add_option ("--source", options->files.source, "source landmarks on the mesh (.pp .json .csv)")->required ();
  command->add_option ("-t,--target", options->files.target, "target landmarks, same names (.pp .json .csv)")
      ->required ();
  command
      ->add_option ("-o,--out", options->out,
                    meshOutputHelp ("warped mesh to write; with --truth", "error against the truth",
                                    "error against the truth in mm"))
      ->capture_default_str ();
  command->add_option ("--labels", options->files.segments,
                       "segment per vertex, JSON {\"regions\": [names], \"labels\": [...]}: segmented warp");
  command
      ->add_option ("--blend", options->settings.blend_width,
                    "how far each segment's warp reaches into its neighbours along the mesh (mm; one value, or one "
                    "per segment separated by commas; 0 = hard segments)")
      ->delimiter (',')
      ->check (nonNegative ())
      ->capture_default_str ();
  command
      ->add_option ("--overlap", options->settings.overlap,
                    "landmarks join a segment at most this much farther (mm; one value, or one per segment "
                    "separated by commas; inf = every landmark)")
      ->delimiter (',')
      ->check (nonNegativeOrInfinite ())
      ->capture_default_str ();
  command->add_option ("--lambda", options->settings.regularization, "TPS regularisation (0 = exact interpolation)")
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
  command->add_option ("--skeleton", options->files.skeleton,
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
  command->callback ([options] () {
    options->settings.method = parseWarpMethod (options->method);
    runWarp (*options);
  });
}

} // namespace tools
} // namespace morphreg

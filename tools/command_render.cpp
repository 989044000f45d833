// SPDX-License-Identifier: BSD-3-Clause
// `morphreg render`: a PNG screenshot of meshes, clouds and landmarks, rendered offscreen (needs X: xvfb-run -a). A
// mesh with a per-vertex "quality" (register's fitted meshes: the residual in mm) is coloured by it, with a colour bar.
#include "commands.h"
#include "option_checks.h"

#include <morphreg/common/error.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/io/output_transaction.h>
#include <morphreg/visualization/fit_layers.h>
#include <morphreg/visualization/registration_visualizer.h>

#include <iostream>
#include <map>
#include <memory>
#include <optional>

namespace morphreg
{
namespace tools
{
namespace
{
struct RenderOptions
{
  std::vector<std::string> meshes;
  std::vector<std::string> clouds;
  std::vector<std::string> landmarks;
  std::string out = "render.png";
  int width = 1280;
  int height = 960;
  std::string view = "front";
  double opacity = 1.0;
  double colour_max = 0.0;               ///< the residual colour scale's top (mm); 0: the 95th percentile
  std::vector<std::string> side_by_side; ///< two captions: the two meshes in a left and a right viewport
};

/** Direction from the subject towards the camera for a named view (+Z out of the face, +X the subject's left). */
Eigen::Vector3d
viewDirection (const std::string& view)
{
  static const std::map<std::string, Eigen::Vector3d> views = {{"front", Eigen::Vector3d::UnitZ ()},
                                                               {"back", -Eigen::Vector3d::UnitZ ()},
                                                               {"left", Eigen::Vector3d::UnitX ()},
                                                               {"right", -Eigen::Vector3d::UnitX ()},
                                                               {"oblique", Eigen::Vector3d (1.0, 0.3, 1.0)}};
  return views.at (view);
}

/** --side-by-side: a left and a right viewport sharing the camera, captioned; returns the viewport of each mesh. */
std::vector<int>
sideBySide (const RenderOptions& options, RegistrationVisualizer& viewer)
{
  int left = 0, right = 0;
  viewer.createBeforeAfterViewports (left, right, options.side_by_side[0], options.side_by_side[1]);
  return {left, right};
}

/** Adds the meshes (those with residuals coloured by them, with the colour bar); returns their ids. */
std::vector<std::string>
addMeshes (const RenderOptions& options, const std::vector<int>& viewports, RegistrationVisualizer& viewer)
{
  std::vector<std::string> ids;
  for (std::size_t i = 0; i < options.meshes.size (); ++i) {
    ids.push_back ("mesh_" + std::to_string (i));
    const FittedMeshFile file =
        addFittedMeshFile (viewer, options.meshes[i], options.colour_max, options.opacity, ids.back (), viewports[i]);
    if (!file.note.empty ())
      std::cerr << "morphreg: " << file.note << '\n';
  }
  return ids;
}

void
runRender (const RenderOptions& options)
{
  if (options.meshes.empty () && options.clouds.empty ())
    throw InvalidInputError ("render: nothing to show; give at least one --mesh or --cloud");
  if (!options.side_by_side.empty () &&
      (options.meshes.size () != 2 || !options.clouds.empty () || !options.landmarks.empty ()))
    throw InvalidInputError ("render --side-by-side shows two --mesh files, the first on the left, and nothing else (" +
                             std::to_string (options.meshes.size ()) + " meshes given)");
  OutputPlan plan;
  for (const std::string& mesh : options.meshes)
    plan.addInput (mesh, "--mesh");
  for (const std::string& cloud : options.clouds)
    plan.addInput (cloud, "--cloud");
  for (const std::string& landmarks : options.landmarks)
    plan.addInput (landmarks, "--landmarks");
  plan.addOutput (options.out, "--out");
  plan.check ();
  OutputTransaction outputs (plan.outputs ());
  RegistrationVisualizer viewer (RegistrationVisualizer::Display::Offscreen);
  std::vector<int> viewports (options.meshes.size (), 0);
  if (!options.side_by_side.empty ())
    viewports = sideBySide (options, viewer);
  const std::vector<std::string> meshes = addMeshes (options, viewports, viewer);
  for (std::size_t i = 0; i < options.clouds.size (); ++i)
    addScanFile (viewer, options.clouds[i], !meshes.empty (), options.width, options.height,
                 "cloud_" + std::to_string (i));
  viewer.setFramedShapes (meshes); // the head, not the shoulders a scan may hold
  for (std::size_t i = 0; i < options.landmarks.size (); ++i)
    viewer.addLandmarks (loadLandmarks (options.landmarks[i]),
                         i == 0 ? RegistrationVisualizer::LandmarkRole::Target
                                : RegistrationVisualizer::LandmarkRole::Source,
                         2.5, true, "landmarks_" + std::to_string (i) + "_");
  viewer.resetCamera (viewDirection (options.view));
  viewer.saveScreenshot (options.out, options.width, options.height);
  outputs.commit ();
  std::cout << "wrote " << options.out << " (" << options.width << "x" << options.height << ")\n";
}
} // namespace

void
registerRenderCommand (CLI::App& app)
{
  auto options = std::make_shared<RenderOptions> ();
  CLI::App* command =
      app.add_subcommand ("render", "write a PNG of meshes, clouds and landmarks (run under xvfb-run -a)");
  command
      ->add_option (
          "--mesh", options->meshes,
          "mesh file (.ply .obj .vtk .stl .off .gltf .glb; drawn with its vertex colours if it has any), repeatable")
      ->check (CLI::ExistingFile);
  command->add_option ("-c,--cloud", options->clouds, "point cloud file (.pcd .ply .obj .gltf .glb), repeatable")
      ->check (CLI::ExistingFile);
  command
      ->add_option ("-l,--landmarks", options->landmarks,
                    "landmark file (.pp .json .csv); the first is drawn as target, others as source")
      ->check (CLI::ExistingFile);
  command->add_option ("-o,--out", options->out, "PNG to write")->capture_default_str ();
  command->add_option ("--width", options->width, "image width (pixels)")
      ->check (inRange (16, 8192))
      ->capture_default_str ();
  command->add_option ("--height", options->height, "image height (pixels)")
      ->check (inRange (16, 8192))
      ->capture_default_str ();
  command->add_option ("--view", options->view, "camera: front, back, left, right, oblique")
      ->check (CLI::IsMember ({"front", "back", "left", "right", "oblique"}))
      ->capture_default_str ();
  command->add_option ("--opacity", options->opacity, "mesh opacity (meshes without residuals)")
      ->check (inRange (0.0, 1.0))
      ->capture_default_str ();
  command
      ->add_option ("--colour-max", options->colour_max,
                    "top of the residual colour bar (mm) for meshes with a per-vertex quality (register's fits); 0: "
                    "the 95th percentile")
      ->check (nonNegative ());
  command
      ->add_option ("--side-by-side", options->side_by_side,
                    "two captions: the two --mesh files side by side (left, right) under one camera")
      ->expected (2);
  command->callback ([options] () { runRender (*options); });
}

} // namespace tools
} // namespace morphreg

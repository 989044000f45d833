// SPDX-License-Identifier: BSD-3-Clause
// `morphreg view`: a PCLVisualizer window on a scan, a fit (coloured by its residuals, with a colour bar in mm), its
// landmarks and the fit's correspondences to the scan, each a layer its key shows or hides; --screenshot writes a PNG
// instead of opening the window (headless: xvfb-run -a).
#include "commands.h"

#include <morphreg/common/error.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/output_plan.h>
#include <morphreg/io/output_transaction.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/visualization/fit_layers.h>
#include <morphreg/visualization/layer_toggles.h>
#include <morphreg/visualization/registration_visualizer.h>

#include <pcl/visualization/pcl_visualizer.h>

#include <vtkRenderWindow.h>

#include <iostream>
#include <memory>
#include <optional>

namespace morphreg
{
namespace tools
{
namespace
{
struct ViewOptions
{
  std::string scan, fit;
  std::vector<std::string> landmarks;
  std::string screenshot; ///< empty: the window
  int width = 1280, height = 960;
  double colour_max = 0.0;
  int correspondences = 400; ///< the most lines drawn
  bool quiet = false;
};

/** Adds what the options name, each as a layer with its key; returns the layers. */
std::unique_ptr<LayerToggles>
addLayers (const ViewOptions& options, RegistrationVisualizer& viewer)
{
  auto layers = std::make_unique<LayerToggles> (viewer);
  pcl::PointCloud<pcl::PointXYZ>::Ptr scan;
  if (!options.scan.empty ()) {
    scan = addScanFile (viewer, options.scan, !options.fit.empty (), options.width, options.height, "scan");
    layers->addLayer ("scan", 't', {"scan"});
  }
  if (!options.fit.empty ()) {
    const FittedMeshFile fit = addFittedMeshFile (viewer, options.fit, options.colour_max, 1.0, "fit");
    if (!fit.note.empty ())
      std::cerr << "morphreg: " << fit.note << '\n';
    layers->addLayer (fit.residuals ? "fit and residuals" : "fit", 'm', {"fit"});
    viewer.setFramedShapes ({"fit"});
    if (scan && options.correspondences > 0) {
      addFitCorrespondences (viewer, *scan, fromPolygonMesh (fit.mesh, options.fit), fit.residuals,
                             static_cast<std::size_t> (options.correspondences));
      layers->addLayer ("correspondences", 'v', {"correspondences"});
    }
  }
  std::vector<std::string> landmark_ids;
  for (std::size_t i = 0; i < options.landmarks.size (); ++i) {
    const std::string prefix = "landmarks_" + std::to_string (i) + "_";
    const LandmarkPositions landmarks = loadLandmarks (options.landmarks[i]);
    viewer.addLandmarks (
        landmarks, i == 0 ? RegistrationVisualizer::LandmarkRole::Target : RegistrationVisualizer::LandmarkRole::Source,
        2.5, true, prefix);
    for (const auto& [id, position] : landmarks)
      landmark_ids.insert (landmark_ids.end (), {prefix + id, prefix + id + "_label"});
  }
  if (!landmark_ids.empty ())
    layers->addLayer ("landmarks", 'k', landmark_ids);
  return layers;
}

void
runView (const ViewOptions& options)
{
  if (options.scan.empty () && options.fit.empty ())
    throw InvalidInputError ("view: nothing to show; give --scan, --fit or both");
  OutputPlan plan;
  plan.addInput (options.scan, "--scan");
  plan.addInput (options.fit, "--fit");
  for (const std::string& landmarks : options.landmarks)
    plan.addInput (landmarks, "--landmarks");
  if (!options.screenshot.empty ())
    plan.addOutput (options.screenshot, "--screenshot");
  plan.check ();
  OutputTransaction outputs (plan.outputs ());
  const bool headless = !options.screenshot.empty ();
  RegistrationVisualizer viewer (
      headless ? RegistrationVisualizer::Display::Offscreen : RegistrationVisualizer::Display::Window, "morphreg view");
  const std::unique_ptr<LayerToggles> layers = addLayers (options, viewer);
  viewer.getVisualizer ().getRenderWindow ()->SetSize (options.width, options.height);
  viewer.resetCamera ();
  if (headless) {
    viewer.saveScreenshot (options.screenshot, options.width, options.height);
    outputs.commit ();
    std::cout << "wrote " << options.screenshot << " (" << options.width << "x" << options.height << ")\n";
    return;
  }
  layers->connectKeys ();
  if (!options.quiet)
    std::cout << "view: " << layers->legend () << "; mouse: rotate, shift: pan, wheel: zoom; q closes\n";
  viewer.spin ();
}
} // namespace

void
registerViewCommand (CLI::App& app)
{
  auto options = std::make_shared<ViewOptions> ();
  CLI::App* command = app.add_subcommand (
      "view", "a window on a scan, a fit, its residuals, landmarks and correspondences (keys toggle them)");
  command->add_option ("-s,--scan", options->scan, "scan: point cloud (.pcd .ply .obj); missing (NaN) points skipped")
      ->check (CLI::ExistingFile);
  command->add_option ("--fit", options->fit, "fitted mesh (register --out): coloured by its residuals if it has them")
      ->check (CLI::ExistingFile);
  command
      ->add_option ("-l,--landmarks", options->landmarks,
                    "landmark file (.pp .json .csv); the first is drawn as the scan's, others as the model's")
      ->check (CLI::ExistingFile);
  command
      ->add_option ("--correspondences", options->correspondences,
                    "the most fit-to-scan lines drawn (nearest scan point of each fitted vertex; 0: none)")
      ->check (CLI::NonNegativeNumber)
      ->capture_default_str ();
  command->add_option ("--colour-max", options->colour_max, "top of the residual colour bar (mm; 0: 95th percentile)")
      ->check (CLI::NonNegativeNumber);
  command->add_option ("--screenshot", options->screenshot, "write this PNG instead of opening a window (xvfb-run -a)");
  command->add_option ("--width", options->width, "window or screenshot width (pixels)")
      ->check (CLI::Range (16, 8192))
      ->capture_default_str ();
  command->add_option ("--height", options->height, "window or screenshot height (pixels)")
      ->check (CLI::Range (16, 8192))
      ->capture_default_str ();
  command->add_flag ("-q,--quiet", options->quiet, "no help line");
  command->footer ("Keys in the window: t the scan, m the fit and its colour bar, v the correspondences, k the "
                   "landmarks; PCLVisualizer's own keys as usual (h lists them).");
  command->callback ([options] () { runView (*options); });
}
} // namespace tools
} // namespace morphreg

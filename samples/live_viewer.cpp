// SPDX-License-Identifier: BSD-3-Clause
// Watch MorphableICP's align() converge: a RegistrationVisualizer plugged into the pcl::Registration visualisation
// callback shows the deformed model, the scan and the accepted correspondences after every iteration.
// The model and the scan come from the built-in synthetic population (a head not in the model, laser-scanned).
//
//   sample_live_viewer                                 a window; close it after the fit to exit
//   xvfb-run -a sample_live_viewer --frames DIR        headless: DIR/frame_000.png, ... one PNG per iteration
//   options: --iterations 30  --width 800  --height 600
#include "sample_heads.h"
#include "sample_options.h"

#include <morphreg/registration/morphable_icp.h>
#include <morphreg/visualization/registration_visualizer.h>

#include <cstdio>
#include <filesystem>

using Cloud = pcl::PointCloud<pcl::PointNormal>;
using Icp = morphreg::MorphableICP<pcl::PointNormal>;
using morphreg::RegistrationVisualizer;

namespace
{
const char* const kUsage = "usage: sample_live_viewer [--frames DIR] [--iterations N] [--width W] [--height H]\n"
                           "  --frames DIR: render offscreen (under xvfb-run -a), one PNG per iteration\n";

void
liveViewer (int argc, char** argv)
{
  const samples::Options options (argc, argv,
                                  {{"--frames", ""}, {"--iterations", "30"}, {"--width", "800"}, {"--height", "600"}});
  const std::string frames = options.text ("--frames");
  const int width = options.integer ("--width", 16), height = options.integer ("--height", 16);
  const int iterations = options.integer ("--iterations", 1);
  if (!frames.empty ())
    std::filesystem::create_directories (frames);

  RegistrationVisualizer viewer (frames.empty () ? RegistrationVisualizer::Display::Window
                                                 : RegistrationVisualizer::Display::Offscreen,
                                 "morphreg: align() live");

  // A coarse scan (about 28k points) keeps the redraws quick.
  const morphreg::synthetic::HeadGenerator generator;
  morphreg::synthetic::ScanSimulator::Parameters scanner;
  scanner.angular_samples = 250;
  scanner.row_spacing = 2.5;
  const samples::UnseenScan unseen = samples::scanUnseenHead (generator, 30, scanner);
  Icp icp;
  icp.setModel (samples::buildHeadModel (generator, 30, 10));
  icp.setInputTarget (unseen.scan.cloud);
  icp.setPointToPlane (true);
  icp.setMaximumIterations (iterations);

  auto show = viewer.makeRegistrationCallback<pcl::PointNormal, pcl::PointNormal> (0, 200);
  int written = 0;
  std::function<Icp::UpdateVisualizerCallbackSignature> callback =
      [&] (const Cloud& model, const pcl::Indices& model_indices, const Cloud& scan, const pcl::Indices& scan_indices) {
        show (model, model_indices, scan, scan_indices);
        if (viewer.getRegistrationUpdateCount () == 1)
          viewer.resetCamera (); // the first call (at registration) shows the start: frame everything once
        if (frames.empty () || model_indices.empty ())
          return; // in a window the visualiser has redrawn already; no PNG for the call at registration
        char name[32];
        std::snprintf (name, sizeof (name), "/frame_%03d.png", written++);
        viewer.saveScreenshot (frames + name, width, height);
      };
  icp.registerVisualizationCallback (callback);
  Cloud fitted;
  icp.align (fitted);

  const morphreg::IcpReport& report = icp.getRegistrationReport ();
  const double rms = std::sqrt ((icp.getFittedVertices () - unseen.truth).colwise ().squaredNorm ().mean ());
  std::printf ("scan of %zu points: %zu iterations (%s), fitness RMS %.3f mm, error against the true head RMS "
               "%.3f mm\n",
               unseen.scan.cloud->size (), report.history.size (), morphreg::toString (report.termination).c_str (),
               report.fitness_rms, rms);
  if (!frames.empty ()) {
    std::printf ("wrote %d frames (%dx%d) to %s\n", written, width, height, frames.c_str ());
    return;
  }
  std::printf ("close the window to exit\n");
  viewer.spin ();
}
} // namespace

int
main (int argc, char** argv)
{
  return samples::run (argc, argv, kUsage, liveViewer);
}

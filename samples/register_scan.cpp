// SPDX-License-Identifier: BSD-3-Clause
// Registers a scan to a morphable head model with MorphableICP (a pcl::Registration) behind a chain of PCL
// correspondence rejectors, writes the fitted mesh as PLY coloured by residual (viridis, 0 to --scale mm) and
// prints the registration report.
//
//   sample_register_scan [--scan scan.pcd|scan.ply --model model.h5] [--out fitted.ply] [--iterations 40]
//                        [--scale 3] [--no-rejectors] [--heads 30]
//
// Without --scan and --model it builds a small model from --heads heads of the built-in synthetic population,
// simulates a laser scan of a head that is not among them, and also prints the fit's error against that head's true
// shape.
#include "sample_heads.h"
#include "sample_options.h"

#include <morphreg/common/cloud_checks.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/model_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/common/colour_map.h>

#include <pcl/registration/correspondence_rejection_median_distance.h>
#include <pcl/registration/correspondence_rejection_one_to_one.h>

#include <cmath>
#include <cstdio>
#include <optional>

using Cloud = pcl::PointCloud<pcl::PointNormal>;

namespace
{
const char* const kUsage =
    "usage: sample_register_scan [--scan SCAN.pcd|.ply --model MODEL.h5] [--out fitted.ply] [--iterations N]\n"
    "                            [--scale MM] [--no-rejectors] [--heads N]\n"
    "  without --scan and --model: a model of N synthetic heads (default 30) and a scan of a head not among them\n";

void
registerScan (int argc, char** argv)
{
  const samples::Options options (argc, argv,
                                  {{"--scan", ""},
                                   {"--model", ""},
                                   {"--out", "fitted.ply"},
                                   {"--iterations", "40"},
                                   {"--scale", "3"},
                                   {"--heads", "30"}},
                                  {"--no-rejectors"});
  if (options.text ("--scan").empty () != options.text ("--model").empty ())
    throw samples::UsageError ("--scan and --model go together");
  const int iterations = options.integer ("--iterations", 1);
  const int heads = options.integer ("--heads", 2);
  const double scale = options.number ("--scale");
  if (!(scale > 0.0))
    throw samples::UsageError ("--scale must be positive");

  morphreg::MorphableModel::ConstPtr model;
  Cloud::Ptr scan;
  std::optional<samples::UnseenScan> unseen; // the ground truth, when the scan is simulated
  if (options.text ("--scan").empty ()) {
    const morphreg::synthetic::HeadGenerator generator;
    model = samples::buildHeadModel (generator, heads, 10);
    unseen = samples::scanUnseenHead (generator, heads);
    scan = unseen->scan.cloud;
  }
  else {
    model = morphreg::loadModel (options.text ("--model"));
    scan = morphreg::loadCloud<pcl::PointNormal> (options.text ("--scan"));
    morphreg::requireFiniteNonEmpty (*scan, options.text ("--scan"));
  }
  std::printf ("model: %ld vertices, %d regions; scan: %zu points\n", static_cast<long> (model->numVertices ()),
               model->numRegions (), scan->size ());

  morphreg::MorphableICP<pcl::PointNormal> icp;
  icp.setModel (model);
  icp.setInputTarget (scan);
  icp.setPointToPlane (true);
  icp.setMaximumIterations (iterations);
  // The rejector chain runs in this order every iteration, as in pcl::IterativeClosestPoint.
  auto median = std::make_shared<pcl::registration::CorrespondenceRejectorMedianDistance> ();
  median->setMedianFactor (3.0); // drop pairs more than 3x the median distance apart (outliers, unmodelled parts)
  auto one_to_one = std::make_shared<pcl::registration::CorrespondenceRejectorOneToOne> (); // one vertex per point
  if (!options.flag ("--no-rejectors")) {
    icp.addCorrespondenceRejector (icp.getTargetBoundaryRejector ()); // the default chain, which a chain replaces
    icp.addCorrespondenceRejector (median);
    icp.addCorrespondenceRejector (one_to_one);
  }
  Cloud fitted;
  icp.align (fitted);

  const morphreg::IcpReport& report = icp.getRegistrationReport ();
  const Eigen::Matrix4d transform = icp.getFinalTransformation ().cast<double> ();
  std::printf ("termination: %s after %d similarity + %d shape iterations\n",
               morphreg::toString (report.termination).c_str (), report.similarity_iterations, report.shape_iterations);
  std::printf ("scale %.4f, %d correspondences kept of %d found in the last iteration\n",
               std::cbrt (transform.topLeftCorner<3, 3> ().determinant ()), report.history.back ().kept,
               report.history.back ().correspondences);
  std::printf ("fitness: mean %.3f mm, median %.3f mm, RMS %.3f mm over %d correspondences\n", report.fitness_mean,
               report.fitness_median, report.fitness_rms, report.correspondences);
  if (unseen) {
    const Eigen::VectorXd error = (icp.getFittedVertices () - unseen->truth).colwise ().norm ().transpose ();
    const Eigen::ArrayXd seen = icp.getVertexResiduals ().array ().isFinite ().cast<double> ();
    std::printf ("error against the true head: RMS %.3f mm (max %.3f mm) over all vertices, RMS %.3f mm over the "
                 "%d the scan saw\n",
                 std::sqrt (error.squaredNorm () / error.size ()), error.maxCoeff (),
                 std::sqrt ((error.array ().square () * seen).sum () / seen.sum ()), static_cast<int> (seen.sum ()));
  }

  const morphreg::TriangleMesh mesh{icp.getFittedVertices (), model->triangles ()};
  const morphreg::VertexColours colours = morphreg::residualColours (icp.getVertexResiduals (), scale);
  morphreg::savePolygonMesh (options.text ("--out"), morphreg::toPolygonMesh (mesh, colours));
  std::printf ("wrote %s (vertex colours: residual 0-%g mm, grey = no correspondence)\n",
               options.text ("--out").c_str (), scale);
}
} // namespace

int
main (int argc, char** argv)
{
  return samples::run (argc, argv, kUsage, registerScan);
}

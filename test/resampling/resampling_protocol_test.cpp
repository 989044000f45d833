// SPDX-License-Identifier: BSD-3-Clause
// The raw-scan protocol: simulated laser scans (sigma 0.2 mm, the scanner's holes, point clouds) of unseen heads
// (seeds 1001-1020) registered with a model of a disjoint population (seeds 1-200), then resampled into the model's
// topology; the resampled vertices are measured against the true head surface, and a model built from the resampled
// scans is compared by the standard quality measures with one built from the same heads' true meshes.
#include <morphreg/mesh/triangle_locator.h>
#include <morphreg/model/model_builder.h>
#include <morphreg/model/model_quality.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/registration/registration_settings.h>
#include <morphreg/resampling/scan_resampler.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/scan_simulator.h>

#include "support/sample_count.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace
{
constexpr int kHeads = 20;
constexpr std::uint64_t kFirstUnseen = 1001;

/** RMS distance (mm) from the resampled vertices in \a state (those above \a floor in the head's frame, +Y up, when
 *  given) to \a truth's surface. */
double
rmsToSurface (const morphreg::ResamplingResult& result, morphreg::ResampledVertex state,
              const morphreg::TriangleLocator& truth,
              const Eigen::Affine3d& scan_to_head = Eigen::Affine3d::Identity (),
              double floor = -std::numeric_limits<double>::infinity ())
{
  double sum = 0.0;
  int count = 0;
  for (Eigen::Index v = 0; v < result.mesh.numVertices (); ++v)
    if (result.state[v] == state && (scan_to_head * Eigen::Vector3d (result.mesh.vertices.col (v))).y () > floor) {
      sum += std::pow (truth.closestPoint (result.mesh.vertices.col (v)).distance, 2);
      ++count;
    }
  return count ? std::sqrt (sum / count) : 0.0;
}

/** The height (+Y, head frame) of the scan's lowest surface point: the neck's cut as the scanner saw it. */
double
lowestScanRow (const morphreg::synthetic::SimulatedScan& scan)
{
  const Eigen::Affine3d scan_to_head = scan.head_to_scan.inverse ();
  double lowest = std::numeric_limits<double>::infinity ();
  for (std::size_t i = 0; i < scan.source_triangle.size (); ++i)
    if (scan.source_triangle[i] >= 0)
      lowest =
          std::min (lowest, (scan_to_head * Eigen::Vector3d ((*scan.cloud)[i].getVector3fMap ().cast<double> ())).y ());
  return lowest;
}

double
median (std::vector<double> values)
{
  std::nth_element (values.begin (), values.begin () + values.size () / 2, values.end ());
  return values[values.size () / 2];
}

/** The model fit to \a scan as `build-model --from-scans` makes it: register's settings, up to 60 components per
 *  region refined at the shape prior 0.2. */
morphreg::TriangleMesh
registerScan (const morphreg::MorphableModel::Ptr& model, const pcl::PointCloud<pcl::PointNormal>::Ptr& scan)
{
  morphreg::RegistrationSettings settings;
  settings.components = {60};
  settings.refinement_prior = 0.2;
  morphreg::MorphableICP<pcl::PointNormal> icp;
  morphreg::configureRegistration (icp, settings, model);
  icp.setInputTarget (scan);
  pcl::PointCloud<pcl::PointNormal> aligned;
  icp.align (aligned);
  return morphreg::TriangleMesh{icp.getFittedVertices (), model->triangles ()};
}

/** The registering model: up to 60 components per region from the heads of seeds 1-200. */
morphreg::MorphableModel::Ptr
registeringModel (const morphreg::synthetic::HeadGenerator& generator)
{
  std::vector<morphreg::TriangleMesh> training;
  for (auto& head : generator.population (200, 1))
    training.push_back (std::move (head.mesh));
  morphreg::ModelBuilderSettings settings;
  settings.max_components = 60;
  return morphreg::ModelBuilder (settings).build (training, generator.regions ());
}

TEST (ResamplingProtocolTest, UnseenHeadsResampledFromTheirLaserScans)
{
  const morphreg::synthetic::HeadGenerator generator;
  const morphreg::MorphableModel::Ptr model = registeringModel (generator);

  std::vector<double> observed_rms, filled_rms, filled_above_cut_rms, fit_rms, coverage; // fit_rms: over the filled
  int folded = 0;
  for (int head = 0; head < morphreg::test::sampleCount (kHeads); ++head) {
    const morphreg::TriangleMesh truth_head = generator.sample (kFirstUnseen + head).mesh;
    const auto scan = morphreg::synthetic::ScanSimulator ().scan (truth_head, kFirstUnseen + head);
    morphreg::TriangleMesh truth = truth_head;
    truth.vertices = scan.head_to_scan * truth_head.vertices;
    const morphreg::TriangleLocator truth_surface (truth);
    const morphreg::TriangleMesh fitted = registerScan (model, scan.cloud);

    morphreg::ScanResampler resampler;
    resampler.setInputReference (fitted);
    resampler.setInputScan (*scan.cloud);
    const morphreg::ResamplingResult result = resampler.resample ();
    morphreg::ResamplingResult model_only = result; // the fit's own vertices, in the same states
    model_only.mesh = fitted;
    fit_rms.push_back (rmsToSurface (model_only, morphreg::ResampledVertex::filled, truth_surface));
    observed_rms.push_back (rmsToSurface (result, morphreg::ResampledVertex::observed, truth_surface));
    filled_rms.push_back (rmsToSurface (result, morphreg::ResampledVertex::filled, truth_surface));
    filled_above_cut_rms.push_back (rmsToSurface (result, morphreg::ResampledVertex::filled, truth_surface,
                                                  scan.head_to_scan.inverse (), lowestScanRow (scan) + 2.0));
    coverage.push_back (result.statistics.coverage);
    folded += result.statistics.folded_triangles;
    std::printf ("[ protocol ] head %d: model fit RMS over the filled vertices %.3f mm; resampled: coverage %.3f, %zu "
                 "holes, observed RMS %.3f mm, "
                 "filled RMS %.3f mm (%.3f mm above the neck's cut), folded %d, rays %.3f s, fill %.3f s\n",
                 head, fit_rms.back (), coverage.back (), result.statistics.holes.size (), observed_rms.back (),
                 filled_rms.back (), filled_above_cut_rms.back (), result.statistics.folded_triangles,
                 result.statistics.ray_seconds, result.statistics.fill_seconds);
  }
  const double observed = median (observed_rms), filled = median (filled_rms);
  const double filled_above_cut = median (filled_above_cut_rms), fit = median (fit_rms);
  std::printf (
      "[ protocol ] %d heads: median observed RMS %.3f mm (max %.3f), median filled RMS %.3f mm (max %.3f; "
      "model fit on the same vertices %.3f mm), %.3f mm above the neck's cut (max %.3f), median coverage "
      "%.3f, folded triangles %d\n",
      morphreg::test::sampleCount (kHeads), observed, *std::max_element (observed_rms.begin (), observed_rms.end ()),
      filled, *std::max_element (filled_rms.begin (), filled_rms.end ()), fit, filled_above_cut,
      *std::max_element (filled_above_cut_rms.begin (), filled_above_cut_rms.end ()), median (coverage), folded);
  // Required: observed <= 0.25 mm, filled <= 1.5 mm (medians over the heads). Most of the fills' error is the neck's
  // length: below the scan's lowest row the true head ends in a flat cap no scan sees, and the fit's neck ends up to
  // 15 mm below it; above that row the fills lie within a few tenths of a millimetre. Measured: observed 0.097 mm
  // (max 0.107), filled 0.724 mm (max 4.7), 0.085 mm above the cut, coverage 0.940, no folds.
  EXPECT_LE (observed, 0.25);
  EXPECT_LE (filled, 1.5);
  EXPECT_LE (filled_above_cut, 0.5);
  EXPECT_LE (filled, 1.05 * fit) << "the fills are no worse than the model fit on the same vertices";
  EXPECT_EQ (folded, 0);
}

// The protocol of models from raw scans at a fifth of its size, to stay near a minute and a half: 20 scanned heads
// (seeds 1001-1020) instead of 100, generalisation on 20 further true heads (seeds 1101-1120) at 10 components
// instead of 20 (a model of 20 meshes has 19), specificity from 1000 samples (seed 1) at 10 components; each
// against the model built from the same heads' true meshes. The scanner keeps its random pose but not its random
// scale (up to 5 %): a scan scaled by the scanner is another head's size, which no registration can undo, and a
// model of such scans holds the scale as a component of its own. Measured: generalisation 0.661 mm against 0.648 mm
// (+2 %), specificity 2.041 mm against 2.086 mm (-2 %). With the scanner's scale, and register's fit (10 components
// per region at the prior 3), they were 0.746 against 0.648 mm (+15 %) and 2.282 against 2.086 mm (+9.4 %).
TEST (ResamplingProtocolTest, ModelFromRawScansMatchesModelFromTrueMeshes)
{
  constexpr int kComponents = 10;
  const morphreg::synthetic::HeadGenerator generator;
  const morphreg::MorphableModel::Ptr model = registeringModel (generator);
  morphreg::synthetic::ScanSimulator::Parameters true_size;
  true_size.max_scale_deviation = 0.0;
  const morphreg::synthetic::ScanSimulator scanner (true_size);
  std::vector<morphreg::TriangleMesh> true_meshes, resampled, held_out;
  for (int head = 0; head < kHeads; ++head) {
    true_meshes.push_back (generator.sample (kFirstUnseen + head).mesh);
    const auto scan = scanner.scan (true_meshes.back (), kFirstUnseen + head);
    morphreg::ScanResampler resampler;
    resampler.setInputReference (registerScan (model, scan.cloud));
    resampler.setInputScan (*scan.cloud);
    resampled.push_back (resampler.resample ().mesh);
    held_out.push_back (generator.sample (kFirstUnseen + 100 + head).mesh);
  }
  const auto from_scans = morphreg::ModelBuilder ().buildGlobal (resampled);
  const auto from_truth = morphreg::ModelBuilder ().buildGlobal (true_meshes);
  const double generalisation_scans = morphreg::generalisation (*from_scans, held_out, kComponents).mean;
  const double generalisation_truth = morphreg::generalisation (*from_truth, held_out, kComponents).mean;
  const double specificity_scans = morphreg::specificity (*from_scans, resampled, kComponents, 1000, 1).mean;
  const double specificity_truth = morphreg::specificity (*from_truth, true_meshes, kComponents, 1000, 1).mean;
  std::printf ("[ protocol ] model of %d heads at %d components: generalisation %.3f mm from raw scans, %.3f mm from "
               "true meshes; specificity %.3f mm from raw scans, %.3f mm from true meshes\n",
               kHeads, kComponents, generalisation_scans, generalisation_truth, specificity_scans, specificity_truth);
  EXPECT_NEAR (generalisation_scans, generalisation_truth, 0.1 * generalisation_truth);
  EXPECT_NEAR (specificity_scans, specificity_truth, 0.1 * specificity_truth);
}
} // namespace

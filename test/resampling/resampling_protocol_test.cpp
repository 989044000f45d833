// SPDX-License-Identifier: BSD-3-Clause
// The raw-scan protocol: simulated laser scans (sigma 0.2 mm, the scanner's holes, point clouds) of unseen heads
// (seeds 1001-1020) registered with a model of a disjoint population (seeds 1-200), then resampled into the model's
// topology; the resampled vertices are measured against the true head surface, and a model built from the resampled
// scans is compared by the standard quality measures with one built from the same heads' true meshes.
#include <morphreg/common/order_statistics.h>
#include <morphreg/mesh/triangle_locator.h>
#include <morphreg/model/model_builder.h>
#include <morphreg/model/model_quality.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/registration/registration_settings.h>
#include <morphreg/resampling/scan_resampler.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/scan_simulator.h>

#include "resampled_distance.h"
#include "support/accuracy_bound.h"
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

/** One head's figures: RMS distances (mm) to the true surface and the observed share, of the resampled vertices, of
 *  the fit's own vertices in the same states (the reference returned as it is) and of the no-op resampler that
 *  observes nothing and fills everything; and the resampler's fold count. */
struct HeadFigures
{
  double observed, filled, filled_above_cut, coverage; ///< the resampled vertices
  double fit_observed, fit_filled;                     ///< the fit's vertices where the resampler observed and filled
  double nothing_observed, nothing_coverage;           ///< the no-op's
  int folded;
};

/** Scans the unseen head \a head, registers \a model to the scan and resamples it; scores it against the truth. */
HeadFigures
resampleUnseenHead (const morphreg::synthetic::HeadGenerator& generator, const morphreg::MorphableModel::Ptr& model,
                    int head)
{
  using morphreg::ResampledVertex;
  using morphreg::test::rmsToSurface;
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
  EXPECT_DOUBLE_EQ (result.statistics.coverage, morphreg::test::observedShare (result)) << "head " << head;
  const morphreg::ResamplingResult unmoved = morphreg::test::referenceInPlace (result, fitted);
  const morphreg::ResamplingResult nothing = morphreg::test::nothingObserved (result, fitted);
  const Eigen::Affine3d scan_to_head = scan.head_to_scan.inverse ();
  const double cut = lowestScanRow (scan) + 2.0;
  const auto above_cut = [&] (Eigen::Index v) {
    return (scan_to_head * Eigen::Vector3d (result.mesh.vertices.col (v))).y () > cut;
  };
  const HeadFigures figures{rmsToSurface (result, ResampledVertex::observed, truth_surface),
                            rmsToSurface (result, ResampledVertex::filled, truth_surface),
                            rmsToSurface (result, ResampledVertex::filled, truth_surface, above_cut),
                            morphreg::test::observedShare (result),
                            rmsToSurface (unmoved, ResampledVertex::observed, truth_surface),
                            rmsToSurface (unmoved, ResampledVertex::filled, truth_surface),
                            rmsToSurface (nothing, ResampledVertex::observed, truth_surface),
                            morphreg::test::observedShare (nothing),
                            result.statistics.folded_triangles};
  std::printf ("[ protocol ] head %d: model fit RMS over the observed vertices %.3f mm, over the filled %.3f mm; "
               "resampled: coverage %.3f, %zu holes, observed RMS %.3f mm, filled RMS %.3f mm (%.3f mm above the "
               "neck's cut), folded %d, rays %.3f s, fill %.3f s\n",
               head, figures.fit_observed, figures.fit_filled, figures.coverage, result.statistics.holes.size (),
               figures.observed, figures.filled, figures.filled_above_cut, figures.folded,
               result.statistics.ray_seconds, result.statistics.fill_seconds);
  return figures;
}

/** The median over \a heads of one figure. */
double
medianOf (const std::vector<HeadFigures>& heads, double HeadFigures::*figure)
{
  std::vector<double> values;
  for (const HeadFigures& head : heads)
    values.push_back (head.*figure);
  return morphreg::median (values);
}

/** The largest (or, with \a smallest, the smallest) over \a heads of one figure. */
double
extremeOf (const std::vector<HeadFigures>& heads, double HeadFigures::*figure, bool smallest = false)
{
  double extreme = heads.front ().*figure;
  for (const HeadFigures& head : heads)
    extreme = smallest ? std::min (extreme, head.*figure) : std::max (extreme, head.*figure);
  return extreme;
}

// Required: the observed vertices beat the scan's range noise (sigma 0.2 mm), the fills stay within a fraction of a
// millimetre above the neck's cut; coverage as measured. Most of the fills' error is the neck's length: below the
// scan's lowest row the true head ends in a flat cap no scan sees, and the fit's neck ends up to 15 mm below it;
// above that row the fills lie within a tenth of a millimetre on most heads (up to 4.1 mm on the three heads whose
// fit is worst: there the fills are the fit, carried to the holes' borders). Measured over 20 heads: observed RMS
// median 0.098 mm (max 0.109), filled 2.57 mm (the fit on the same vertices 2.41 mm: 1.07x), 0.089 mm above the
// cut, coverage median 0.939 (min 0.927), no folds. The filled figure is the neck below the scan: with register's
// defaults since issue 31 (every component, landmarks placing the start only, the normal-compatibility rejector)
// the fits leave it up to 10 mm off on some heads (it was 0.72 mm before); the registration, not the resampler,
// owns that. These heads are of the registering model's own kind, and its fit (60 components per region at the
// prior 0.2) lies closer to them where they are observed than the scan itself: returned as it is, the fit scores a
// median 0.034 mm there, while the resampler keeps the scan's own surface, so neither RMS bound tells the resampler
// from the fit it starts from (the real scan does: RealScanResamplingTest); this protocol's no-op is the resampler
// that observes nothing, which its coverage and observed figure fail.
TEST (ResamplingProtocolTest, UnseenHeadsResampledFromTheirLaserScans)
{
  const morphreg::synthetic::HeadGenerator generator;
  const morphreg::MorphableModel::Ptr model = registeringModel (generator);
  std::vector<HeadFigures> heads;
  int folded = 0;
  for (int head = 0; head < morphreg::test::sampleCount (kHeads); ++head) {
    heads.push_back (resampleUnseenHead (generator, model, head));
    folded += heads.back ().folded;
  }
  const double observed = medianOf (heads, &HeadFigures::observed), filled = medianOf (heads, &HeadFigures::filled);
  const double filled_above_cut = medianOf (heads, &HeadFigures::filled_above_cut);
  const double fit_filled = medianOf (heads, &HeadFigures::fit_filled);
  const double coverage = medianOf (heads, &HeadFigures::coverage);
  std::printf (
      "[ protocol ] %zu heads: median observed RMS %.3f mm (max %.3f), median filled RMS %.3f mm (model fit on "
      "the same vertices %.3f mm), %.3f mm above the neck's cut, median coverage %.3f (min %.3f), folded "
      "triangles %d; the fit returned as it is: %.3f mm at the observed vertices\n",
      heads.size (), observed, extremeOf (heads, &HeadFigures::observed), filled, fit_filled, filled_above_cut,
      coverage, extremeOf (heads, &HeadFigures::coverage, true), folded, medianOf (heads, &HeadFigures::fit_observed));
  constexpr double kObservedBound = 0.115;
  EXPECT_LT (kObservedBound, morphreg::synthetic::ScanSimulator::Parameters ().noise_sigma);
  using morphreg::test::suiteMedianLowerBound;
  using morphreg::test::suiteMedianUpperBound;
  EXPECT_PRED_FORMAT2 (suiteMedianUpperBound, observed, kObservedBound) << "median observed RMS";
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, extremeOf (heads, &HeadFigures::observed), 0.125)
      << "largest observed RMS";
  EXPECT_PRED_FORMAT2 (suiteMedianUpperBound, filled, 3.2) << "median filled RMS";
  EXPECT_PRED_FORMAT2 (suiteMedianUpperBound, filled_above_cut, 0.1) << "median filled RMS above the cut";
  EXPECT_PRED_FORMAT2 (suiteMedianLowerBound, coverage, 0.93) << "median coverage";
  EXPECT_PRED_FORMAT2 (morphreg::test::tightLowerBound, extremeOf (heads, &HeadFigures::coverage, true), 0.915)
      << "smallest coverage";
  EXPECT_LE (filled, 1.1 * fit_filled) << "the fills are within 10 % of the model fit on the same vertices";
  EXPECT_EQ (folded, 0);
  // The no-op resampler, which observes nothing and fills everything, has no observed figure (NaN meets no bound) and
  // no coverage.
  for (const HeadFigures& head : heads) {
    EXPECT_FALSE (head.nothing_observed <= kObservedBound) << head.nothing_observed;
    EXPECT_LT (head.nothing_coverage, 0.915);
  }
}

// The protocol of models from raw scans at a fifth of its size, to stay near a minute and a half: 20 scanned heads
// (seeds 1001-1020) instead of 100, generalisation on 20 further true heads (seeds 1101-1120) at 10 components
// instead of 20 (a model of 20 meshes has 19), specificity from 1000 samples (seed 1) at 10 components; each
// against the model built from the same heads' true meshes. The scanner keeps its random pose but not its random
// scale (up to 5 %): a scan scaled by the scanner is another head's size, which no registration can undo, and a
// model of such scans holds the scale as a component of its own. Measured: generalisation 0.669 mm against 0.648 mm
// (+3 %), specificity 2.023 mm against 2.086 mm (-3 %); the mean head (no component) generalises to 3.573 mm. With
// the scanner's scale, and register's fit (10 components per region at the prior 3), they were 0.746 against
// 0.648 mm (+15 %) and 2.282 against 2.086 mm (+9.4 %).
TEST (ResamplingProtocolTest, ModelFromRawScansMatchesModelFromTrueMeshes)
{
  // A capped run (MORPHREG_TEST_SAMPLES) scans fewer heads; a model of n heads has at most n - 1 components.
  const int heads = std::max (2, morphreg::test::sampleCount (kHeads));
  const int components = std::min (10, heads - 1);
  const morphreg::synthetic::HeadGenerator generator;
  const morphreg::MorphableModel::Ptr model = registeringModel (generator);
  morphreg::synthetic::ScanSimulator::Parameters true_size;
  true_size.max_scale_deviation = 0.0;
  const morphreg::synthetic::ScanSimulator scanner (true_size);
  std::vector<morphreg::TriangleMesh> true_meshes, resampled, held_out;
  for (int head = 0; head < heads; ++head) {
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
  const double generalisation_scans = morphreg::generalisation (*from_scans, held_out, components).mean;
  const double generalisation_truth = morphreg::generalisation (*from_truth, held_out, components).mean;
  const double specificity_scans = morphreg::specificity (*from_scans, resampled, components, 1000, 1).mean;
  const double specificity_truth = morphreg::specificity (*from_truth, true_meshes, components, 1000, 1).mean;
  std::printf ("[ protocol ] model of %d heads at %d components: generalisation %.3f mm from raw scans, %.3f mm from "
               "true meshes; specificity %.3f mm from raw scans, %.3f mm from true meshes\n",
               heads, components, generalisation_scans, generalisation_truth, specificity_scans, specificity_truth);
  using morphreg::test::suiteMedianUpperBound;
  EXPECT_PRED_FORMAT2 (suiteMedianUpperBound, generalisation_scans, 0.75);
  EXPECT_PRED_FORMAT2 (suiteMedianUpperBound, specificity_scans, 2.3);
  // Against the model of the true meshes (differences of a few per cent either way, too near zero for a ratio):
  using morphreg::test::suiteFigureNear;
  EXPECT_PRED_FORMAT3 (suiteFigureNear, generalisation_scans, generalisation_truth, 0.05 * generalisation_truth);
  EXPECT_PRED_FORMAT3 (suiteFigureNear, specificity_scans, specificity_truth, 0.05 * specificity_truth);
  // The no-op: the model of the scans without its components (its mean head).
  const double generalisation_mean = morphreg::generalisation (*from_scans, held_out, 0).mean;
  std::printf ("[ protocol ] the mean head of the model from raw scans: generalisation %.3f mm\n", generalisation_mean);
  EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, generalisation_mean, 0.75);
}
} // namespace

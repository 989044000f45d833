// SPDX-License-Identifier: BSD-3-Clause
// The real head-and-shoulders scan (82k points) resampled into the ICT topology: the ICT model (30 components per
// region) fitted with `morphreg resample --components 30`'s registration (register's defaults), then ScanResampler; the face's coverage and the observed face
// vertices' distance to the scan's own mesh, against the model-only fit's.
#include "real_scan_support.h"
#include "support/accuracy_bound.h"

#include <morphreg/common/order_statistics.h>
#include <morphreg/mesh/triangle_locator.h>
#include <morphreg/registration/registration_settings.h>
#include <morphreg/resampling/scan_resampler.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace
{
using namespace morphreg::test;

constexpr int kFaceVertices = 9409; ///< ICT's face: vertex ids below this

TEST (RealScanResamplingTest, Cloud82kIntoTheIctTopology)
{
  MORPHREG_REQUIRE_REAL_SCANS ();
  const auto scan = leeScan82k ();
  morphreg::MorphableICP<pcl::PointNormal> icp;
  morphreg::RegistrationSettings settings;
  settings.components = {30};
  configureRegistration (icp, settings, std::make_shared<morphreg::MorphableModel> (*ictModel30 ()));
  icp.setInputTarget (scan);
  pcl::PointCloud<pcl::PointNormal> aligned;
  icp.align (aligned);
  const morphreg::TriangleMesh fitted{icp.getFittedVertices (), ictModel30 ()->triangles ()};

  morphreg::ScanResampler resampler;
  resampler.setInputReference (fitted);
  resampler.setInputScan (*scan);
  const morphreg::ResamplingResult result = resampler.resample ();
  ASSERT_TRUE (result.mesh.vertices.allFinite ());

  const morphreg::TriangleLocator truth (leeHeadMesh ());
  std::vector<double> resampled, model_only; // the observed face vertices, resampled and as the fit left them
  for (int v = 0; v < kFaceVertices; ++v)
    if (result.state[v] == morphreg::ResampledVertex::observed) {
      resampled.push_back (truth.closestPoint (result.mesh.vertices.col (v)).distance);
      model_only.push_back (truth.closestPoint (fitted.vertices.col (v)).distance);
    }
  ASSERT_FALSE (resampled.empty ());
  const double face_coverage = static_cast<double> (resampled.size ()) / kFaceVertices;
  const double median = morphreg::median (resampled), percentile95 = morphreg::percentile (resampled, 0.95);
  const double model_median = morphreg::median (model_only);
  std::printf ("[ real resampling ] face coverage %.3f (%zu of %d), observed face vertices' distance to the scan mesh: "
               "median %.3f mm, 95th percentile %.3f mm (the model-only fit there: median %.3f mm, 95th percentile "
               "%.3f mm); whole head: coverage %.3f, %zu holes, folded %d, rays %.3f s, fill %.3f s\n",
               face_coverage, resampled.size (), kFaceVertices, median, percentile95, model_median,
               morphreg::percentile (model_only, 0.95), result.statistics.coverage, result.statistics.holes.size (),
               result.statistics.folded_triangles, result.statistics.ray_seconds, result.statistics.fill_seconds);
  // Required: at least 90 % of the face observed, observed median <= 0.3 mm. The misses are ICT's creases the scan
  // does not have (eyelid margins, nostrils, the lips' line, the ears' folds): their rays meet the scan at a grazing
  // angle or against its normal, or land on the one surface the scan has there and would turn their triangles over.
  // The folds counted against the fit are mostly those creases flattened onto the scan. Measured: face coverage
  // 0.915 (whole head 0.926), median 0.053 mm, 95th percentile 0.526 mm; the no-op, the model-only fit at the same
  // vertices, median 0.465 mm, 95th percentile 1.90 mm.
  EXPECT_PRED_FORMAT2 (tightLowerBound, face_coverage, 0.9);
  EXPECT_PRED_FORMAT2 (tightLowerBound, result.statistics.coverage, 0.91);
  EXPECT_PRED_FORMAT2 (tightUpperBound, median, 0.065);
  EXPECT_PRED_FORMAT2 (tightUpperBound, percentile95, 0.62);
  EXPECT_PRED_FORMAT2 (noOpFailsUpperBound, model_median, 0.065);
  EXPECT_PRED_FORMAT2 (noOpFailsUpperBound, morphreg::percentile (model_only, 0.95), 0.62);
}
} // namespace

// SPDX-License-Identifier: BSD-3-Clause
// landmarkReference: a template warped onto landmarks marked on a scan, the reference of a resampling without a
// registration (METHOD section 5), on a synthetic head with known truth; and its bad input.
#include "../support/expect_error.h"
#include "resampled_distance.h"
#include "support/accuracy_bound.h"

#include <morphreg/common/error.h>
#include <morphreg/mesh/triangle_locator.h>
#include <morphreg/resampling/landmark_reference.h>
#include <morphreg/resampling/scan_resampler.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/scan_simulator.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <iterator>

namespace
{
using morphreg::LandmarkPositions;
using morphreg::TriangleMesh;

/** The landmarks of \a head (the generator's vertices) carried by \a pose. */
LandmarkPositions
landmarksOf (const TriangleMesh& head, const morphreg::LandmarkVertices& vertices, const Eigen::Affine3d& pose)
{
  LandmarkPositions positions;
  for (const auto& [id, vertex] : vertices)
    positions[id] = pose * head.vertices.col (vertex);
  return positions;
}

TEST (LandmarkReferenceTest, WarpedTemplateMeetsTheLandmarksAndResamplesTheScanCloseToTheTruth)
{
  const morphreg::synthetic::HeadGenerator generator;
  const TriangleMesh template_head = generator.sample (1).mesh;
  const TriangleMesh truth = generator.sample (1001).mesh;
  const auto scan = morphreg::synthetic::ScanSimulator ().scan (truth, 5);
  const LandmarkPositions marked = landmarksOf (truth, generator.landmarks (), scan.head_to_scan);

  const TriangleMesh reference = morphreg::landmarkReference (template_head, generator.landmarks (), marked, "marks");
  ASSERT_EQ (reference.numVertices (), template_head.numVertices ());
  for (const auto& [id, vertex] : generator.landmarks ())
    EXPECT_LT ((reference.vertices.col (vertex) - marked.at (id)).norm (), 1e-6) << id;

  morphreg::ScanResampler resampler;
  resampler.setInputReference (reference);
  resampler.setInputScan (*scan.cloud);
  const morphreg::ResamplingResult result = resampler.resample ();
  TriangleMesh posed = truth;
  posed.vertices = scan.head_to_scan * truth.vertices;
  const morphreg::TriangleLocator locator (posed);
  const double observed_rms = morphreg::test::rmsToSurface (result, morphreg::ResampledVertex::observed, locator);
  // The no-op: the warped template returned as it is, scored at the vertices the resampler observed.
  const double reference_rms = morphreg::test::rmsToSurface (morphreg::test::referenceInPlace (result, reference),
                                                             morphreg::ResampledVertex::observed, locator);
  std::printf ("[ landmark reference ] coverage %.3f, observed RMS %.3f mm (the warped template there: %.3f mm), %zu "
               "holes, folded %d\n",
               result.statistics.coverage, observed_rms, reference_rms, result.statistics.holes.size (),
               result.statistics.folded_triangles);
  // Measured: coverage 0.925, observed RMS 0.083 mm, the warped template 1.711 mm there.
  EXPECT_PRED_FORMAT2 (morphreg::test::tightLowerBound, result.statistics.coverage, 0.91);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, observed_rms, 0.1);
  EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, reference_rms, 0.1);
  EXPECT_EQ (result.statistics.folded_triangles, 0);
}

TEST (LandmarkReferenceTest, TooFewOrDegenerateLandmarksAreNamed)
{
  const morphreg::synthetic::HeadGenerator generator (20);
  const TriangleMesh head = generator.sample (1).mesh;
  const morphreg::LandmarkVertices& vertices = generator.landmarks ();
  LandmarkPositions four;
  for (const auto& [id, vertex] : vertices)
    if (four.size () < 4)
      four[id] = head.vertices.col (vertex);
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> (
      [&] { morphreg::landmarkReference (head, vertices, four, "four.json"); },
      "four.json: 4 of its landmarks are on the template, at least 5 are needed");

  // Two ids on one template vertex sent to two places: no warp can do that.
  const LandmarkPositions marked = landmarksOf (head, vertices, Eigen::Affine3d::Identity ());
  morphreg::LandmarkVertices coincident = vertices;
  coincident.begin ()->second = std::next (coincident.begin ())->second;
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> (
      [&] { morphreg::landmarkReference (head, coincident, marked, "marks.json"); },
      "marks.json: the template cannot be warped onto these landmarks");

  morphreg::LandmarkVertices outside = vertices;
  outside.begin ()->second = static_cast<int> (head.numVertices ());
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> (
      [&] { morphreg::landmarkReference (head, outside, marked, "marks.json"); }, "outside the");
}
} // namespace

// SPDX-License-Identifier: BSD-3-Clause
#include "population.h"

#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/model/region_segmentation.h>

#include <gtest/gtest.h>

using morphreg::LandmarkGroup;

TEST (RegionSegmentationTest, AssignsVerticesToTheGeodesicallyNearestGroup)
{
  const auto& generator = morphreg::test::coarseGenerator ();
  const morphreg::TriangleMesh head = morphreg::test::trainingMeshes (1)[0];
  const auto& lm = generator.landmarks ();
  const std::vector<LandmarkGroup> groups = {
      {"nose", {lm.at ("nose_tip")}, 25.0},
      {"mouth", {lm.at ("right_mouth_corner"), lm.at ("left_mouth_corner")}, 20.0},
      {"ears", {lm.at ("right_tragus"), lm.at ("left_tragus")}, 30.0}};
  const morphreg::RegionLabels regions = morphreg::segmentByLandmarkGroups (head, groups);
  ASSERT_EQ (regions.names.size (), 4u);
  EXPECT_EQ (regions.names.back (), "skull_neck");
  EXPECT_EQ (regions.labels[lm.at ("nose_tip")], 0);
  EXPECT_EQ (regions.labels[lm.at ("left_mouth_corner")], 1);
  EXPECT_EQ (regions.labels[lm.at ("right_tragus")], 2);

  const morphreg::MeshTopology topology (head);
  std::vector<std::vector<double>> distance;
  for (const auto& group : groups)
    distance.push_back (topology.geodesicDistances (head.vertices, group.vertices));
  for (size_t v = 0; v < regions.labels.size (); ++v) {
    const int label = regions.labels[v];
    if (label < 3) {
      EXPECT_LE (distance[label][v], groups[label].radius);
      for (size_t g = 0; g < groups.size (); ++g)
        EXPECT_LE (distance[label][v], distance[g][v]);
    }
    else
      for (size_t g = 0; g < groups.size (); ++g)
        EXPECT_GT (distance[g][v], groups[g].radius);
  }
}

TEST (RegionSegmentationTest, RejectsInvalidGroups)
{
  const morphreg::TriangleMesh head = morphreg::test::trainingMeshes (1)[0];
  EXPECT_THROW (morphreg::segmentByLandmarkGroups (head, {{"a", {}, 10.0}}), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::segmentByLandmarkGroups (head, {{"a", {0}, -1.0}}), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::segmentByLandmarkGroups (head, {{"a", {1 << 30}, 10.0}}), morphreg::InvalidInputError);
  // A radius covering the whole head leaves the rest region empty.
  EXPECT_THROW (morphreg::segmentByLandmarkGroups (head, {{"a", {0}, 1e6}}), morphreg::InvalidInputError);
}

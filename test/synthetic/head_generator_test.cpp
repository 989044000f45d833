// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/common/landmarks.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/synthetic/head_generator.h>

#include <Eigen/Geometry>
#include "support/synthetic_heads.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

using morphreg::synthetic::HeadGenerator;
using morphreg::synthetic::HeadParameters;
using morphreg::synthetic::HeadRegion;

namespace
{
const morphreg::synthetic::HeadGenerator&
generator ()
{
  return morphreg::test::headGenerator ();
}

/** Every parameter at its minimum (or maximum): the most extreme heads the population allows. */
HeadParameters
extremeParameters (bool maximum)
{
  HeadParameters parameters;
  for (const auto& range : HeadParameters::ranges ())
    parameters.*(range.member) = maximum ? range.max : range.min;
  return parameters;
}

Eigen::Vector3d
landmark (const morphreg::TriangleMesh& mesh, const std::string& id)
{
  return mesh.vertices.col (generator ().landmarks ().at (id));
}
} // namespace

TEST (HeadGeneratorTest, SameSeedGivesIdenticalHead)
{
  const auto a = generator ().sample (7);
  const auto b = generator ().sample (7);
  EXPECT_EQ (a.mesh.vertices, b.mesh.vertices);
  EXPECT_EQ (a.parameters.asVector (), b.parameters.asVector ());
  const auto population = generator ().population (3, 6);
  EXPECT_EQ (population[1].mesh.vertices, a.mesh.vertices) << "head i of a population uses seed + i";
  EXPECT_NE (generator ().sample (8).mesh.vertices, a.mesh.vertices);
}

TEST (HeadGeneratorTest, SizeAndUnitsAreHumanInMillimetres)
{
  const morphreg::TriangleMesh head = generator ().generate (HeadParameters ());
  EXPECT_GE (head.numVertices (), 5000);
  EXPECT_LE (head.numVertices (), 12000);
  const Eigen::Vector3d extent = head.vertices.rowwise ().maxCoeff () - head.vertices.rowwise ().minCoeff ();
  EXPECT_GT (extent.x (), 150.0); // skull breadth plus ears
  EXPECT_LT (extent.x (), 220.0);
  EXPECT_GT (extent.y (), 250.0); // head and neck
  EXPECT_LT (extent.y (), 400.0);
  EXPECT_GT (extent.z (), 180.0); // head length plus nose
  EXPECT_LT (extent.z (), 260.0);
  // The nose tip is the front-most landmark and sits near the origin's front (+Z).
  const Eigen::Vector3d tip = landmark (head, "nose_tip");
  EXPECT_NEAR (tip.x (), 0.0, 1.0);
  EXPECT_GT (tip.z (), 80.0);
  for (const auto& entry : generator ().landmarks ())
    EXPECT_LE (head.vertices (2, entry.second), tip.z () + 1e-9) << entry.first;
}

TEST (HeadGeneratorTest, EveryHeadIsClosedManifoldWithoutDegenerateTriangles)
{
  std::vector<morphreg::TriangleMesh> heads = {generator ().generate (extremeParameters (false)),
                                               generator ().generate (extremeParameters (true))};
  for (auto& head : generator ().population (8, 100))
    heads.push_back (head.mesh);
  const morphreg::MeshTopology topology (generator ().triangles (), generator ().numVertices ());
  EXPECT_TRUE (topology.isClosedManifold ());
  EXPECT_EQ (topology.eulerCharacteristic (), 2);
  for (const auto& head : heads) {
    EXPECT_EQ (head.triangles, generator ().triangles ()) << "topology is shared by every head";
    ASSERT_NO_THROW (morphreg::validateMesh (head, "generated head"));
    const Eigen::VectorXd areas = morphreg::triangleAreas (head);
    EXPECT_GT (areas.minCoeff (), 0.05) << "degenerate triangle";
    // Outward orientation: the signed volume of a closed outward mesh is positive.
    double volume = 0.0;
    for (Eigen::Index t = 0; t < head.numTriangles (); ++t)
      volume += head.vertices.col (head.triangles (0, t))
                    .dot (head.vertices.col (head.triangles (1, t)).cross (head.vertices.col (head.triangles (2, t))));
    EXPECT_GT (volume / 6.0, 2.0e6) << "a head holds a few litres";
  }
}

TEST (HeadGeneratorTest, AllLandmarksPresentAndOnTheirSide)
{
  const auto& landmarks = generator ().landmarks ();
  EXPECT_EQ (landmarks.size (), morphreg::knownLandmarkIds ().size ());
  for (const auto& id : morphreg::knownLandmarkIds ())
    EXPECT_EQ (landmarks.count (id), 1u) << id;
  std::set<int> vertices;
  const auto head = generator ().sample (3).mesh;
  for (const auto& [id, vertex] : landmarks) {
    vertices.insert (vertex);
    const double x = head.vertices (0, vertex);
    if (id.rfind ("left_", 0) == 0)
      EXPECT_GT (x, 2.0) << id << " (+X is the subject's left)";
    else if (id.rfind ("right_", 0) == 0)
      EXPECT_LT (x, -2.0) << id;
    else
      EXPECT_NEAR (x, 0.0, 1.0) << id << " is on the midline";
  }
  EXPECT_EQ (vertices.size (), landmarks.size ()) << "two landmarks share a vertex";
  // Anatomical order, top to bottom, on a sampled head.
  EXPECT_GT (landmark (head, "forehead").y (), landmark (head, "nasion").y ());
  EXPECT_GT (landmark (head, "nasion").y (), landmark (head, "nose_tip").y ());
  EXPECT_GT (landmark (head, "nose_tip").y (), landmark (head, "upper_lip_center").y ());
  EXPECT_GT (landmark (head, "upper_lip_center").y (), landmark (head, "lower_lip_center").y ());
  EXPECT_GT (landmark (head, "lower_lip_center").y (), landmark (head, "chin").y ());
  EXPECT_GT (landmark (head, "left_ear_top").y (), landmark (head, "left_earlobe").y ());
  EXPECT_GT (std::abs (landmark (head, "left_ear_middle").x ()), 65.0) << "ears stand off the skull";
  EXPECT_GT (landmark (head, "left_eye_outer").x (), landmark (head, "left_eye_inner").x ());
}

TEST (HeadGeneratorTest, RegionsAreTheLabelsNamedForTheModelBuilder)
{
  const morphreg::RegionLabels regions = generator ().regions ();
  ASSERT_EQ (regions.names.size (), static_cast<std::size_t> (morphreg::synthetic::kNumHeadRegions));
  EXPECT_EQ (regions.names[static_cast<int> (HeadRegion::nose)], "nose");
  EXPECT_EQ (regions.names[static_cast<int> (HeadRegion::skull_neck)], "skull_neck");
  ASSERT_EQ (regions.labels.size (), generator ().regionLabels ().size ());
  for (std::size_t v = 0; v < regions.labels.size (); ++v)
    ASSERT_EQ (regions.labels[v], static_cast<int> (generator ().regionLabels ()[v])) << "vertex " << v;
  EXPECT_NO_THROW (morphreg::validateRegionLabels (regions, generator ().numVertices ()));
}

TEST (HeadGeneratorTest, RegionLabelsCoverEveryVertexAndFeature)
{
  const auto& labels = generator ().regionLabels ();
  ASSERT_EQ (static_cast<Eigen::Index> (labels.size ()), generator ().numVertices ());
  std::vector<int> counts (morphreg::synthetic::kNumHeadRegions, 0);
  for (HeadRegion region : labels)
    ++counts[static_cast<int> (region)];
  for (int r = 0; r < morphreg::synthetic::kNumHeadRegions; ++r)
    EXPECT_GT (counts[r], 50) << morphreg::synthetic::headRegionName (static_cast<HeadRegion> (r));
  const auto region_of = [&] (const std::string& id) { return labels[generator ().landmarks ().at (id)]; };
  EXPECT_EQ (region_of ("nose_tip"), HeadRegion::nose);
  EXPECT_EQ (region_of ("left_eye_outer"), HeadRegion::eyes);
  EXPECT_EQ (region_of ("mouth_center"), HeadRegion::mouth);
  EXPECT_EQ (region_of ("right_ear_middle"), HeadRegion::ears);
  EXPECT_EQ (region_of ("chin"), HeadRegion::chin);
  EXPECT_EQ (region_of ("forehead"), HeadRegion::skull_neck);
  EXPECT_EQ (morphreg::synthetic::headRegionName (HeadRegion::cheeks), "cheeks");
}

TEST (HeadGeneratorTest, ProfileLineRunsOverTheMidline)
{
  const auto& profile = generator ().profileLine ();
  ASSERT_GT (profile.size (), 60u);
  const auto head = generator ().sample (5).mesh;
  for (int v : profile)
    EXPECT_NEAR (head.vertices (0, v), 0.0, 1e-9);
  const auto position = [&] (const std::string& id) {
    return std::find (profile.begin (), profile.end (), generator ().landmarks ().at (id)) - profile.begin ();
  };
  // From the front of the neck over the face to the back: chin, nose tip, nasion, forehead in that order.
  EXPECT_LT (position ("chin"), position ("nose_tip"));
  EXPECT_LT (position ("nose_tip"), position ("nasion"));
  EXPECT_LT (position ("nasion"), position ("forehead"));
  EXPECT_LT (position ("forehead"), static_cast<long> (profile.size ()));
}

TEST (HeadGeneratorTest, EveryParameterChangesTheShape)
{
  const morphreg::TriangleMesh mean = generator ().generate (HeadParameters ());
  for (const auto& range : HeadParameters::ranges ()) {
    HeadParameters changed;
    changed.*(range.member) = range.max;
    const double moved = (generator ().generate (changed).vertices - mean.vertices).colwise ().norm ().maxCoeff ();
    EXPECT_GT (moved, 2.0) << range.name << " has no visible effect";
  }
  HeadParameters wide;
  wide.head_breadth += 10.0;
  const auto breadth = [] (const morphreg::TriangleMesh& m) {
    double widest = 0.0; // skull breadth above the ears
    for (Eigen::Index v = 0; v < m.numVertices (); ++v)
      if (m.vertices (1, v) > 60.0)
        widest = std::max (widest, 2.0 * std::abs (m.vertices (0, v)));
    return widest;
  };
  EXPECT_NEAR (breadth (generator ().generate (wide)) - breadth (mean), 10.0, 4.0);
}

TEST (HeadGeneratorTest, PopulationVariesLikeTheDocumentedRanges)
{
  std::mt19937_64 rng (11);
  const auto& ranges = HeadParameters::ranges ();
  std::vector<double> sum (ranges.size (), 0.0), sum_sq (ranges.size (), 0.0);
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const std::vector<double> values = HeadParameters::sample (rng).asVector ();
    for (std::size_t k = 0; k < values.size (); ++k) {
      EXPECT_GE (values[k], ranges[k].min);
      EXPECT_LE (values[k], ranges[k].max);
      sum[k] += values[k];
      sum_sq[k] += values[k] * values[k];
    }
  }
  for (std::size_t k = 0; k < ranges.size (); ++k) {
    const double mean = sum[k] / n;
    const double sd = std::sqrt (sum_sq[k] / n - mean * mean);
    EXPECT_NEAR (mean, ranges[k].mean, 0.1 * ranges[k].stddev) << ranges[k].name;
    EXPECT_NEAR (sd, ranges[k].stddev, 0.15 * ranges[k].stddev) << ranges[k].name;
  }
}

TEST (HeadGeneratorTest, InvalidParametersAreNamed)
{
  HeadParameters parameters;
  parameters.nose_width = 400.0;
  try {
    generator ().generate (parameters);
    FAIL () << "an impossible nose was accepted";
  }
  catch (const morphreg::InvalidInputError& e) {
    EXPECT_NE (std::string (e.what ()).find ("nose_width"), std::string::npos) << e.what ();
  }
  parameters = HeadParameters ();
  parameters.neck_girth = std::nan ("");
  EXPECT_THROW (generator ().generate (parameters), morphreg::InvalidInputError);
  EXPECT_THROW (HeadGenerator (13), morphreg::InvalidInputError);
  EXPECT_THROW (generator ().population (-1, 0), morphreg::InvalidInputError);
}

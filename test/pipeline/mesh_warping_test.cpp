// SPDX-License-Identifier: BSD-3-Clause
// The library's mesh warping (pipeline/mesh_warping.h), the sequence `morphreg warp` runs: landmarks moved by a known
// map land where it puts them, the error against the true mesh is reported, inputs in another unit are brought to mm,
// and landmark sets that do not pair are refused naming the files.
#include "support/expect_error.h"
#include "support/synthetic_heads.h"
#include "support/temp_directory.h"
#include "support/text_file.h"

#include <morphreg/common/error.h>
#include <morphreg/io/mesh_annotations.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/pipeline/mesh_warping.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

namespace
{
using morphreg::LandmarkPositions;
using morphreg::MeshWarpInput;
using morphreg::TriangleMesh;
using morphreg::test::expectErrorContaining;

const TriangleMesh&
head ()
{
  static const TriangleMesh mesh = morphreg::test::headGenerator (20).population (1, 5).front ().mesh;
  return mesh;
}

/** Writes \a points as a landmark CSV of any names (as body rigs' joints are), which loadNamedPoints reads. */
void
writeNamedPoints (const std::string& path, const LandmarkPositions& points)
{
  std::ostringstream text;
  text.precision (17);
  text << "id,x,y,z\n";
  for (const auto& [name, p] : points)
    text << name << ',' << p.x () << ',' << p.y () << ',' << p.z () << '\n';
  morphreg::test::writeText (path, text.str ());
}

/** A smooth known map: a bulge along x growing with height, and a shift. */
Eigen::Vector3d
moved (const Eigen::Vector3d& p)
{
  return p + Eigen::Vector3d (4.0 + 0.02 * p.y (), -2.0, 1.0 + 0.01 * p.x ());
}

TriangleMesh
movedMesh (const TriangleMesh& mesh)
{
  TriangleMesh out = mesh;
  for (Eigen::Index v = 0; v < out.numVertices (); ++v)
    out.vertices.col (v) = moved (mesh.vertices.col (v));
  return out;
}

/** Landmarks on every 25th vertex of the head, and where the map puts them. */
MeshWarpInput
warpInput ()
{
  MeshWarpInput input;
  input.mesh = head ();
  input.mesh_name = "head.ply";
  for (Eigen::Index v = 0; v < input.mesh.numVertices (); v += 25) {
    const std::string name = "p" + std::to_string (v);
    input.source[name] = input.mesh.vertices.col (v);
    input.target[name] = moved (input.mesh.vertices.col (v));
  }
  input.source_name = "source.json";
  input.target_name = "target.json";
  return input;
}

TEST (MeshWarpingTest, LandmarksLandOnTheirTargetsAndTheTruthErrorIsReported)
{
  const MeshWarpInput input = warpInput ();
  for (const auto method : {morphreg::WarpMethod::thin_plate_spline, morphreg::WarpMethod::moving_least_squares}) {
    morphreg::MeshWarpingSettings settings;
    settings.method = method;
    morphreg::MeshWarpOutcome outcome = morphreg::warpMesh (input, settings);
    for (const auto& [name, position] : input.source) {
      const Eigen::Index vertex = std::stol (name.substr (1));
      EXPECT_LT ((outcome.warped.vertices.col (vertex) - input.target.at (name)).norm (), 0.1) << name;
    }
    EXPECT_EQ (outcome.report["landmarks"], input.source.size ());
    morphreg::evaluateWarpAgainst (input, movedMesh (head ()), "truth.ply", settings, outcome);
    ASSERT_TRUE (outcome.truth_error.has_value ());
    EXPECT_EQ (outcome.truth_error->size (), head ().numVertices ());
    EXPECT_LT (outcome.report["error_mm"]["max"].get<double> (), 1.0);
    EXPECT_NEAR (outcome.report["error_mm"]["max"].get<double> (), outcome.truth_error->maxCoeff (), 1e-12);
  }
}

TEST (MeshWarpingTest, SegmentedWarpTakesOneValuePerSegmentOrRefusesNamingThem)
{
  MeshWarpInput input = warpInput ();
  input.segments = morphreg::test::headGenerator (20).regions ();
  input.segments_name = "regions.json";
  morphreg::MeshWarpingSettings settings;
  settings.overlap = {std::numeric_limits<double>::infinity ()};
  const morphreg::MeshWarpOutcome outcome = morphreg::warpMesh (input, settings);
  EXPECT_EQ (outcome.report["mode"], "segmented");
  EXPECT_EQ (outcome.report["overlap_mm"][0], "all");
  const Eigen::Index vertex = 25;
  EXPECT_LT ((outcome.warped.vertices.col (vertex) - input.target.at ("p25")).norm (), 0.5);
  settings.blend_width = {10.0, 20.0};
  expectErrorContaining<morphreg::InvalidInputError> ([&] { morphreg::warpMesh (input, settings); },
                                                      "the blend width has 2 values for");
  settings.method = morphreg::WarpMethod::articulated;
  input.segments.reset ();
  expectErrorContaining<morphreg::InvalidInputError> ([&] { morphreg::warpMesh (input, settings); },
                                                      "head.ply: the articulated warp needs the segment");
}

TEST (MeshWarpingTest, FilesInCentimetresAreReadInMillimetres)
{
  morphreg::test::TempDirectory directory;
  const MeshWarpInput input = warpInput ();
  TriangleMesh in_cm = head ();
  in_cm.vertices /= 10.0;
  LandmarkPositions source_cm = input.source, target_cm = input.target;
  for (LandmarkPositions* points : {&source_cm, &target_cm})
    for (auto& entry : *points)
      entry.second /= 10.0;
  const morphreg::MeshWarpFiles files{directory.file ("head.ply"), directory.file ("source.csv"),
                                      directory.file ("target.csv"), "", ""};
  morphreg::saveTriangleMesh (files.mesh, in_cm);
  writeNamedPoints (files.source, source_cm);
  writeNamedPoints (files.target, target_cm);
  const MeshWarpInput read = morphreg::readMeshWarpInput (files, morphreg::LengthUnit::centimetre);
  EXPECT_LT ((read.mesh.vertices - head ().vertices).cwiseAbs ().maxCoeff (), 1e-3);
  EXPECT_LT ((read.target.at ("p25") - input.target.at ("p25")).norm (), 1e-3);
  EXPECT_EQ (read.source_name, files.source);
}

TEST (MeshWarpingTest, LandmarkSetsThatDoNotPairAreRefusedNamingTheFiles)
{
  morphreg::test::TempDirectory directory;
  const MeshWarpInput input = warpInput ();
  LandmarkPositions fewer = input.target;
  fewer.erase ("p25");
  const morphreg::MeshWarpFiles files{directory.file ("head.ply"), directory.file ("from.csv"),
                                      directory.file ("to_fewer.csv"), "", ""};
  morphreg::saveTriangleMesh (files.mesh, head ());
  writeNamedPoints (files.source, input.source);
  writeNamedPoints (files.target, fewer);
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] { morphreg::readMeshWarpInput (files, morphreg::LengthUnit::millimetre); }, "to_fewer.csv");
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] { morphreg::readMeshWarpInput (files, morphreg::LengthUnit::millimetre); }, "not in both: p25");

  MeshWarpInput collinear = input;
  collinear.source.clear ();
  collinear.target.clear ();
  for (int k = 0; k < 5; ++k) {
    collinear.source["c" + std::to_string (k)] = Eigen::Vector3d (k, 0.0, 0.0);
    collinear.target["c" + std::to_string (k)] = Eigen::Vector3d (k, 1.0, 0.0);
  }
  expectErrorContaining<morphreg::InvalidInputError> ([&] { morphreg::warpMesh (collinear, {}); },
                                                      "the landmarks of source.json -> target.json");
  const morphreg::MeshWarpFiles missing{files.mesh, files.source, directory.file ("none.csv"), "", ""};
  expectErrorContaining<morphreg::IoError> (
      [&] { morphreg::readMeshWarpInput (missing, morphreg::LengthUnit::millimetre); }, "none.csv");
}

TEST (MeshWarpingTest, MethodNamesAreParsedAndOthersRefused)
{
  EXPECT_EQ (morphreg::parseWarpMethod ("mls"), morphreg::WarpMethod::moving_least_squares);
  EXPECT_EQ (morphreg::parseWarpMethod ("articulated"), morphreg::WarpMethod::articulated);
  expectErrorContaining<morphreg::InvalidInputError> ([] { morphreg::parseWarpMethod ("rbf"); },
                                                      "expected tps, mls or articulated");
}
} // namespace

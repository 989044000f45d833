// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/landmark_io.h>

#include "support/temp_directory.h"

#include <gtest/gtest.h>

#include <fstream>

using morphreg::test::TempDirectory;

namespace
{
void
writeText (const std::string& path, const std::string& text)
{
  std::ofstream (path) << text;
}

/** Expects loading \a path to throw E with a message containing \a fragment. */
template <typename E>
void
expectLoadError (const std::string& path, const std::string& fragment)
{
  try {
    morphreg::loadLandmarks (path);
    FAIL () << "no error for " << path;
  }
  catch (const E& e) {
    EXPECT_NE (std::string (e.what ()).find (fragment), std::string::npos) << e.what ();
  }
}

morphreg::LandmarkPositions
someLandmarks ()
{
  return {{"nose_tip", {0.0, -2.5, 105.25}}, {"left_eye_outer", {45.5, 33.0, 73.0}}, {"chin", {0.1, -100, 62}}};
}
} // namespace

TEST (LandmarkIoTest, RoundTripsThroughEveryFormat)
{
  TempDirectory dir;
  for (const std::string name : {"l.pp", "l.json", "l.csv"}) {
    morphreg::saveLandmarks (dir.file (name), someLandmarks ());
    const auto loaded = morphreg::loadLandmarks (dir.file (name));
    ASSERT_EQ (loaded.size (), 3u) << name;
    for (const auto& [id, position] : someLandmarks ())
      EXPECT_EQ (loaded.at (id), position) << name << " " << id; // shortest round-trip formatting is exact
  }
  const morphreg::LandmarkPixels pixels = {{"nose_tip", {320.5, 240.25}}, {"chin", {321.0, 400.0}}};
  morphreg::saveLandmarkPixels (dir.file ("p.csv"), pixels);
  EXPECT_EQ (morphreg::loadLandmarkPixels (dir.file ("p.csv")), pixels);
  morphreg::saveLandmarkPixels (dir.file ("p.json"), pixels);
  EXPECT_EQ (morphreg::loadLandmarkPixels (dir.file ("p.json")), pixels);
}

TEST (LandmarkIoTest, ReadsMeshLabPickedPointsAndConvertsUnits)
{
  TempDirectory dir;
  writeText (dir.file ("m.pp"), R"(<!DOCTYPE PickedPoints>
<PickedPoints>
 <DocumentData><DataFileName name="scan.ply"/></DocumentData>
 <point x="1.5" y="-2" z="3e1" name="nose_tip" active="1"/>
 <point x="9" y="9" z="9" name="chin" active="0"/>
</PickedPoints>)");
  const auto picked = morphreg::loadLandmarks (dir.file ("m.pp"));
  ASSERT_EQ (picked.size (), 1u) << "inactive points are skipped";
  EXPECT_EQ (picked.at ("nose_tip"), Eigen::Vector3d (1.5, -2.0, 30.0));
  writeText (dir.file ("cm.json"), R"({"units": "cm", "landmarks": [{"id": "nasion", "position": [0, 1.5, 9]}]})");
  EXPECT_TRUE (morphreg::loadLandmarks (dir.file ("cm.json")).at ("nasion").isApprox (Eigen::Vector3d (0, 15, 90)));
}

TEST (LandmarkIoTest, MalformedFilesAreNamedWithTheProblem)
{
  TempDirectory dir;
  writeText (dir.file ("bad.pp"), "<PickedPoints><point x=\"1\" y=\"2\" name=\"nose_tip\"/>");
  expectLoadError<morphreg::FormatError> (dir.file ("bad.pp"), "malformed XML");
  writeText (dir.file ("noz.pp"), "<PickedPoints><point x=\"1\" y=\"2\" name=\"nose_tip\"/></PickedPoints>");
  expectLoadError<morphreg::FormatError> (dir.file ("noz.pp"), "'z'");
  writeText (dir.file ("bad.json"), "{\"landmarks\": [ {\"id\": \"nose_tip\", \"position\": [1, 2]} ]}");
  expectLoadError<morphreg::FormatError> (dir.file ("bad.json"), "array of 3 numbers");
  writeText (dir.file ("broken.json"), "{\"landmarks\": [");
  expectLoadError<morphreg::FormatError> (dir.file ("broken.json"), "malformed JSON");
  writeText (dir.file ("overflow.json"), "{\"landmarks\": [{\"id\": \"nose_tip\", \"position\": [1, 2, 1e999]}]}");
  expectLoadError<morphreg::FormatError> (dir.file ("overflow.json"), "malformed JSON");
  writeText (dir.file ("nan.csv"), "id,x,y,z\nnose_tip,1,nan,3\n");
  expectLoadError<morphreg::FormatError> (dir.file ("nan.csv"), "nan.csv:2");
  writeText (dir.file ("fields.csv"), "id,x,y,z\nnose_tip,1,2\n");
  expectLoadError<morphreg::FormatError> (dir.file ("fields.csv"), "expected 4 fields");
  writeText (dir.file ("header.csv"), "name,a,b,c\nnose_tip,1,2,3\n");
  expectLoadError<morphreg::FormatError> (dir.file ("header.csv"), "header");
  writeText (dir.file ("dup.csv"), "id,x,y,z\nnose_tip,1,2,3\nnose_tip,1,2,3\n");
  expectLoadError<morphreg::FormatError> (dir.file ("dup.csv"), "duplicate landmark 'nose_tip'");
  writeText (dir.file ("empty.csv"), "id,x,y,z\n");
  expectLoadError<morphreg::FormatError> (dir.file ("empty.csv"), "no landmarks");
  writeText (dir.file ("units.json"), R"({"units": "inch", "landmarks": []})");
  expectLoadError<morphreg::FormatError> (dir.file ("units.json"), "inch");
}

TEST (LandmarkIoTest, UnknownIdsWrongCountsAndMissingFilesAreErrors)
{
  TempDirectory dir;
  writeText (dir.file ("unknown.csv"), "id,x,y,z\nnose_tipp,1,2,3\n");
  expectLoadError<morphreg::InvalidInputError> (dir.file ("unknown.csv"), "unknown landmark id 'nose_tipp'");
  expectLoadError<morphreg::IoError> (dir.file ("missing.json"), "no such file");
  writeText (dir.file ("landmarks.txt"), "nose_tip 1 2 3\n");
  expectLoadError<morphreg::IoError> (dir.file ("landmarks.txt"), "unsupported");
  morphreg::saveLandmarks (dir.file ("three.json"), someLandmarks ());
  try {
    morphreg::loadLandmarks (dir.file ("three.json"), {"nose_tip", "chin", "nasion"});
    FAIL () << "a wrong landmark set was accepted";
  }
  catch (const morphreg::FormatError& e) {
    const std::string message = e.what ();
    EXPECT_NE (message.find ("missing: nasion"), std::string::npos) << message;
    EXPECT_NE (message.find ("unexpected: left_eye_outer"), std::string::npos) << message;
  }
  EXPECT_THROW (morphreg::saveLandmarks (dir.file ("x.json"), {{"not_an_id", Eigen::Vector3d::Zero ()}}),
                morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::saveLandmarks (dir.file ("x.json"), {}), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::saveLandmarkPixels (dir.file ("x.pp"), {{"chin", Eigen::Vector2d::Zero ()}}),
                morphreg::IoError);
}

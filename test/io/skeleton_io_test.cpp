// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/datasets/makehuman_bodies.h>
#include <morphreg/io/skeleton_io.h>

#include "support/expect_error.h"
#include "support/temp_directory.h"
#include "support/text_file.h"

#include <gtest/gtest.h>

using morphreg::test::expectErrorContaining;
using morphreg::test::TempDirectory;
using morphreg::test::writeText;

TEST (SkeletonIoTest, MakeHumanSkeletonRoundTrips)
{
  TempDirectory dir;
  const morphreg::Skeleton skeleton = morphreg::makeHumanSkeleton ();
  morphreg::saveSkeleton (dir.file ("skeleton.json"), skeleton);
  const morphreg::Skeleton read = morphreg::loadSkeleton (dir.file ("skeleton.json"));
  ASSERT_EQ (read.numBones (), skeleton.numBones ());
  for (int b = 0; b < skeleton.numBones (); ++b) {
    const morphreg::Bone &expected = skeleton.bones ()[b], &actual = read.bones ()[b];
    EXPECT_EQ (actual.name, expected.name);
    EXPECT_EQ (actual.head, expected.head);
    EXPECT_EQ (actual.tail, expected.tail);
    EXPECT_EQ (actual.segment, expected.segment);
    EXPECT_EQ (actual.twist_from, expected.twist_from);
    EXPECT_EQ (actual.twist_to, expected.twist_to);
  }
  EXPECT_EQ (read.jointNames (), skeleton.jointNames ());
  EXPECT_EQ (read.boneJointNames (), skeleton.boneJointNames ());
  EXPECT_EQ (skeleton.jointNames ().size (), 51u) << "every major joint, used by a bone or not";
}

TEST (SkeletonIoTest, MalformedFilesAreNamed)
{
  TempDirectory dir;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"{\"bone\": []}", "a skeleton file needs {\"bones\": [...]}"},
      {"{\"bones\": [{\"name\": \"a\", \"head\": \"h\", \"segment\": \"s\"}]}", "bone 0 needs \"tail\""},
      {"{\"bones\": [{\"name\": \"a\", \"head\": \"h\", \"tail\": 3, \"segment\": \"s\"}]}", "bone 0 needs \"tail\""},
      {"{\"bones\": [{\"name\": \"a\", \"head\": \"h\", \"tail\": \"t\", \"segment\": \"s\", \"twist\": [\"x\"]}]}",
       "bone 0 ('a'): \"twist\" must be two joint names"},
      {"{\"bones\": [7]}", "bone 0 is not an object"},
      {"{\"bones\": [{\"name\": \"a\", \"head\": \"h\", \"tail\": \"t\", \"segment\": \"s\"}], \"other_joints\": [1]}",
       "\"other_joints\" must be a list of joint names"},
      {"{\"bones\": [", "malformed JSON"}};
  for (std::size_t i = 0; i < cases.size (); ++i) {
    const std::string path = dir.file ("bad_" + std::to_string (i) + ".json");
    writeText (path, cases[i].first);
    expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadSkeleton (path); },
                                                  path + ": " + cases[i].second);
  }
  writeText (dir.file ("twice.json"),
             "{\"bones\": [{\"name\": \"a\", \"head\": \"h\", \"tail\": \"t\", \"segment\": "
             "\"s\"}, {\"name\": \"a\", \"head\": \"t\", \"tail\": \"u\", \"segment\": \"s\"}]}");
  expectErrorContaining<morphreg::InvalidInputError> ([&] { morphreg::loadSkeleton (dir.file ("twice.json")); },
                                                      "twice.json: Skeleton: two bones are named 'a'");
  expectErrorContaining<morphreg::IoError> ([&] { morphreg::loadSkeleton (dir.file ("none.json")); }, "none.json");
}

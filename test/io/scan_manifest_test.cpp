// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/scan_manifest.h>

#include "support/expect_error.h"
#include "support/temp_directory.h"
#include "support/text_file.h"

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <set>

using morphreg::test::TempDirectory;
using morphreg::test::writeText;

namespace
{
/** Expects loading \a path to throw IoError (or FormatError) with a message containing \a fragment. */
void
expectListError (const std::string& path, const std::string& fragment)
{
  morphreg::test::expectErrorContaining<morphreg::IoError> ([&] { morphreg::loadScanList (path); }, fragment);
}
} // namespace

TEST (ScanManifestTest, ReadsRowsWithOptionalLandmarksAndIds)
{
  TempDirectory dir;
  writeText (dir.file ("study/manifest.csv"), "scan,landmarks,id\n# a comment\nscans/a.ply\n\n"
                                              "scans/b.pcd, marks/b.pts\n/abs/c.stl,,subject_c\n");
  const morphreg::ScanManifest scans = morphreg::loadScanList (dir.file ("study/manifest.csv"));
  ASSERT_EQ (scans.size (), 3u);
  EXPECT_EQ (scans[0].id, "a");
  EXPECT_EQ (scans[0].scan, dir.file ("study/scans/a.ply")) << "relative to the manifest's folder";
  EXPECT_EQ (scans[0].landmarks, "");
  EXPECT_EQ (scans[1].landmarks, dir.file ("study/marks/b.pts"));
  EXPECT_EQ (scans[2].id, "subject_c");
  EXPECT_EQ (scans[2].scan, "/abs/c.stl");
  EXPECT_EQ (scans[2].where, dir.file ("study/manifest.csv") + ":6");
}

TEST (ScanManifestTest, BadManifestsAreNamedWithTheLine)
{
  TempDirectory dir;
  const std::vector<std::array<std::string, 3>> cases = {
      {"dup.csv", "a.ply\nother/a.ply\n", "dup.csv:2: duplicate scan id 'a' (first at " + dir.file ("dup.csv:1")},
      {"fields.csv", "a.ply,a.json,a,extra\n", "fields.csv:1: 4 fields, expected scan[,landmarks[,id]]"},
      {"empty_scan.csv", "scan,landmarks,id\n,a.json,a\n", "empty_scan.csv:2: the scan path is empty"},
      {"slash.csv", "a.ply,,x/y\n", "slash.csv:1: id 'x/y' must be a plain file name"},
      {"none.csv", "scan,landmarks,id\n# nothing\n", "none.csv: no scans listed"}};
  for (const auto& [name, text, fragment] : cases) {
    writeText (dir.file (name), text);
    expectListError (dir.file (name), fragment);
  }
  expectListError (dir.file ("missing.csv"), "missing.csv: no such file");
}

TEST (ScanManifestTest, ListsAFolderOfScansWithTheirLandmarks)
{
  TempDirectory dir;
  for (const char* name : {"b.ply", "a.pcd", "c.off", "a_landmarks.json", "b_landmarks.pts", "notes.txt"})
    writeText (dir.file (std::string ("scans/") + name), "x");
  const morphreg::ScanManifest scans = morphreg::loadScanList (dir.file ("scans"));
  ASSERT_EQ (scans.size (), 3u);
  EXPECT_EQ (scans[0].id, "a");
  EXPECT_EQ (scans[0].landmarks, dir.file ("scans/a_landmarks.json"));
  EXPECT_EQ (scans[1].landmarks, dir.file ("scans/b_landmarks.pts"));
  EXPECT_EQ (scans[2].scan, dir.file ("scans/c.off"));
  EXPECT_EQ (scans[2].landmarks, "");
  writeText (dir.file ("clash/a.ply"), "x");
  writeText (dir.file ("clash/a.pcd"), "x");
  expectListError (dir.file ("clash"), "duplicate scan id 'a'");
  writeText (dir.file ("empty/readme.txt"), "x");
  expectListError (dir.file ("empty"), "no scans in the folder");
}

TEST (ScanManifestTest, ShardsTakeEveryScanExactlyOnce)
{
  morphreg::ScanManifest scans;
  for (int k = 0; k < 11; ++k)
    scans.push_back ({"s" + std::to_string (k), "s.ply", "", ""});
  std::multiset<std::string> taken;
  for (int index = 0; index < 4; ++index) {
    const morphreg::ScanManifest shard = morphreg::manifestShard (scans, index, 4);
    EXPECT_EQ (shard.size (), index < 3 ? 3u : 2u);
    EXPECT_EQ (shard.front ().id, "s" + std::to_string (index));
    for (const auto& entry : shard)
      taken.insert (entry.id);
  }
  EXPECT_EQ (taken.size (), scans.size ());
  EXPECT_EQ (std::set<std::string> (taken.begin (), taken.end ()).size (), scans.size ());
  EXPECT_THROW (morphreg::manifestShard (scans, 4, 4), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::manifestShard (scans, -1, 4), morphreg::InvalidInputError);
}

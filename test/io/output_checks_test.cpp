// SPDX-License-Identifier: BSD-3-Clause
// Output paths are checked before any work: a folder that is missing or not a folder, a path that is a folder, an
// output that is one of the inputs (by another spelling or a hard link).
#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>

#include "support/expect_error.h"
#include "support/temp_directory.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

using morphreg::test::expectErrorContaining;
using morphreg::test::TempDirectory;

TEST (OutputChecksTest, AWritableFolderPasses)
{
  TempDirectory dir;
  EXPECT_NO_THROW (morphreg::requireWritableOutput (dir.file ("fit.ply")));
  std::ofstream (dir.file ("existing.ply")) << "old";
  EXPECT_NO_THROW (morphreg::requireWritableOutput (dir.file ("existing.ply"))) << "replacing a file is allowed";
}

TEST (OutputChecksTest, AMissingFolderIsNamed)
{
  TempDirectory dir;
  expectErrorContaining<morphreg::IoError> (
      [&] { morphreg::requireWritableOutput (dir.file ("no_such_folder/fit.ply")); },
      dir.file ("no_such_folder") + " does not exist");
}

TEST (OutputChecksTest, AFileInPlaceOfTheFolderIsNamed)
{
  TempDirectory dir;
  std::ofstream (dir.file ("scan.pcd")) << "points";
  expectErrorContaining<morphreg::IoError> ([&] { morphreg::requireWritableOutput (dir.file ("scan.pcd/fit.ply")); },
                                            "scan.pcd is not a folder");
}

TEST (OutputChecksTest, AFolderAsTheOutputIsRefused)
{
  TempDirectory dir;
  expectErrorContaining<morphreg::IoError> ([&] { morphreg::requireWritableOutput (dir.file ("")); }, "is a directory");
  expectErrorContaining<morphreg::IoError> ([&] { morphreg::requireWritableOutput (""); }, "empty");
}

TEST (OutputChecksTest, AnOutputThatIsAnInputIsRefusedHoweverItIsSpelt)
{
  TempDirectory dir;
  const std::string scan = dir.file ("scan.ply");
  std::ofstream (scan) << "points";
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] {
        morphreg::requireNotAnInput (scan, {"", dir.file ("model.h5"), scan});
      },
      "also an input");
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] { morphreg::requireNotAnInput (dir.file ("sub/../scan.ply"), {scan}); }, "would overwrite");
  std::filesystem::create_hard_link (scan, dir.file ("link.ply"));
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] { morphreg::requireNotAnInput (dir.file ("link.ply"), {scan}); }, "also an input");
  EXPECT_NO_THROW (morphreg::requireNotAnInput (dir.file ("fit.ply"), {scan, dir.file ("missing.h5")}));
}

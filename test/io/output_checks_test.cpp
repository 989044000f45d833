// SPDX-License-Identifier: BSD-3-Clause
// Output paths are checked before any work: a folder that is missing or not a folder, a path that is a folder, an
// output that is one of the inputs (by another spelling, a hard link or a symbolic link) or lies in a folder of
// inputs, two outputs on one file.
#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/output_plan.h>

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

/** OutputPlan::check() on one output \a out against the input \a scan. */
void
checkOutput (const std::string& out, const std::string& scan)
{
  morphreg::OutputPlan plan;
  plan.addInput ("", "--landmarks");
  plan.addInput (scan, "--scan");
  plan.addOutput (out, "--out");
  plan.check ();
}

TEST (OutputChecksTest, AnOutputThatIsAnInputIsRefusedHoweverItIsSpelt)
{
  TempDirectory dir;
  const std::string scan = dir.file ("scan.ply");
  std::ofstream (scan) << "points";
  std::filesystem::create_directories (dir.file ("sub"));
  expectErrorContaining<morphreg::InvalidInputError> ([&] { checkOutput (scan, scan); }, "also an input");
  expectErrorContaining<morphreg::InvalidInputError> ([&] { checkOutput (dir.file ("sub/../scan.ply"), scan); },
                                                      "would overwrite");
  std::filesystem::create_hard_link (scan, dir.file ("link.ply"));
  expectErrorContaining<morphreg::InvalidInputError> ([&] { checkOutput (dir.file ("link.ply"), scan); },
                                                      scan + " (--scan)");
  std::filesystem::create_symlink (scan, dir.file ("symlink.ply"));
  expectErrorContaining<morphreg::InvalidInputError> ([&] { checkOutput (dir.file ("symlink.ply"), scan); },
                                                      "symlink.ply (--out): is also an input");
  EXPECT_NO_THROW (checkOutput (dir.file ("fit.ply"), scan));
  expectErrorContaining<morphreg::InvalidInputError> ([&] { checkOutput ("", scan); },
                                                      "--out: the output file name is empty");
}

TEST (OutputChecksTest, AnOutputInAFolderOfInputsIsRefused)
{
  TempDirectory dir;
  std::filesystem::create_directories (dir.file ("scans"));
  morphreg::OutputPlan plan;
  plan.addInputFolder (dir.file ("scans/."), "--scans");
  plan.addOutput (dir.file ("scans/a.ply"), "the fitted mesh of scan 'a'");
  expectErrorContaining<morphreg::InvalidInputError> ([&] { plan.check (); },
                                                      "a folder whose files this run reads as inputs");
  morphreg::OutputPlan beside;
  beside.addInputFolder (dir.file ("scans"), "--scans");
  beside.addOutput (dir.file ("a.ply"), "the fitted mesh of scan 'a'");
  EXPECT_NO_THROW (beside.check ());
}

TEST (OutputChecksTest, TwoOutputsOnOneFileAreRefusedNamingBoth)
{
  TempDirectory dir;
  morphreg::OutputPlan plan;
  plan.addOutput (dir.file ("a_fit.ply"), "the fit of scan 'a'");
  plan.addOutput (dir.file ("b.ply"), "the resampled mesh of scan 'b'");
  plan.addOutput (dir.file ("./a_fit.ply"), "the resampled mesh of scan 'a_fit'");
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] { plan.check (); }, "write it twice, as the fit of scan 'a' and as the resampled mesh of scan 'a_fit'");
}

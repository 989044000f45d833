// SPDX-License-Identifier: BSD-3-Clause
// The outputs of one run are committed together: a run that fails half-way changes no file, removes no old output
// and leaves no partial file; transactions nest.
#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>
#include <morphreg/io/output_transaction.h>

#include "support/temp_directory.h"
#include "support/text_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

using morphreg::test::readBytes;
using morphreg::test::TempDirectory;

namespace
{
void
write (const std::string& path, const std::string& text)
{
  morphreg::writeFileAtomically (path, text);
}

/** The names of the files in \a folder (hidden ones included), sorted. */
std::vector<std::string>
namesIn (const std::string& folder)
{
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::recursive_directory_iterator (folder))
    names.push_back (std::filesystem::relative (entry.path (), folder).string ());
  std::sort (names.begin (), names.end ());
  return names;
}
} // namespace

TEST (OutputTransactionTest, NothingMovesUntilEveryOutputIsWritten)
{
  TempDirectory dir;
  write (dir.file ("fit.ply"), "old fit");
  write (dir.file ("fit.json"), "old report");
  morphreg::OutputTransaction outputs ({dir.file ("fit.ply"), dir.file ("fit.json"), ""});
  write (dir.file ("fit.ply"), "new fit");
  EXPECT_EQ (readBytes (dir.file ("fit.ply")), "old fit") << "replaced before the run is complete";
  write (dir.file ("fit.json"), "new report");
  write (dir.file ("other.txt"), "not an output of the transaction");
  EXPECT_EQ (readBytes (dir.file ("other.txt")), "not an output of the transaction");
  outputs.commit ();
  EXPECT_EQ (readBytes (dir.file ("fit.ply")), "new fit");
  EXPECT_EQ (readBytes (dir.file ("fit.json")), "new report");
  EXPECT_EQ (namesIn (dir.file ("")), (std::vector<std::string>{"fit.json", "fit.ply", "other.txt"}));
}

TEST (OutputTransactionTest, AFailedRunKeepsTheOldOutputsAndLeavesNoPartialFile)
{
  TempDirectory dir;
  write (dir.file ("fit.ply"), "old fit");
  write (dir.file ("fit.json"), "old report");
  EXPECT_THROW (
      {
        morphreg::OutputTransaction outputs ({dir.file ("fit.ply"), dir.file ("fit.json"), dir.file ("fit.png")});
        write (dir.file ("fit.ply"), "new fit");
        write (dir.file ("fit.png"), "new screenshot");
        throw std::runtime_error ("the report cannot be written");
      },
      std::runtime_error);
  EXPECT_EQ (readBytes (dir.file ("fit.ply")), "old fit");
  EXPECT_EQ (readBytes (dir.file ("fit.json")), "old report");
  EXPECT_EQ (namesIn (dir.file ("")), (std::vector<std::string>{"fit.json", "fit.ply"}));
}

TEST (OutputTransactionTest, AFolderIsCompleteOrAbsent)
{
  TempDirectory dir;
  {
    morphreg::OutputTransaction outputs ({}, {dir.file ("synth/heads")});
    write (dir.file ("synth/heads/head_000.ply"), "head");
    EXPECT_EQ (namesIn (dir.file ("synth")), (std::vector<std::string>{"heads", "heads/.partial.head_000.ply"}));
  }
  EXPECT_FALSE (std::filesystem::exists (dir.file ("synth"))) << "the folder the failed run created is left";
  morphreg::OutputTransaction outputs ({}, {dir.file ("synth")});
  write (dir.file ("synth/population.json"), "manifest");
  write (dir.file ("synth/head_000.ply"), "head");
  outputs.commit (dir.file ("synth/population.json"));
  EXPECT_EQ (namesIn (dir.file ("synth")), (std::vector<std::string>{"head_000.ply", "population.json"}));
  EXPECT_THROW (morphreg::OutputTransaction ({}, {dir.file ("synth/head_000.ply")}), morphreg::IoError)
      << "a file in place of the folder";
}

TEST (OutputTransactionTest, AnInnerCommitStaysStagedForTheOuterTransaction)
{
  TempDirectory dir;
  {
    morphreg::OutputTransaction model ({dir.file ("model.h5")}, {dir.file ("reports")});
    {
      morphreg::OutputTransaction scan ({dir.file ("reports/a.json")});
      write (dir.file ("reports/a.json"), "report of a");
      scan.commit ();
    }
    EXPECT_FALSE (std::filesystem::exists (dir.file ("reports/a.json"))) << "committed past the outer transaction";
    EXPECT_TRUE (std::filesystem::exists (dir.file ("reports/.partial.a.json")));
  }
  EXPECT_FALSE (std::filesystem::exists (dir.file ("reports"))) << "the outer rollback keeps the inner outputs";
}

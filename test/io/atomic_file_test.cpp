// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>

#include "support/temp_directory.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

using morphreg::test::TempDirectory;

TEST (AtomicFileTest, TheFileAppearsOnlyWhenComplete)
{
  TempDirectory dir;
  const std::string path = dir.file ("fit.ply");
  EXPECT_EQ (morphreg::partialPath (path), dir.file (".partial.fit.ply")) << "same folder, extension kept";
  morphreg::writeAtomically (path, [&] (const std::string& partial) {
    std::ofstream (partial) << "whole";
    EXPECT_FALSE (std::filesystem::exists (path)) << "visible before it is complete";
  });
  std::ifstream stream (path);
  std::string content;
  stream >> content;
  EXPECT_EQ (content, "whole");
  EXPECT_FALSE (std::filesystem::exists (morphreg::partialPath (path)));
}

TEST (AtomicFileTest, AFailedWriteLeavesNeitherFileNorPartial)
{
  TempDirectory dir;
  const std::string path = dir.file ("report.json");
  EXPECT_THROW (morphreg::writeAtomically (path,
                                           [] (const std::string& partial) {
                                             std::ofstream (partial) << "half";
                                             throw std::runtime_error ("disk full");
                                           }),
                std::runtime_error);
  EXPECT_FALSE (std::filesystem::exists (path));
  EXPECT_FALSE (std::filesystem::exists (morphreg::partialPath (path)));
  EXPECT_THROW (morphreg::commitPartial (dir.file ("never_written"), path), morphreg::IoError);
}

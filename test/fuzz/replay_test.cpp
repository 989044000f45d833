// SPDX-License-Identifier: BSD-3-Clause
// Replays every committed fuzz input (fuzz/corpus/<target>/) and crash reproducer (fuzz/crashes/<target>/) through
// its target's loaders: each must load or throw morphreg::Error, never crash or throw anything else.
#include <fuzz_target.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <set>

namespace
{
namespace fs = std::filesystem;

const fs::path kFuzzDir = MORPHREG_FUZZ_DIR;

std::vector<std::string>
targetNames ()
{
  std::vector<std::string> names;
  for (const auto& target : morphreg::fuzz::targets ())
    names.push_back (target.name);
  return names;
}

/** The files of fuzz/<kind>/<target>/, sorted; none if the folder does not exist. */
std::vector<fs::path>
inputFiles (const char* kind, const std::string& target)
{
  std::vector<fs::path> files;
  const fs::path folder = kFuzzDir / kind / target;
  if (fs::is_directory (folder))
    for (const auto& entry : fs::directory_iterator (folder))
      if (entry.is_regular_file ())
        files.push_back (entry.path ());
  std::sort (files.begin (), files.end ());
  return files;
}

std::vector<std::uint8_t>
readBytes (const fs::path& path)
{
  std::ifstream stream (path, std::ios::binary);
  return {std::istreambuf_iterator<char> (stream), std::istreambuf_iterator<char> ()};
}

TEST (FuzzCorpus, EveryTargetHasASeedCorpusAndEveryFolderATarget)
{
  const std::vector<std::string> names = targetNames ();
  const std::set<std::string> registered (names.begin (), names.end ());
  EXPECT_EQ (registered.size (), names.size ()) << "two fuzz targets share a name";
  for (const char* kind : {"corpus", "crashes", "open"}) {
    if (!fs::is_directory (kFuzzDir / kind))
      continue;
    for (const auto& entry : fs::directory_iterator (kFuzzDir / kind))
      EXPECT_TRUE (registered.count (entry.path ().filename ().string ()))
          << entry.path () << " is not the folder of a fuzz target";
  }
  for (const std::string& name : names)
    EXPECT_FALSE (inputFiles ("corpus", name).empty ()) << "fuzz target " << name << " has no seed corpus";
}

class FuzzReplay : public ::testing::TestWithParam<std::string>
{};

TEST_P (FuzzReplay, CorpusAndCrashReproducersLoadOrFailCleanly)
{
  const morphreg::fuzz::Target& target = morphreg::fuzz::findTarget (GetParam ());
  for (const char* kind : {"corpus", "crashes"})
    for (const fs::path& file : inputFiles (kind, target.name)) {
      SCOPED_TRACE (file.string ());
      const std::vector<std::uint8_t> bytes = readBytes (file);
      EXPECT_NO_THROW (morphreg::fuzz::runTarget (target, bytes.data (), bytes.size ()));
    }
}

INSTANTIATE_TEST_SUITE_P (Targets, FuzzReplay, ::testing::ValuesIn (targetNames ()),
                          [] (const ::testing::TestParamInfo<std::string>& info) { return info.param; });
} // namespace

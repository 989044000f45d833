// SPDX-License-Identifier: BSD-3-Clause
#include "progress.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <string>

using morphreg::tools::Progress;

namespace
{
/** Runs steps 1..\a steps of \a total and finish(), returning what was written. */
std::string
runStage (int total, int steps, bool redraw, Progress::Clock::duration interval, bool quiet = false)
{
  std::ostringstream out;
  const Progress progress ("fitting", total, quiet, out, redraw, interval);
  for (int done = 1; done <= steps; ++done)
    progress.step (done, " detail");
  progress.finish (steps);
  return out.str ();
}

long
countOf (const std::string& text, char c)
{
  return std::count (text.begin (), text.end (), c);
}
} // namespace

TEST (ProgressTest, RedrawsOneLineOnATerminal)
{
  const std::string out = runStage (100, 3, true, std::chrono::hours (1));
  EXPECT_EQ (countOf (out, '\r'), 4);
  EXPECT_EQ (countOf (out, '\n'), 1);
  EXPECT_NE (out.find ("\rfitting [3/100] detail"), std::string::npos);
  EXPECT_NE (out.find ("\rfitting [3/100] done"), std::string::npos);
}

TEST (ProgressTest, WritesTheFirstStepEachTenthAndTheEndAsLinesInALog)
{
  const std::string out = runStage (100, 100, false, std::chrono::hours (1));
  EXPECT_EQ (countOf (out, '\r'), 0);
  std::string expected = "fitting [1/100] detail\n";
  for (int done = 10; done <= 100; done += 10)
    expected += "fitting [" + std::to_string (done) + "/100] detail\n";
  EXPECT_EQ (out, expected + "fitting [100/100] done\n");
}

TEST (ProgressTest, WritesAStepAfterTheIntervalInALog)
{
  const std::string out = runStage (1000, 5, false, std::chrono::seconds (0));
  EXPECT_EQ (out, "fitting [1/1000] detail\nfitting [2/1000] detail\nfitting [3/1000] detail\n"
                  "fitting [4/1000] detail\nfitting [5/1000] detail\nfitting [5/1000] done\n");
}

TEST (ProgressTest, StageThatStopsEarlyEndsWithItsCount)
{
  const std::string out = runStage (40, 9, false, std::chrono::hours (1));
  EXPECT_EQ (out, "fitting [1/40] detail\nfitting [4/40] detail\nfitting [8/40] detail\nfitting [9/40] done\n");
}

TEST (ProgressTest, QuietWritesNothing)
{
  EXPECT_EQ (runStage (10, 10, false, std::chrono::seconds (0), true), "");
  EXPECT_EQ (runStage (10, 10, true, std::chrono::seconds (0), true), "");
}

// SPDX-License-Identifier: BSD-3-Clause
// The share of a study a user names: "I/N", "auto" in a Slurm job array, or the whole study.
#include <morphreg/common/error.h>
#include <morphreg/pipeline/batch_shard.h>

#include "support/expect_error.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace
{
using morphreg::BatchShard;
using morphreg::InvalidInputError;
using morphreg::parseBatchShard;
using morphreg::test::expectErrorContaining;

TEST (BatchShardTest, NamedSharesAndTheWholeStudy)
{
  const BatchShard whole = parseBatchShard ("");
  EXPECT_EQ (whole.index, 0);
  EXPECT_EQ (whole.count, 1);
  EXPECT_EQ (whole.tag (), "all");
  const BatchShard third = parseBatchShard ("2/3");
  EXPECT_EQ (third.index, 2);
  EXPECT_EQ (third.count, 3);
  EXPECT_EQ (third.tag (), "shard-2-of-3");
  for (const char* bad : {"3/3", "-1/3", "1/0", "1/2x", "1-2", "a/b", "1/2/3"})
    expectErrorContaining<InvalidInputError> ([&] { parseBatchShard (bad); },
                                              "shard '" + std::string (bad) + "': expected I/N with 0 <= I < N");
}

TEST (BatchShardTest, AutoIsThisTaskOfTheSlurmJobArray)
{
  ::unsetenv ("SLURM_ARRAY_TASK_ID");
  ::unsetenv ("SLURM_ARRAY_TASK_MIN");
  ::setenv ("SLURM_ARRAY_TASK_COUNT", "4", 1);
  expectErrorContaining<InvalidInputError> ([] { parseBatchShard ("auto"); }, "SLURM_ARRAY_TASK_ID is not set");
  ::setenv ("SLURM_ARRAY_TASK_ID", "seven", 1);
  expectErrorContaining<InvalidInputError> ([] { parseBatchShard ("auto"); },
                                            "SLURM_ARRAY_TASK_ID='seven' is not a whole number");
  ::setenv ("SLURM_ARRAY_TASK_ID", "7", 1);
  ::setenv ("SLURM_ARRAY_TASK_MIN", "5", 1);
  const BatchShard shard = parseBatchShard ("auto");
  EXPECT_EQ (shard.index, 2);
  EXPECT_EQ (shard.count, 4);
  ::setenv ("SLURM_ARRAY_TASK_ID", "9", 1);
  expectErrorContaining<InvalidInputError> ([] { parseBatchShard ("auto"); }, "is outside the job array");
  for (const char* name : {"SLURM_ARRAY_TASK_ID", "SLURM_ARRAY_TASK_MIN", "SLURM_ARRAY_TASK_COUNT"})
    ::unsetenv (name);
}
} // namespace

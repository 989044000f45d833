// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/pipeline/batch_shard.h>

#include <morphreg/common/error.h>

#include <cstdlib>
#include <sstream>

namespace morphreg
{
namespace
{
/** The whole number in the environment variable \a name, for shard "auto". */
int
slurmInteger (const char* name)
{
  const char* value = std::getenv (name);
  if (value == nullptr || *value == '\0')
    throw InvalidInputError (std::string ("shard 'auto': the environment variable ") + name +
                             " is not set (run it as a Slurm job array: sbatch --array=0-(N-1))");
  char* end = nullptr;
  const long number = std::strtol (value, &end, 10);
  if (*end != '\0' || number < 0 || number > 1000000)
    throw InvalidInputError (std::string ("shard 'auto': ") + name + "='" + value + "' is not a whole number");
  return static_cast<int> (number);
}

/** This task's share of a Slurm job array. */
BatchShard
slurmShard ()
{
  const int first = std::getenv ("SLURM_ARRAY_TASK_MIN") ? slurmInteger ("SLURM_ARRAY_TASK_MIN") : 0;
  const BatchShard shard{slurmInteger ("SLURM_ARRAY_TASK_ID") - first, slurmInteger ("SLURM_ARRAY_TASK_COUNT")};
  if (shard.count < 1 || shard.index < 0 || shard.index >= shard.count)
    throw InvalidInputError ("shard 'auto': task " + std::to_string (shard.index) + " of " +
                             std::to_string (shard.count) +
                             " is outside the job array (SLURM_ARRAY_TASK_ID, _MIN and _COUNT disagree)");
  return shard;
}
} // namespace

BatchShard
parseBatchShard (const std::string& text)
{
  if (text.empty ())
    return {};
  if (text == "auto")
    return slurmShard ();
  BatchShard shard;
  char slash = 0, rest = 0;
  std::istringstream stream (text);
  if (!(stream >> shard.index >> slash >> shard.count) || slash != '/' || stream >> rest || shard.count < 1 ||
      shard.index < 0 || shard.index >= shard.count)
    throw InvalidInputError ("shard '" + text + "': expected I/N with 0 <= I < N (e.g. 0/4), or auto");
  return shard;
}
} // namespace morphreg

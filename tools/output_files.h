// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The files a subcommand writes, checked before any work and removed again if the run fails.
#include "pipeline.h"

#include <sys/types.h>

#include <string>
#include <vector>

namespace morphreg
{
namespace tools
{
/** The output files of one run. The constructor checks each before any work is done (its folder exists and is
 *  writable, it is none of the inputs, no two outputs are the same file); if the run then fails (the object is
 *  destroyed without keep()), every output the run wrote is removed, so no partial result is left behind. Outputs
 *  are written atomically by the library, so a file the run did not get to keeps its old content.
 */
class OutputFiles
{
public:
  /** Checks \a outputs (empty names are skipped: optional outputs not asked for) against \a inputs. */
  OutputFiles (const std::vector<std::string>& outputs, const std::vector<std::string>& inputs);
  ~OutputFiles ();
  OutputFiles (const OutputFiles&) = delete;
  OutputFiles&
  operator= (const OutputFiles&) = delete;

  /** The run succeeded (or failed its checks with its outputs written on purpose): keep what it wrote. */
  void
  keep ();

private:
  struct Output
  {
    std::string path;
    ino_t inode; ///< the file's inode before the run, 0 if it did not exist: a new inode means the run wrote it
  };
  std::vector<Output> outputs_;
  bool keep_ = false;
};

/** An output folder of one run (synth): checked before any work (it is a folder or can be created, and is none of
 *  the inputs); if the run fails, the files it created there are removed, and the folders too if the run created
 *  them.
 */
class OutputFolder
{
public:
  /** Checks that \a path can be created (or is a writable folder) and is none of \a inputs. */
  OutputFolder (const std::string& path, const std::vector<std::string>& inputs);
  ~OutputFolder ();
  OutputFolder (const OutputFolder&) = delete;
  OutputFolder&
  operator= (const OutputFolder&) = delete;

  /** The run succeeded: keep the folder and its files. */
  void
  keep ();

private:
  std::string path_;
  std::string created_; ///< the outermost folder the run creates ("" if the folder exists)
  std::vector<std::string> files_before_;
  bool keep_ = false;
};
/** Runs \a run and keeps \a outputs when it succeeds or throws FitCheckFailure: a fit that failed its checks has
 *  its outputs written on purpose (the report says why it failed).
 */
template <typename Outputs, typename Run>
auto
keepOnSuccessOrFitFailure (Outputs& outputs, Run run) -> decltype (run ())
{
  try {
    auto result = run ();
    outputs.keep ();
    return result;
  }
  catch (const FitCheckFailure&) {
    outputs.keep ();
    throw;
  }
}
} // namespace tools
} // namespace morphreg

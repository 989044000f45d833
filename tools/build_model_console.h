// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What `morphreg build-model` shows as the library builds: each stage's progress, and the scans left out.
#include "progress.h"

#include <morphreg/pipeline/model_building.h>

#include <iostream>
#include <optional>
#include <string>

namespace morphreg
{
namespace tools
{
/** The progress of a model building on the console (quiet: none); a scan left out on stderr, always. */
class BuildModelConsole : public ModelBuildingObserver
{
public:
  explicit BuildModelConsole (bool quiet) : quiet_ (quiet) {}

  void
  stageStarted (const std::string& stage, int count) override
  {
    progress_.emplace (stage, count, quiet_);
  }

  void
  inputDone (int done, const std::string& detail) override
  {
    progress_->step (done, detail);
  }

  void
  stageFinished () override
  {
    progress_->finish ();
  }

  void
  inputLeftOut (const ModelInput& input) override
  {
    std::cerr << "build-model: left out " << input.file << ": " << input.reason << '\n';
  }

  void
  warning (const std::string& text) override
  {
    std::cerr << "build-model: warning: " << text << '\n';
  }

private:
  bool quiet_;
  std::optional<Progress> progress_;
};
} // namespace tools
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Registration of the CLI's subcommands; each lives in its own tools/command_<name>.cpp.
#include <CLI/CLI.hpp>

namespace morphreg
{
namespace tools
{
/** Exit codes: 0 success, 1 bad input (a file or its content), 2 bad arguments (CLI11), 3 internal error, 4 a fit
 *  that failed its plausibility checks (register: outputs written, the report marked failed). */
constexpr int kExitInputError = 1;
constexpr int kExitBadArguments = 2;
constexpr int kExitInternalError = 3;
constexpr int kExitFitFailedChecks = 4;

void
registerSynthCommand (CLI::App& app);
void
registerDemoCommand (CLI::App& app);
void
registerRenderCommand (CLI::App& app);
void
registerWarpCommand (CLI::App& app);
void
registerViewCommand (CLI::App& app);
void
registerBuildModelCommand (CLI::App& app);
void
registerRegisterCommand (CLI::App& app);
void
registerFitPhotosCommand (CLI::App& app);
void
registerModelInfoCommand (CLI::App& app);
void
registerResampleCommand (CLI::App& app);
void
registerMergeSummariesCommand (CLI::App& app);
void
registerEvaluateModelCommand (CLI::App& app);

/** Adds every subcommand to \a app. */
inline void
registerCommands (CLI::App& app)
{
  registerSynthCommand (app);
  registerBuildModelCommand (app);
  registerRegisterCommand (app);
  registerResampleCommand (app);
  registerFitPhotosCommand (app);
  registerMergeSummariesCommand (app);
  registerModelInfoCommand (app);
  registerEvaluateModelCommand (app);
  registerDemoCommand (app);
  registerRenderCommand (app);
  registerViewCommand (app);
  registerWarpCommand (app);
}
} // namespace tools
} // namespace morphreg

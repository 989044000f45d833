// SPDX-License-Identifier: BSD-3-Clause
// The morphreg command line: subcommands are registered by the tools/command_*.cpp files.
#include "commands.h"
#include "console.h"
#include "option_suggestions.h"
#include "pipeline.h"
#include "provenance.h"

#include <morphreg/common/error.h>
#include <morphreg/visualization/message_verbosity.h>

#include <CLI/CLI.hpp>

#include <csignal>
#include <iostream>

int
main (int argc, char** argv)
{
  // A file size limit (ulimit -f) then makes a write fail with an error the writers report, instead of killing us.
  morphreg::tools::recordCommandLine (argc, argv);
  std::signal (SIGXFSZ, SIG_IGN);
  CLI::App app{"morphreg: morphable-model registration and thin plate spline warping for PCL"};
  app.set_version_flag ("--version", std::string ("morphreg ") + MORPHREG_VERSION);
  app.require_subcommand (1);
  app.footer ("Exit codes: 0 success, 1 bad input (a file or its content), 2 bad arguments, 3 internal error, "
              "4 the fit failed its checks (register: the fitted mesh and the report are written, the report's "
              "status is \"failed\").");
  morphreg::tools::registerCommands (app);
  morphreg::tools::addVerbosityOptions (app);
  if (const std::string unknown = morphreg::tools::unknownArgumentMessage (app, argc, argv); !unknown.empty ()) {
    std::cerr << "morphreg: " << unknown << "\nRun with --help for more information.\n";
    return morphreg::tools::kExitBadArguments;
  }
  try {
    app.parse (argc, argv);
  }
  catch (const CLI::ParseError& e) {
    const int status = app.exit (e); // prints the message, or the help / version text (status 0)
    return status == 0 ? 0 : morphreg::tools::kExitBadArguments;
  }
  catch (const morphreg::tools::FitCheckFailure& e) {
    std::cerr << morphreg::takeHeldVtkErrors () << std::flush;
    std::cerr << "morphreg: the fit failed its checks: " << e.what () << '\n';
    return morphreg::tools::kExitFitFailedChecks;
  }
  catch (const morphreg::Error& e) {
    morphreg::takeHeldVtkErrors (); // dropped: the message names the problem
    std::cerr << "morphreg: error: " << e.what () << '\n';
    return morphreg::tools::kExitInputError;
  }
  catch (const std::exception& e) {
    std::cerr << morphreg::takeHeldVtkErrors () << std::flush;
    std::cerr << "morphreg: internal error: " << e.what () << '\n';
    return morphreg::tools::kExitInternalError;
  }
  std::cerr << morphreg::takeHeldVtkErrors () << std::flush;
  return 0;
}

// SPDX-License-Identifier: BSD-3-Clause
// The CLI's verbosity: PCL's console level and a VTK output window that filters by message type.
#include "console.h"

#include <pcl/console/print.h>

#include <vtkLogger.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

#include <iostream>
#include <string>

namespace morphreg
{
namespace tools
{
namespace
{
Verbosity current_verbosity = Verbosity::normal;
std::string held_errors; ///< VTK's errors in normal mode, printed at the end unless the command failed

/** Prints VTK's warnings, debug and plain text only when verbose (on stderr: stdout carries results, e.g. model-info
 *  --json). Its errors are printed at once when verbose and held in normal mode: a failing command's own message
 *  names the problem, so they are shown only when the command does not fail (printHeldErrors).
 */
class VerbosityOutputWindow : public vtkOutputWindow
{
public:
  static VerbosityOutputWindow*
  New ();
  vtkTypeMacro (VerbosityOutputWindow, vtkOutputWindow);

  void
  DisplayText (const char* text) override
  {
    if (current_verbosity == Verbosity::verbose)
      std::cerr << text << std::flush;
    else if (current_verbosity == Verbosity::normal && GetCurrentMessageType () == MESSAGE_TYPE_ERROR)
      held_errors += text;
  }
};
vtkStandardNewMacro (VerbosityOutputWindow);

pcl::console::VERBOSITY_LEVEL
pclLevel (Verbosity verbosity)
{
  switch (verbosity) {
  case Verbosity::quiet:
    return pcl::console::L_ALWAYS;
  case Verbosity::verbose:
    return pcl::console::L_DEBUG;
  default:
    return pcl::console::L_ERROR;
  }
}
} // namespace

void
setVerbosity (Verbosity verbosity)
{
  current_verbosity = verbosity;
  pcl::console::setVerbosityLevel (pclLevel (verbosity));
  // VTK's macros log each message to vtkLogger's stderr and hand it to the output window: the window alone prints.
  vtkLogger::SetStderrVerbosity (vtkLogger::VERBOSITY_OFF);
  if (!vtkOutputWindow::GetInstance ()->IsA ("VerbosityOutputWindow"))
    vtkOutputWindow::SetInstance (vtkSmartPointer<VerbosityOutputWindow>::New ());
}

void
printHeldErrors ()
{
  std::cerr << held_errors << std::flush;
  held_errors.clear ();
}

void
discardHeldErrors ()
{
  held_errors.clear ();
}

void
addVerbosityOptions (CLI::App& app)
{
  for (CLI::App* command : app.get_subcommands ({})) {
    CLI::Option* quiet = command->get_option_no_throw ("--quiet");
    if (quiet == nullptr)
      quiet = command->add_flag ("-q,--quiet");
    quiet->description ("no progress and no PCL or VTK messages on stderr");
    command->add_flag ("-v,--verbose", "also print PCL's and VTK's warnings and debug output")->excludes (quiet);
  }
  app.parse_complete_callback ([&app] {
    for (CLI::App* command : app.get_subcommands ()) {
      if (command->count ("--verbose") > 0)
        setVerbosity (Verbosity::verbose);
      else
        setVerbosity (command->count ("--quiet") > 0 ? Verbosity::quiet : Verbosity::normal);
    }
  });
}
} // namespace tools
} // namespace morphreg

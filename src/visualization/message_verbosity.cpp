// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/visualization/message_verbosity.h>

#include <pcl/console/print.h>

#include <vtkLogger.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>

#include <iostream>
#include <mutex>

namespace morphreg
{
namespace
{
MessageVerbosity current_verbosity = MessageVerbosity::normal;
std::mutex held_mutex;
std::string held_errors; ///< VTK's errors at the normal level, until takeHeldVtkErrors

/** Prints VTK's messages on stderr when verbose; holds its errors at the normal level; drops the rest. */
class VerbosityOutputWindow : public vtkOutputWindow
{
public:
  static VerbosityOutputWindow*
  New ();
  vtkTypeMacro (VerbosityOutputWindow, vtkOutputWindow);

  void
  DisplayText (const char* text) override
  {
    if (current_verbosity == MessageVerbosity::verbose)
      std::cerr << text << std::flush;
    else if (current_verbosity == MessageVerbosity::normal && GetCurrentMessageType () == MESSAGE_TYPE_ERROR) {
      const std::lock_guard<std::mutex> lock (held_mutex);
      held_errors += text;
    }
  }
};
vtkStandardNewMacro (VerbosityOutputWindow);

pcl::console::VERBOSITY_LEVEL
pclLevel (MessageVerbosity verbosity)
{
  switch (verbosity) {
  case MessageVerbosity::quiet:
    return pcl::console::L_ALWAYS;
  case MessageVerbosity::verbose:
    return pcl::console::L_DEBUG;
  default:
    return pcl::console::L_ERROR;
  }
}
} // namespace

void
setMessageVerbosity (MessageVerbosity verbosity)
{
  current_verbosity = verbosity;
  pcl::console::setVerbosityLevel (pclLevel (verbosity));
  // VTK's macros log each message to vtkLogger's stderr and hand it to the output window: the window alone prints.
  vtkLogger::SetStderrVerbosity (vtkLogger::VERBOSITY_OFF);
  if (!vtkOutputWindow::GetInstance ()->IsA ("VerbosityOutputWindow"))
    vtkOutputWindow::SetInstance (vtkSmartPointer<VerbosityOutputWindow>::New ());
}

std::string
takeHeldVtkErrors ()
{
  const std::lock_guard<std::mutex> lock (held_mutex);
  std::string errors;
  errors.swap (held_errors);
  return errors;
}
} // namespace morphreg

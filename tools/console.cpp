// SPDX-License-Identifier: BSD-3-Clause
// The CLI's verbosity options, applied to PCL's console and VTK's messages (visualization/message_verbosity.h).
#include "console.h"

#include <morphreg/visualization/message_verbosity.h>

namespace morphreg
{
namespace tools
{
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
        setMessageVerbosity (MessageVerbosity::verbose);
      else
        setMessageVerbosity (command->count ("--quiet") > 0 ? MessageVerbosity::quiet : MessageVerbosity::normal);
    }
  });
}
} // namespace tools
} // namespace morphreg

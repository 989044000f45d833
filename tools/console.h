// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// How much the CLI prints on stderr (-q, normal, --verbose), applied to PCL's console and VTK's messages too.
#include <CLI/CLI.hpp>

namespace morphreg
{
namespace tools
{
/** The CLI's levels of output on stderr. */
enum class Verbosity
{
  quiet,   ///< -q: no progress and no PCL or VTK messages (the command's own warnings and errors remain)
  normal,  ///< progress and the libraries' errors; their warnings and debug output hidden
  verbose, ///< --verbose: also PCL's and VTK's warnings and debug output
};

/** \brief Sets the verbosity of the process: PCL's console level and which VTK messages reach stderr.
 *  \param[in] verbosity the level; VTK's warnings and debug text are shown only when verbose, its errors unless
 *  quiet (held until the end in normal mode, see printHeldErrors).
 */
void
setVerbosity (Verbosity verbosity);

/** \brief Prints the VTK errors held back in normal mode (the command went on despite them) and forgets them. */
void
printHeldErrors ();

/** \brief Forgets the VTK errors held back in normal mode: the command failed with a message of its own. */
void
discardHeldErrors ();

/** \brief Adds -q,--quiet and -v,--verbose to every subcommand of \a app (keeping a subcommand's own --quiet) and
 *  sets the verbosity from them once the command line is parsed, before the subcommand runs.
 *  \param[in,out] app the CLI with its subcommands registered.
 */
void
addVerbosityOptions (CLI::App& app);
} // namespace tools
} // namespace morphreg

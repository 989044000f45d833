// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// How much the CLI prints on stderr (-q, normal, --verbose), applied to PCL's console and VTK's messages too
// (the library's setMessageVerbosity).
#include <CLI/CLI.hpp>

namespace morphreg
{
namespace tools
{
/** \brief Adds -q,--quiet and -v,--verbose to every subcommand of \a app (keeping a subcommand's own --quiet) and
 *  sets the libraries' message verbosity from them once the command line is parsed, before the subcommand runs.
 *  \param[in,out] app the CLI with its subcommands registered.
 */
void
addVerbosityOptions (CLI::App& app);
} // namespace tools
} // namespace morphreg

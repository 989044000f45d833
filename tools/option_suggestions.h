// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Unknown subcommands and options named before parsing, with the nearest known name: CLI11 reports a missing
// required option first, so `register --scna x` would otherwise say "--model is required".
#include <CLI/CLI.hpp>

#include <string>

namespace morphreg
{
namespace tools
{
/** \brief The message for the first unknown subcommand or option in \a argv ("" if every one is known), naming it
 *  and the closest known name when one is near (a few edits away).
 *  \param[in] app the command line with every subcommand registered
 *  \param[in] argc the argument count
 *  \param[in] argv the arguments
 *  \return e.g. "register: unknown option --scna; did you mean --scan?"
 */
std::string
unknownArgumentMessage (CLI::App& app, int argc, char** argv);
} // namespace tools
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file message_verbosity.h
 *  \brief How much PCL and VTK say on stderr in a program that registers and renders: PCL's console level, and a VTK
 *  output window that passes VTK's messages by type (a headless program need not print VTK's warnings, nor open
 *  VTK's message window).
 */
#include <string>

namespace morphreg
{
/** \brief Levels of the libraries' messages. */
enum class MessageVerbosity
{
  quiet,   ///< none of PCL's or VTK's messages
  normal,  ///< PCL's errors; VTK's errors held back (takeHeldVtkErrors), its warnings and debug text hidden
  verbose, ///< every PCL and VTK message, warnings and debug output included
};

/** \brief Sets PCL's console level and installs the VTK output window that filters by \a verbosity (once per
 *  process; later calls change the level).
 *  \param[in] verbosity the level */
void
setMessageVerbosity (MessageVerbosity verbosity);

/** \brief VTK's errors held back at MessageVerbosity::normal since the last call, which the caller prints when
 *  they matter (its task went on despite them) and drops when its own error message names the problem.
 *  \return the errors' text, and forgets it */
std::string
takeHeldVtkErrors ();
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Provenance of the CLI's outputs: every JSON report it writes or prints, and every model it builds, carries the
// morphreg version and the command line that made it.
#include <nlohmann/json.hpp>

#include <string>

namespace morphreg
{
namespace tools
{
/** \brief Records the command line (main's arguments) for provenanceJson; called once, first thing in main.
 *  \param[in] argc the argument count
 *  \param[in] argv the arguments
 */
void
recordCommandLine (int argc, const char* const* argv);

/** \brief The command line as a shell would take it back: arguments separated by spaces, quoted where needed.
 *  \return e.g. "morphreg register --scan 'my scan.ply'"
 */
std::string
commandLine ();

/** \brief {"version": "0.1.0", "command_line": commandLine ()}: what every report carries under "morphreg".
 *  \return the object
 */
nlohmann::json
provenanceJson ();

/** \brief \a report with provenanceJson () under its "morphreg" key.
 *  \param[in] report a JSON object
 *  \return the stamped report
 */
nlohmann::json
stamped (nlohmann::json report);

/** \brief Writes \a report, stamped, to \a path (atomically, as writeJsonFile).
 *  \param[in] path the JSON file
 *  \param[in] report the report
 */
void
writeReport (const std::string& path, const nlohmann::json& report);
} // namespace tools
} // namespace morphreg

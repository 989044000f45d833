// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file json_file.h
 *  \brief Reading a JSON file with errors that name it (nlohmann-json, a public dependency of the package).
 */
#include <nlohmann/json.hpp>

#include <string>

namespace morphreg
{
/** \brief Parses the JSON file \a path. Throws IoError if it is missing or unreadable, FormatError naming the file
 *  and the parser's message if it is not valid JSON.
 *  \param[in] path the file
 *  \return the parsed document
 */
nlohmann::json
readJsonFile (const std::string& path);

/** \brief Writes \a document to \a path (indented), atomically: whole or not at all (writeFileAtomically()); IoError
 *  naming the file if it cannot be written.
 *  \param[in] path the file
 *  \param[in] document the JSON to write
 */
void
writeJsonFile (const std::string& path, const nlohmann::json& document);

} // namespace morphreg

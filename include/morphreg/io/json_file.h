// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file json_file.h
 *  \brief Reading a JSON file with errors that name it (nlohmann-json, a public dependency of the package).
 */
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace morphreg
{
/** \brief Parses the JSON file \a path. Throws IoError if it is missing or unreadable, FormatError naming the file
 *  and the parser's message if it is not valid JSON.
 *  \param[in] path the file
 *  \return the parsed document
 */
nlohmann::json
readJsonFile (const std::string& path);

/** \brief The whole number \a value holds, checked: a JSON integer, or a number written with a point or an exponent
 *  that has no fraction (2.0, 1e3), from \a low to \a high. Anything else is a FormatError
 *  "<what> <value> is not a whole number" or "... is not from LOW to HIGH", never a value wrapped or truncated
 *  (4294967301 read as 5, 12.9 as 12).
 *  \param[in] value the JSON value
 *  \param[in] low the smallest value accepted
 *  \param[in] high the largest value accepted
 *  \param[in] what the file and the field, for the message (e.g. "regions.json: label of vertex 7")
 *  \return the number
 */
long long
jsonWholeNumber (const nlohmann::json& value, long long low, long long high, const std::string& what);

/** \brief jsonWholeNumber() of each element of the JSON array \a values, as int; FormatError if it is not an array.
 *  \param[in] values the JSON array
 *  \param[in] low the smallest value accepted
 *  \param[in] high the largest value accepted
 *  \param[in] what the file and the field, for the messages (each element's adds "element <k>")
 *  \return the numbers
 */
std::vector<int>
jsonWholeNumbers (const nlohmann::json& values, int low, int high, const std::string& what);

/** \brief Writes \a document to \a path (indented), atomically: whole or not at all (writeFileAtomically()); IoError
 *  naming the file if it cannot be written.
 *  \param[in] path the file
 *  \param[in] document the JSON to write
 */
void
writeJsonFile (const std::string& path, const nlohmann::json& document);

} // namespace morphreg

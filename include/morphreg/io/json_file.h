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
 */
nlohmann::json
readJsonFile (const std::string& path);

} // namespace morphreg

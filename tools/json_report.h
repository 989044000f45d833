#pragma once
// JSON reports of the CLI commands.
#include <nlohmann/json.hpp>

#include <string>

namespace morphreg
{
namespace tools
{
/** Writes \a json, indented, to \a path; throws IoError naming the file on failure. */
void
writeJsonReport (const std::string& path, const nlohmann::json& json);

} // namespace tools
} // namespace morphreg

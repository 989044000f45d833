// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/json_file.h>

#include <fstream>

namespace morphreg
{
nlohmann::json
readJsonFile (const std::string& path)
{
  requireReadableFile (path);
  std::ifstream stream (path);
  try {
    return nlohmann::json::parse (stream);
  }
  catch (const nlohmann::json::exception& e) {
    throw FormatError (path + ": malformed JSON (" + e.what () + ")");
  }
}

void
writeJsonFile (const std::string& path, const nlohmann::json& document)
{
  writeFileAtomically (path, document.dump (2) + '\n');
}

} // namespace morphreg

#include "json_report.h"

#include <morphreg/common/error.h>

#include <fstream>
#include <iomanip>

namespace morphreg
{
namespace tools
{
void
writeJsonReport (const std::string& path, const nlohmann::json& json)
{
  std::ofstream stream (path);
  stream << std::setw (2) << json << '\n';
  if (!stream)
    throw IoError (path + ": cannot write the report");
}
} // namespace tools
} // namespace morphreg

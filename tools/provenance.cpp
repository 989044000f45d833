// SPDX-License-Identifier: BSD-3-Clause
#include "provenance.h"

#include <morphreg/io/json_file.h>

#include <vector>

namespace morphreg
{
namespace tools
{
namespace
{
std::vector<std::string>&
arguments ()
{
  static std::vector<std::string> recorded;
  return recorded;
}

/** \a argument as a shell word: as it is when it holds only safe characters, otherwise in single quotes. */
std::string
shellWord (const std::string& argument)
{
  const std::string safe = "abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=./:,@%";
  if (!argument.empty () && argument.find_first_not_of (safe) == std::string::npos)
    return argument;
  std::string quoted = "'";
  for (char c : argument)
    quoted += c == '\'' ? std::string ("'\\''") : std::string (1, c);
  return quoted + "'";
}
} // namespace

void
recordCommandLine (int argc, const char* const* argv)
{
  arguments ().assign (argv, argv + argc);
}

std::string
commandLine ()
{
  std::string line;
  for (const std::string& argument : arguments ())
    line += (line.empty () ? "" : " ") + shellWord (argument);
  return line;
}

nlohmann::json
provenanceJson ()
{
  return {{"version", MORPHREG_VERSION}, {"command_line", commandLine ()}};
}

nlohmann::json
stamped (nlohmann::json report)
{
  report["morphreg"] = provenanceJson ();
  return report;
}

void
writeReport (const std::string& path, const nlohmann::json& report)
{
  writeJsonFile (path, stamped (report));
}
} // namespace tools
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private helpers of the line-based readers (landmark CSV, scan manifests): trimming and splitting fields.
#include <sstream>
#include <string>
#include <vector>

namespace morphreg
{
namespace text
{
/** \a text without leading and trailing white space. */
inline std::string
trim (const std::string& text)
{
  const auto first = text.find_first_not_of (" \t\r\n");
  if (first == std::string::npos)
    return "";
  return text.substr (first, text.find_last_not_of (" \t\r\n") - first + 1);
}

/** The comma-separated fields of \a line, trimmed; a trailing comma gives a last empty field. */
inline std::vector<std::string>
splitCsvFields (const std::string& line)
{
  std::vector<std::string> fields;
  std::istringstream stream (line);
  for (std::string field; std::getline (stream, field, ',');)
    fields.push_back (trim (field));
  if (!line.empty () && line.back () == ',')
    fields.emplace_back ();
  return fields;
}
} // namespace text
} // namespace morphreg

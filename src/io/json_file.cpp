// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/json_file.h>

#include <cmath>
#include <cstdint>
#include <fstream>

namespace morphreg
{
nlohmann::json
readJsonFile (const std::string& path)
{
  requireReadableFile (path, kMaxTextFileBytes);
  std::ifstream stream (path);
  try {
    return nlohmann::json::parse (stream);
  }
  catch (const nlohmann::json::exception& e) {
    throw FormatError (path + ": malformed JSON (" + e.what () + ")");
  }
}

long long
jsonWholeNumber (const nlohmann::json& value, long long low, long long high, const std::string& what)
{
  const std::string range = " is not from " + std::to_string (low) + " to " + std::to_string (high);
  if (value.is_number_unsigned ()) {
    if (value.get<std::uint64_t> () > static_cast<std::uint64_t> (high) || high < 0)
      throw FormatError (what + " " + value.dump () + range);
    return static_cast<long long> (value.get<std::uint64_t> ());
  }
  if (value.is_number_integer ()) {
    const long long number = value.get<long long> ();
    if (number < low || number > high)
      throw FormatError (what + " " + value.dump () + range);
    return number;
  }
  if (!value.is_number ())
    throw FormatError (what + " " + value.dump () + " is not a number");
  const double number = value.get<double> ();
  if (!std::isfinite (number) || number != std::floor (number))
    throw FormatError (what + " " + value.dump () + " is not a whole number");
  if (number < static_cast<double> (low) || number > static_cast<double> (high))
    throw FormatError (what + " " + value.dump () + range);
  return static_cast<long long> (number);
}

std::vector<int>
jsonWholeNumbers (const nlohmann::json& values, int low, int high, const std::string& what)
{
  if (!values.is_array ())
    throw FormatError (what + " is not an array of whole numbers");
  std::vector<int> numbers;
  numbers.reserve (values.size ());
  for (std::size_t k = 0; k < values.size (); ++k)
    numbers.push_back (
        static_cast<int> (jsonWholeNumber (values[k], low, high, what + " element " + std::to_string (k))));
  return numbers;
}

void
writeJsonFile (const std::string& path, const nlohmann::json& document)
{
  writeFileAtomically (path, document.dump (2) + '\n');
}

} // namespace morphreg

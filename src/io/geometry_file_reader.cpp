// SPDX-License-Identifier: BSD-3-Clause
#include "geometry_file_reader.h"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <limits>
#include <sstream>

namespace morphreg
{
namespace validation
{
GeometryFileReader::GeometryFileReader (const std::string& path) : path_ (path), stream_ (path, std::ios::binary)
{
  std::error_code ec;
  size_ = std::filesystem::file_size (path, ec);
  if (!stream_ || ec)
    throw IoError (path + ": cannot be opened for reading");
}

bool
GeometryFileReader::nextLine (std::string& line)
{
  if (!std::getline (stream_, line))
    return false;
  ++line_number_;
  offset_ += line.size () + (stream_.eof () ? 0 : 1);
  if (!line.empty () && line.back () == '\r')
    line.pop_back ();
  return true;
}

bool
GeometryFileReader::readBytes (char* out, std::uint64_t bytes)
{
  stream_.read (out, static_cast<std::streamsize> (bytes));
  offset_ += static_cast<std::uint64_t> (stream_.gcount ());
  return static_cast<std::uint64_t> (stream_.gcount ()) == bytes;
}

bool
GeometryFileReader::skipBytes (std::uint64_t bytes)
{
  if (bytes > remaining ())
    return false;
  // Short skips stay in the stream's buffer; a seek would drop it and read the file again.
  if (bytes < (1u << 20))
    stream_.ignore (static_cast<std::streamsize> (bytes));
  else
    stream_.seekg (static_cast<std::streamoff> (bytes), std::ios::cur);
  offset_ += bytes;
  return static_cast<bool> (stream_);
}

void
splitTokens (std::string_view line, std::vector<std::string_view>& tokens)
{
  tokens.clear ();
  const auto is_space = [] (char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v'; };
  std::size_t i = 0;
  while (i < line.size ()) {
    while (i < line.size () && is_space (line[i]))
      ++i;
    const std::size_t start = i;
    while (i < line.size () && !is_space (line[i]))
      ++i;
    if (i > start)
      tokens.push_back (line.substr (start, i - start));
  }
}

bool
parseInteger (std::string_view token, long long& value)
{
  if (token.size () > 1 && token[0] == '+')
    token.remove_prefix (1);
  const auto [end, ec] = std::from_chars (token.data (), token.data () + token.size (), value);
  return ec == std::errc () && end == token.data () + token.size () && !token.empty ();
}

bool
parseNumber (std::string_view token, double& value)
{
  if (token.size () > 1 && token[0] == '+')
    token.remove_prefix (1);
  const auto [end, ec] = std::from_chars (token.data (), token.data () + token.size (), value);
  return ec == std::errc () && end == token.data () + token.size () && !token.empty ();
}

bool
isFiniteFloat (std::string_view token)
{
  double value = 0.0;
  return parseNumber (token, value) && std::isfinite (value) &&
         std::abs (value) <= static_cast<double> (std::numeric_limits<float>::max ());
}

std::string
describeBytes (double bytes)
{
  const char* units[] = {"bytes", "KB", "MB", "GB", "TB", "PB", "EB"};
  int unit = 0;
  while (bytes >= 1000.0 && unit < 6) {
    bytes /= 1000.0;
    ++unit;
  }
  std::ostringstream text;
  text << (unit == 0 ? bytes : std::round (bytes * 10.0) / 10.0) << " " << units[unit];
  return text.str ();
}

FormatError
countBeyondFile (const std::string& path, std::uint64_t count, double item_bytes, std::uint64_t available,
                 const std::string& what)
{
  return FormatError (path + ": header claims " + std::to_string (count) + " " + what + " (at least " +
                      describeBytes (static_cast<double> (count) * item_bytes) + ") but the file holds " +
                      describeBytes (static_cast<double> (available)) +
                      " after its header; the file is cut short or its header is wrong");
}

void
requireCountFits (const std::string& path, std::uint64_t count, double item_bytes, std::uint64_t available,
                  const std::string& what, bool text)
{
  if (static_cast<double> (count) * item_bytes > static_cast<double> (available) + (text ? 1.0 : 0.0))
    throw countBeyondFile (path, count, item_bytes, available, what);
}

} // namespace validation
} // namespace morphreg

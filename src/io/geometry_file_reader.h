// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private to the geometry file validators: a file read line by line (or in raw bytes) that knows its size and the
// current line number, whitespace tokenising without copies, and number parsing.
#include <morphreg/common/error.h>

#include <cstdint>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

namespace morphreg
{
namespace validation
{
/** A file opened for validation: lines with their numbers, raw bytes, and errors that name the file and line. */
class GeometryFileReader
{
public:
  /** Opens \a path; IoError if it cannot be read. */
  explicit GeometryFileReader (const std::string& path);

  /** Reads the next line into \a line without its end ("\n" or "\r\n"); false at the end of the file. */
  bool
  nextLine (std::string& line);

  /** Reads \a bytes raw bytes into \a out; false if the file ends first. */
  bool
  readBytes (char* out, std::uint64_t bytes);

  /** Skips \a bytes raw bytes; false if the file ends first. */
  bool
  skipBytes (std::uint64_t bytes);

  /** The offset of the next byte to be read. */
  std::uint64_t
  offset () const
  {
    return offset_;
  }

  /** The bytes from the next one to be read to the end of the file. */
  std::uint64_t
  remaining () const
  {
    return offset_ < size_ ? size_ - offset_ : 0;
  }

  /** The file's size in bytes. */
  std::uint64_t
  size () const
  {
    return size_;
  }

  /** The number of the line read last (1-based). */
  std::uint64_t
  lineNumber () const
  {
    return line_number_;
  }

  /** "path:line" of the line read last. */
  std::string
  where () const
  {
    return path_ + ":" + std::to_string (line_number_);
  }

  /** The file's path. */
  const std::string&
  path () const
  {
    return path_;
  }

  /** Throws FormatError "path:line: problem". */
  [[noreturn]] void
  failAtLine (const std::string& problem) const
  {
    throw FormatError (where () + ": " + problem);
  }

  /** Throws FormatError "path: problem". */
  [[noreturn]] void
  fail (const std::string& problem) const
  {
    throw FormatError (path_ + ": " + problem);
  }

private:
  std::string path_;
  std::ifstream stream_;
  std::uint64_t size_ = 0;
  std::uint64_t offset_ = 0;
  std::uint64_t line_number_ = 0;
};

/** Splits \a line at white space into \a tokens (views into \a line). */
void
splitTokens (std::string_view line, std::vector<std::string_view>& tokens);

/** Parses \a token as a whole decimal number (a leading '+' allowed); false if it is not one. */
bool
parseInteger (std::string_view token, long long& value);

/** Parses \a token as a number, "nan" and "inf" included (a leading '+' allowed); false if it is not one. */
bool
parseNumber (std::string_view token, double& value);

/** True if \a token is a number that a float holds finitely (not NaN, not infinite, not beyond FLT_MAX). */
bool
isFiniteFloat (std::string_view token);

/** "212 bytes", "24 GB": \a bytes for messages. */
std::string
describeBytes (double bytes);

/** The FormatError of requireCountFits(): "file: header claims 2000000000 points (at least 24 GB) but the file holds
 *  12 bytes after its header; ...".
 */
FormatError
countBeyondFile (const std::string& path, std::uint64_t count, double item_bytes, std::uint64_t available,
                 const std::string& what);

/** Throws FormatError naming the file unless \a count items of at least \a item_bytes each fit in the \a available
 *  bytes after the header: "file: header claims 2000000000 points (at least 24 GB) but the file holds 12 bytes after
 *  its header". \a what names the items ("points", "'vertex' elements"). In \a text, the last item may lack its
 *  final separator (a file without a last line end).
 */
void
requireCountFits (const std::string& path, std::uint64_t count, double item_bytes, std::uint64_t available,
                  const std::string& what, bool text = false);

} // namespace validation
} // namespace morphreg

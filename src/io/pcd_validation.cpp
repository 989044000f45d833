#include "geometry_file_reader.h"
#include "geometry_validators.h"

#include <algorithm>
#include <limits>

namespace morphreg
{
namespace validation
{
namespace
{
/** LZF, PCL's binary_compressed codec, at best turns 3 bytes into 264 (one back reference). */
constexpr double max_lzf_expansion = 88.0;

struct PcdHeader
{
  std::vector<std::string> fields;
  std::vector<long long> sizes;
  std::vector<std::string> types;
  std::vector<long long> counts;
  long long width = -1;
  long long height = -1;
  long long points = -1;
  std::string data;
};

std::vector<long long>
parseIntegers (const GeometryFileReader& reader, const std::vector<std::string_view>& tokens, long long low,
               long long high)
{
  std::vector<long long> values;
  for (std::size_t i = 1; i < tokens.size (); ++i) {
    long long value = 0;
    if (!parseInteger (tokens[i], value) || value < low || value > high)
      reader.failAtLine (std::string (tokens[0]) + " value '" + std::string (tokens[i]) +
                         "' is not a whole number in [" + std::to_string (low) + ", " + std::to_string (high) + "]");
    values.push_back (value);
  }
  return values;
}

long long
parseOneInteger (const GeometryFileReader& reader, const std::vector<std::string_view>& tokens)
{
  if (tokens.size () != 2)
    reader.failAtLine (std::string (tokens[0]) + " must be followed by one number");
  return parseIntegers (reader, tokens, 0, std::numeric_limits<long long>::max () / 2).front ();
}

/** One header line other than DATA into \a header. */
void
parseHeaderLine (const GeometryFileReader& reader, const std::vector<std::string_view>& tokens, PcdHeader& header)
{
  const std::string_view keyword = tokens[0];
  const std::vector<std::string> words (tokens.begin () + 1, tokens.end ());
  if (keyword == "VERSION")
    return;
  if (keyword == "FIELDS" || keyword == "COLUMNS")
    header.fields = words;
  else if (keyword == "SIZE")
    header.sizes = parseIntegers (reader, tokens, 1, 8);
  else if (keyword == "TYPE")
    header.types = words;
  else if (keyword == "COUNT")
    header.counts = parseIntegers (reader, tokens, 1, 1 << 20);
  else if (keyword == "WIDTH")
    header.width = parseOneInteger (reader, tokens);
  else if (keyword == "HEIGHT")
    header.height = parseOneInteger (reader, tokens);
  else if (keyword == "POINTS")
    header.points = parseOneInteger (reader, tokens);
  else if (keyword == "VIEWPOINT") {
    if (tokens.size () != 8 || !std::all_of (tokens.begin () + 1, tokens.end (), isFiniteFloat))
      reader.failAtLine ("VIEWPOINT must be followed by 7 finite numbers (tx ty tz qw qx qy qz)");
  }
  else
    reader.failAtLine ("unexpected PCD header line starting with '" + std::string (keyword.substr (0, 40)) + "'");
}

PcdHeader
parseHeader (GeometryFileReader& reader)
{
  PcdHeader header;
  std::string line;
  std::vector<std::string_view> tokens;
  while (header.data.empty ()) {
    if (!reader.nextLine (line))
      reader.fail ("the PCD header has no DATA line (the file is cut short or not a PCD file)");
    splitTokens (line, tokens);
    if (tokens.empty () || tokens[0][0] == '#')
      continue;
    if (tokens[0] != "DATA")
      parseHeaderLine (reader, tokens, header);
    else if (tokens.size () == 2 && (tokens[1] == "ascii" || tokens[1] == "binary" || tokens[1] == "binary_compressed"))
      header.data = std::string (tokens[1]);
    else
      reader.failAtLine ("the DATA line must be 'DATA ascii', 'DATA binary' or 'DATA binary_compressed'");
  }
  return header;
}

/** FIELDS, SIZE, TYPE and COUNT agree, the types are valid, and WIDTH * HEIGHT = POINTS. Returns a point's bytes. */
std::uint64_t
checkHeader (const GeometryFileReader& reader, PcdHeader& header)
{
  const std::size_t n = header.fields.size ();
  if (n == 0)
    reader.fail ("the PCD header has no FIELDS");
  if (header.counts.empty ())
    header.counts.assign (n, 1);
  if (header.sizes.size () != n || header.types.size () != n || header.counts.size () != n)
    reader.fail ("the PCD header lists " + std::to_string (n) + " FIELDS but " + std::to_string (header.sizes.size ()) +
                 " SIZE, " + std::to_string (header.types.size ()) + " TYPE and " +
                 std::to_string (header.counts.size ()) + " COUNT values");
  std::uint64_t point_bytes = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const std::string& type = header.types[i];
    const long long size = header.sizes[i];
    const bool valid = (type == "F" && (size == 4 || size == 8)) ||
                       ((type == "I" || type == "U") && (size == 1 || size == 2 || size == 4 || size == 8));
    if (!valid)
      reader.fail ("PCD field '" + header.fields[i] + "' has TYPE " + type + " and SIZE " + std::to_string (size) +
                   ", which is not a valid pair (F 4|8, I or U 1|2|4|8)");
    point_bytes += static_cast<std::uint64_t> (size * header.counts[i]);
  }
  if (header.width < 0 || header.height < 0 || header.points < 0)
    reader.fail ("the PCD header lacks WIDTH, HEIGHT or POINTS");
  if (static_cast<double> (header.width) * static_cast<double> (header.height) != static_cast<double> (header.points))
    reader.fail ("the PCD header's WIDTH " + std::to_string (header.width) + " times HEIGHT " +
                 std::to_string (header.height) + " is not its POINTS " + std::to_string (header.points));
  return point_bytes;
}

std::uint32_t
littleEndian32 (const unsigned char* bytes)
{
  return static_cast<std::uint32_t> (bytes[0]) | static_cast<std::uint32_t> (bytes[1]) << 8 |
         static_cast<std::uint32_t> (bytes[2]) << 16 | static_cast<std::uint32_t> (bytes[3]) << 24;
}

/** binary_compressed: the compressed and unpacked sizes that precede the data agree with the file and POINTS. */
void
checkCompressed (GeometryFileReader& reader, const PcdHeader& header, std::uint64_t point_bytes)
{
  unsigned char sizes[8];
  if (!reader.readBytes (reinterpret_cast<char*> (sizes), 8))
    reader.fail ("the compressed PCD data has no sizes (the file is cut short)");
  const std::uint64_t compressed = littleEndian32 (sizes);
  const std::uint64_t unpacked = littleEndian32 (sizes + 4);
  const double expected = static_cast<double> (header.points) * static_cast<double> (point_bytes);
  if (compressed > reader.remaining ())
    reader.fail ("the compressed PCD data claims " + std::to_string (compressed) + " bytes but the file holds " +
                 std::to_string (reader.remaining ()) + " after its header (the file is cut short)");
  if (static_cast<double> (unpacked) != expected)
    reader.fail ("the compressed PCD data unpacks to " + std::to_string (unpacked) + " bytes but POINTS " +
                 std::to_string (header.points) + " of " + std::to_string (point_bytes) + " bytes need " +
                 describeBytes (expected));
  if (static_cast<double> (unpacked) > max_lzf_expansion * static_cast<double> (compressed))
    reader.fail ("the compressed PCD data (" + std::to_string (compressed) + " bytes) cannot unpack to the " +
                 std::to_string (unpacked) + " bytes its header claims");
}

/** The token of each value of a point, in order, is a number of its field's type ("nan" allowed for F). */
void
checkAsciiPoints (GeometryFileReader& reader, const PcdHeader& header)
{
  std::string value_types;
  for (std::size_t i = 0; i < header.fields.size (); ++i)
    value_types.append (static_cast<std::size_t> (header.counts[i]), header.types[i][0]);
  std::string line;
  std::vector<std::string_view> tokens;
  for (long long point = 0; point < header.points;) {
    if (!reader.nextLine (line))
      reader.fail ("the file ends after " + std::to_string (point) + " of its " + std::to_string (header.points) +
                   " points (the data is cut short)");
    splitTokens (line, tokens);
    if (tokens.empty ())
      continue;
    if (tokens.size () != value_types.size ())
      reader.failAtLine ("point " + std::to_string (point) + " has " + std::to_string (tokens.size ()) +
                         " values, expected " + std::to_string (value_types.size ()));
    for (std::size_t v = 0; v < tokens.size (); ++v) {
      double number = 0.0;
      long long whole = 0;
      const bool ok = value_types[v] == 'F' ? parseNumber (tokens[v], number)
                                            : parseInteger (tokens[v], whole) && (value_types[v] == 'I' || whole >= 0);
      if (!ok)
        reader.failAtLine ("value '" + std::string (tokens[v]) + "' of point " + std::to_string (point) +
                           " is not a number of its field's type " + value_types[v]);
    }
    ++point;
  }
}
} // namespace

void
validatePcdFile (const std::string& path)
{
  GeometryFileReader reader (path);
  PcdHeader header = parseHeader (reader);
  const std::uint64_t point_bytes = checkHeader (reader, header);
  const auto points = static_cast<std::uint64_t> (header.points);
  if (header.data == "binary")
    requireCountFits (path, points, static_cast<double> (point_bytes), reader.remaining (), "points");
  else if (header.data == "binary_compressed")
    checkCompressed (reader, header, point_bytes);
  else {
    std::uint64_t values = 0;
    for (long long count : header.counts)
      values += static_cast<std::uint64_t> (count);
    requireCountFits (path, points, 2.0 * static_cast<double> (values), reader.remaining (), "points", true);
    checkAsciiPoints (reader, header);
  }
}

} // namespace validation
} // namespace morphreg

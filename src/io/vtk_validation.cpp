#include "geometry_file_reader.h"
#include "geometry_validators.h"

#include <algorithm>
#include <cctype>
#include <limits>
#include <map>

namespace morphreg
{
namespace validation
{
namespace
{
/** The file after its header: keyword lines, then each section's values, as text tokens (ASCII) or raw big-endian
 *  numbers (BINARY).
 */
struct VtkSource
{
  explicit VtkSource (GeometryFileReader& file) : reader (file) {}

  GeometryFileReader& reader;
  bool binary = false;
  int major_version = 0;
  std::string line;
  std::vector<std::string_view> tokens;
  std::size_t next = 0;
};

std::string
upper (std::string_view text)
{
  std::string result (text);
  for (char& c : result)
    c = static_cast<char> (std::toupper (static_cast<unsigned char> (c)));
  return result;
}

/** The bytes of one value of a VTK data type; 0 if the type is unknown. */
int
typeBytes (std::string_view type)
{
  static const std::map<std::string, int> sizes = {
      {"BIT", 1},    {"CHAR", 1},         {"UNSIGNED_CHAR", 1}, {"SHORT", 2},    {"UNSIGNED_SHORT", 2},
      {"INT", 4},    {"UNSIGNED_INT", 4}, {"FLOAT", 4},         {"LONG", 8},     {"UNSIGNED_LONG", 8},
      {"DOUBLE", 8}, {"VTKTYPEINT64", 8}, {"VTKTYPEINT32", 4},  {"VTKIDTYPE", 8}};
  const auto size = sizes.find (upper (type));
  return size == sizes.end () ? 0 : size->second;
}

/** The next non-blank line as keyword tokens; false at the end of the file. In ASCII the previous section's values
 *  must have been used up: a leftover token means the section holds more values than its header says.
 */
bool
nextKeywordLine (VtkSource& source)
{
  if (source.next < source.tokens.size ())
    source.reader.failAtLine ("'" + std::string (source.tokens[source.next]) +
                              "' is one value more than the section's header claims");
  while (source.reader.nextLine (source.line)) {
    splitTokens (source.line, source.tokens);
    source.next = source.tokens.size ();
    if (!source.tokens.empty ())
      return true;
  }
  return false;
}

/** The next ASCII value, across lines; FormatError if the file ends first. */
std::string_view
nextToken (VtkSource& source, const std::string& what)
{
  while (source.next >= source.tokens.size ()) {
    if (!source.reader.nextLine (source.line))
      source.reader.fail ("the file ends inside the " + what + " (the file is cut short or its header claims more)");
    splitTokens (source.line, source.tokens);
    source.next = 0;
  }
  return source.tokens[source.next++];
}

/** The next whole number of \a bytes bytes (BINARY) or the next token (ASCII). */
long long
nextInteger (VtkSource& source, int bytes, const std::string& what)
{
  if (source.binary) {
    unsigned char raw[8];
    if (!source.reader.readBytes (reinterpret_cast<char*> (raw), static_cast<std::uint64_t> (bytes)))
      source.reader.fail ("the file ends inside the " + what + " (the file is cut short or its header claims more)");
    std::uint64_t bits = 0;
    for (int i = 0; i < bytes; ++i)
      bits = (bits << 8) | raw[i];
    return bytes == 4 ? static_cast<long long> (static_cast<std::int32_t> (bits)) : static_cast<long long> (bits);
  }
  const std::string_view token = nextToken (source, what);
  long long value = 0;
  if (!parseInteger (token, value))
    source.reader.failAtLine ("'" + std::string (token) + "' in the " + what + " is not a whole number");
  return value;
}

/** A count from a section header; \a what names it for the message. */
long long
headerCount (const VtkSource& source, std::size_t i, const std::string& what)
{
  long long value = -1;
  if (i >= source.tokens.size () || !parseInteger (source.tokens[i], value) || value < 0)
    source.reader.failAtLine ("the " + what + " is missing or not a whole number of 0 or more");
  return value;
}

/** A problem in a section's values: at the line in ASCII, in the file in BINARY. */
[[noreturn]] void
failInData (const VtkSource& source, const std::string& problem)
{
  if (source.binary)
    source.reader.fail (problem);
  source.reader.failAtLine (problem);
}

void
checkPointIndex (const VtkSource& source, long long index, long long points, const std::string& section)
{
  if (index < 0 || index >= points)
    failInData (source, section + " index " + std::to_string (index) + " is outside the " + std::to_string (points) +
                            " points [0, " + std::to_string (points) + ")");
}

/** \a count values of \a bytes bytes each (BINARY) or \a count numbers (ASCII; finite ones if \a finite). */
void
checkValues (VtkSource& source, std::uint64_t count, int bytes, bool finite, const std::string& what)
{
  requireCountFits (source.reader.path (), count, source.binary ? bytes : 2.0, source.reader.remaining (),
                    what + " values", !source.binary);
  if (source.binary) {
    if (!source.reader.skipBytes (count * static_cast<std::uint64_t> (bytes)))
      source.reader.fail ("the file ends inside the " + what + " (the file is cut short)");
    return;
  }
  double number = 0.0;
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::string_view token = nextToken (source, what);
    if (finite ? !isFiniteFloat (token) : !parseNumber (token, number))
      source.reader.failAtLine (what + " value '" + std::string (token) + "' is not a" +
                                (finite ? " finite number" : " number"));
  }
}

/** "POINTS n type" and its 3n values; returns n. */
long long
checkPoints (VtkSource& source)
{
  const long long points = headerCount (source, 1, "point count");
  const int bytes = source.tokens.size () == 3 ? typeBytes (source.tokens[2]) : 0;
  if (bytes == 0)
    source.reader.failAtLine ("POINTS must be followed by a count and a data type (e.g. 'POINTS 8 float')");
  requireCountFits (source.reader.path (), static_cast<std::uint64_t> (points), source.binary ? 3.0 * bytes : 6.0,
                    source.reader.remaining (), "points", !source.binary);
  checkValues (source, 3 * static_cast<std::uint64_t> (points), bytes, true, "point coordinate");
  return points;
}

/** The classic layout: \a cells cells of "k i_1 .. i_k", \a size values in all. */
void
checkClassicCells (VtkSource& source, long long points, const std::string& section, long long cells, long long size)
{
  requireCountFits (source.reader.path (), static_cast<std::uint64_t> (size), source.binary ? 4.0 : 2.0,
                    source.reader.remaining (), section + " values", !source.binary);
  long long used = 0;
  for (long long c = 0; c < cells; ++c) {
    const long long corners = nextInteger (source, 4, section);
    if (corners < 0 || used + 1 + corners > size)
      failInData (source, section + " cell " + std::to_string (c) + " has " + std::to_string (corners) +
                              " indices, beyond the " + std::to_string (size) + " values the section's header claims");
    used += 1 + corners;
    for (long long i = 0; i < corners; ++i)
      checkPointIndex (source, nextInteger (source, 4, section), points, section);
  }
  if (used != size)
    failInData (source, "the " + section + " cells hold " + std::to_string (used) +
                            " values but the section's header "
                            "claims " +
                            std::to_string (size));
}

/** The next keyword line must be "<keyword> <type>"; returns the type's bytes. */
int
expectArrayLine (VtkSource& source, const std::string& keyword, long long count)
{
  if (!nextKeywordLine (source) || upper (source.tokens[0]) != keyword || source.tokens.size () != 2 ||
      typeBytes (source.tokens[1]) == 0)
    source.reader.failAtLine ("expected '" + keyword + " <type>' (e.g. vtktypeint64)");
  const int bytes = typeBytes (source.tokens[1]);
  requireCountFits (source.reader.path (), static_cast<std::uint64_t> (count), source.binary ? bytes : 2.0,
                    source.reader.remaining (), keyword + " values", !source.binary);
  return bytes;
}

/** The layout of format 5: \a offsets offsets (0, nondecreasing, ending at \a size), then \a size indices. */
void
checkOffsetCells (VtkSource& source, long long points, const std::string& section, long long offsets, long long size)
{
  int bytes = expectArrayLine (source, "OFFSETS", offsets);
  long long previous = 0;
  for (long long i = 0; i < offsets; ++i) {
    const long long offset = nextInteger (source, bytes, section + " offsets");
    if ((i == 0 && offset != 0) || offset < previous || offset > size)
      failInData (source, section + " offset " + std::to_string (i) + " is " + std::to_string (offset) +
                              "; offsets must start at 0 and rise to the connectivity size " + std::to_string (size));
    previous = offset;
  }
  if (previous != size)
    failInData (source, "the last " + section + " offset " + std::to_string (previous) +
                            " is not the connectivity size " + std::to_string (size));
  bytes = expectArrayLine (source, "CONNECTIVITY", size);
  for (long long i = 0; i < size; ++i)
    checkPointIndex (source, nextInteger (source, bytes, section + " connectivity"), points, section);
}

/** "# vtk DataFile Version x.y", a title, ASCII or BINARY, "DATASET POLYDATA". */
void
checkHeader (VtkSource& source)
{
  GeometryFileReader& reader = source.reader;
  reader.nextLine (source.line);
  const std::size_t version = source.line.find_first_of ("0123456789");
  long long major = 0;
  if (version == std::string::npos ||
      !parseInteger (std::string_view (source.line).substr (version, source.line.find ('.', version) - version), major))
    reader.failAtLine ("the first line must be '# vtk DataFile Version <major>.<minor>'");
  source.major_version = static_cast<int> (major);
  std::string encoding;
  if (!reader.nextLine (source.line) || !reader.nextLine (encoding))
    reader.fail ("the VTK header is cut short");
  splitTokens (encoding, source.tokens);
  const std::string word = source.tokens.size () == 1 ? upper (source.tokens[0]) : "";
  if (word != "ASCII" && word != "BINARY")
    reader.failAtLine ("the third line must be ASCII or BINARY");
  source.binary = word == "BINARY";
  source.next = source.tokens.size ();
  if (!nextKeywordLine (source) || upper (source.tokens[0]) != "DATASET" || source.tokens.size () != 2)
    reader.failAtLine ("expected 'DATASET POLYDATA'");
  if (upper (source.tokens[1]) != "POLYDATA")
    reader.failAtLine ("the dataset is " + std::string (source.tokens[1]) +
                       "; only POLYDATA (polygon meshes and point sets) can be read");
}

/** A METADATA block runs up to the next blank line. */
void
skipMetadata (VtkSource& source)
{
  while (source.reader.nextLine (source.line) && source.line.find_first_not_of (" \t") != std::string::npos)
    continue;
}

/** \a a * \a b values, FormatError if that overflows. */
std::uint64_t
valueCount (const VtkSource& source, long long a, long long b)
{
  if (a != 0 && b > std::numeric_limits<long long>::max () / a)
    source.reader.failAtLine ("the section's sizes overflow");
  return static_cast<std::uint64_t> (a * b);
}

/** The data type at token \a i of the current line, by its bytes. */
int
typeAt (const VtkSource& source, std::size_t i)
{
  const int bytes = i < source.tokens.size () ? typeBytes (source.tokens[i]) : 0;
  if (bytes == 0)
    source.reader.failAtLine ("'" + std::string (source.tokens[0]) + "' needs a data type as its word " +
                              std::to_string (i + 1));
  return bytes;
}

/** A FIELD's arrays, each "<name> <components> <tuples> <type>" and its values. */
void
checkFieldArrays (VtkSource& source, long long arrays)
{
  for (long long a = 0; a < arrays; ++a) {
    if (!nextKeywordLine (source))
      source.reader.fail ("the file ends inside a FIELD (the file is cut short)");
    if (upper (source.tokens[0]) == "METADATA") {
      skipMetadata (source);
      --a;
      continue;
    }
    if (source.tokens.size () != 4)
      source.reader.failAtLine ("expected a FIELD array '<name> <components> <tuples> <type>'");
    const std::uint64_t values =
        valueCount (source, headerCount (source, 1, "component count"), headerCount (source, 2, "tuple count"));
    checkValues (source, values, typeAt (source, 3), false, "FIELD array");
  }
}

/** One attribute of a POINT_DATA or CELL_DATA section of \a tuples tuples: its header line (read) and its values. */
void
checkAttribute (VtkSource& source, long long tuples)
{
  const std::string keyword = upper (source.tokens[0]);
  if (keyword == "NORMALS" || keyword == "VECTORS" || keyword == "TENSORS")
    checkValues (source, valueCount (source, keyword == "TENSORS" ? 9 : 3, tuples), typeAt (source, 2), false, keyword);
  else if (keyword == "TEXTURE_COORDINATES")
    checkValues (source, valueCount (source, headerCount (source, 2, "dimension"), tuples), typeAt (source, 3), false,
                 keyword);
  else if (keyword == "COLOR_SCALARS")
    checkValues (source, valueCount (source, headerCount (source, 2, "component count"), tuples), 1, false, keyword);
  else if (keyword == "SCALARS") {
    const int bytes = typeAt (source, 2);
    const long long components = source.tokens.size () > 3 ? headerCount (source, 3, "component count") : 1;
    if (!nextKeywordLine (source) || upper (source.tokens[0]) != "LOOKUP_TABLE")
      source.reader.failAtLine ("expected 'LOOKUP_TABLE <name>' after SCALARS");
    checkValues (source, valueCount (source, components, tuples), bytes, false, keyword);
  }
  else if (keyword == "LOOKUP_TABLE")
    checkValues (source, valueCount (source, 4, headerCount (source, 2, "table size")), 1, false, keyword);
  else if (keyword == "FIELD")
    checkFieldArrays (source, headerCount (source, 2, "array count"));
  else if (keyword == "METADATA")
    skipMetadata (source);
  else
    source.reader.failAtLine ("unexpected '" + source.line.substr (0, 80) + "' among the attributes");
}

/** The attribute sections, up to the end of the file. */
void
checkAttributes (VtkSource& source)
{
  long long tuples = headerCount (source, 1, "tuple count");
  while (nextKeywordLine (source)) {
    const std::string keyword = upper (source.tokens[0]);
    if (keyword == "POINT_DATA" || keyword == "CELL_DATA")
      tuples = headerCount (source, 1, "tuple count");
    else
      checkAttribute (source, tuples);
  }
}

void
checkSections (VtkSource& source)
{
  static const std::vector<std::string> cell_sections = {"VERTICES", "LINES", "POLYGONS", "TRIANGLE_STRIPS"};
  long long points = -1;
  while (nextKeywordLine (source)) {
    const std::string keyword = upper (source.tokens[0]);
    if (keyword == "POINTS" && points < 0)
      points = checkPoints (source);
    else if (std::find (cell_sections.begin (), cell_sections.end (), keyword) != cell_sections.end () && points >= 0) {
      const long long cells = headerCount (source, 1, keyword + " cell count");
      const long long size = headerCount (source, 2, keyword + " size");
      source.major_version >= 5 ? checkOffsetCells (source, points, keyword, cells, size)
                                : checkClassicCells (source, points, keyword, cells, size);
    }
    else if (keyword == "METADATA")
      skipMetadata (source);
    else if ((keyword == "POINT_DATA" || keyword == "CELL_DATA") && points >= 0)
      return checkAttributes (source);
    else
      source.reader.failAtLine ("unexpected '" + source.line.substr (0, 80) + "'" +
                                (points < 0 ? " before POINTS" : " in a POLYDATA file"));
  }
  if (points < 0)
    source.reader.fail ("the VTK file has no POINTS");
}
} // namespace

void
validateVtkFile (const std::string& path)
{
  GeometryFileReader reader (path);
  VtkSource source (reader);
  checkHeader (source);
  checkSections (source);
}

} // namespace validation
} // namespace morphreg

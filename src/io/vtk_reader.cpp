// SPDX-License-Identifier: BSD-3-Clause
#include "vtk_reader.h"

#include "geometry_file_reader.h"

#include <pcl/conversions.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <limits>
#include <map>

namespace morphreg
{
namespace
{
using validation::GeometryFileReader;
using validation::parseInteger;
using validation::parseNumber;
using validation::requireCountFits;
using validation::splitTokens;

/** The file after its header: keyword lines, then each section's values, as text tokens (ASCII) or raw big-endian
 *  numbers (BINARY); and what is kept of it: the points and the polygons (triangle strips cut into triangles).
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
  pcl::PointCloud<pcl::PointXYZ> points;
  std::vector<pcl::Vertices> polygons;
};

/** A VTK data type: its bytes, and how BINARY files store it (big-endian). */
struct VtkType
{
  int bytes = 0; ///< 0 for an unknown type
  bool floating = false;
  bool is_signed = false;
};

std::string
upper (std::string_view text)
{
  std::string result (text);
  for (char& c : result)
    c = static_cast<char> (std::toupper (static_cast<unsigned char> (c)));
  return result;
}

/** A VTK data type by its name; bytes 0 if the name is unknown. */
VtkType
typeNamed (std::string_view name)
{
  static const std::map<std::string, VtkType> types = {{"BIT", {1, false, false}},
                                                       {"CHAR", {1, false, true}},
                                                       {"UNSIGNED_CHAR", {1, false, false}},
                                                       {"SHORT", {2, false, true}},
                                                       {"UNSIGNED_SHORT", {2, false, false}},
                                                       {"INT", {4, false, true}},
                                                       {"UNSIGNED_INT", {4, false, false}},
                                                       {"FLOAT", {4, true, true}},
                                                       {"LONG", {8, false, true}},
                                                       {"UNSIGNED_LONG", {8, false, false}},
                                                       {"DOUBLE", {8, true, true}},
                                                       {"VTKTYPEINT64", {8, false, true}},
                                                       {"VTKTYPEINT32", {4, false, true}},
                                                       {"VTKIDTYPE", {8, false, true}}};
  const auto type = types.find (upper (name));
  return type == types.end () ? VtkType{} : type->second;
}

/** The bytes of one value of a VTK data type; 0 if the type is unknown. */
int
typeBytes (std::string_view name)
{
  return typeNamed (name).bytes;
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

/** \a index, checked to be one of the \a points points. */
pcl::index_t
pointIndex (const VtkSource& source, long long index, long long points, const std::string& section)
{
  if (index < 0 || index >= points)
    failInData (source, section + " index " + std::to_string (index) + " is outside the " + std::to_string (points) +
                            " points [0, " + std::to_string (points) + ")");
  return static_cast<pcl::index_t> (index);
}

/** \a count values of \a bytes bytes each (BINARY) or \a count numbers (ASCII), checked and skipped. */
void
skipValues (VtkSource& source, std::uint64_t count, int bytes, const std::string& what)
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
    if (!parseNumber (token, number))
      source.reader.failAtLine (what + " value '" + std::string (token) + "' is not a number");
  }
}

/** The next value of \a type as a number: raw big-endian bytes (BINARY) or a token (ASCII). */
double
nextNumber (VtkSource& source, const VtkType& type, const std::string& what)
{
  if (!source.binary) {
    const std::string_view token = nextToken (source, what);
    double value = 0.0;
    if (!parseNumber (token, value))
      source.reader.failAtLine (what + " value '" + std::string (token) + "' is not a number");
    return value;
  }
  unsigned char raw[8];
  if (!source.reader.readBytes (reinterpret_cast<char*> (raw), static_cast<std::uint64_t> (type.bytes)))
    source.reader.fail ("the file ends inside the " + what + " (the file is cut short or its header claims more)");
  std::uint64_t bits = 0;
  for (int i = 0; i < type.bytes; ++i)
    bits = (bits << 8) | raw[i];
  if (type.floating && type.bytes == 4) {
    const auto word = static_cast<std::uint32_t> (bits);
    float value;
    std::memcpy (&value, &word, sizeof value);
    return value;
  }
  if (type.floating) {
    double value;
    std::memcpy (&value, &bits, sizeof value);
    return value;
  }
  const int unused = 64 - 8 * type.bytes; // sign-extends signed types narrower than 64 bits
  return type.is_signed ? static_cast<double> (static_cast<std::int64_t> (bits << unused) >> unused)
                        : static_cast<double> (bits);
}

/** "POINTS n type" and its 3n values, kept as the points; returns n. */
long long
readPoints (VtkSource& source)
{
  const long long points = headerCount (source, 1, "point count");
  const VtkType type = source.tokens.size () == 3 ? typeNamed (source.tokens[2]) : VtkType{};
  if (type.bytes == 0)
    source.reader.failAtLine ("POINTS must be followed by a count and a data type (e.g. 'POINTS 8 float')");
  requireCountFits (source.reader.path (), static_cast<std::uint64_t> (points), source.binary ? 3.0 * type.bytes : 6.0,
                    source.reader.remaining (), "points", !source.binary);
  source.points.resize (static_cast<std::size_t> (points));
  for (std::size_t i = 0; i < source.points.size (); ++i)
    for (int k = 0; k < 3; ++k) {
      const double value = nextNumber (source, type, "point coordinate");
      if (!std::isfinite (value) || std::abs (value) > std::numeric_limits<float>::max ())
        failInData (source, "point " + std::to_string (i) + " has a coordinate that is not a finite number");
      source.points[i].data[k] = static_cast<float> (value);
    }
  return points;
}

/** Keeps a cell of \a section: a polygon as it is, a triangle strip as its triangles (every other one turned to keep
 *  the strip's orientation); vertices and lines are not kept.
 */
void
keepCell (VtkSource& source, const std::string& section, const pcl::Indices& corners)
{
  if (section == "POLYGONS") {
    source.polygons.emplace_back ();
    source.polygons.back ().vertices = corners;
  }
  else if (section == "TRIANGLE_STRIPS")
    for (std::size_t i = 2; i < corners.size (); ++i) {
      source.polygons.emplace_back ();
      const bool odd = i % 2 == 1;
      source.polygons.back ().vertices = {corners[odd ? i - 1 : i - 2], corners[odd ? i - 2 : i - 1], corners[i]};
    }
}

/** The classic layout: \a cells cells of "k i_1 .. i_k", \a size values in all. */
void
readClassicCells (VtkSource& source, long long points, const std::string& section, long long cells, long long size)
{
  requireCountFits (source.reader.path (), static_cast<std::uint64_t> (size), source.binary ? 4.0 : 2.0,
                    source.reader.remaining (), section + " values", !source.binary);
  long long used = 0;
  pcl::Indices cell;
  for (long long c = 0; c < cells; ++c) {
    const long long corners = nextInteger (source, 4, section);
    if (corners == 0)
      failInData (source, section + " cell " + std::to_string (c) + " has no indices");
    if (corners < 0 || used + 1 + corners > size)
      failInData (source, section + " cell " + std::to_string (c) + " has " + std::to_string (corners) +
                              " indices, beyond the " + std::to_string (size) + " values the section's header claims");
    used += 1 + corners;
    cell.resize (static_cast<std::size_t> (corners));
    for (pcl::index_t& corner : cell)
      corner = pointIndex (source, nextInteger (source, 4, section), points, section);
    keepCell (source, section, cell);
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

/** The layout of format 5: \a offsets offsets (0, nondecreasing, ending at \a size), then \a size indices; cell c
 *  is the indices from offset c up to offset c + 1.
 */
void
readOffsetCells (VtkSource& source, long long points, const std::string& section, long long offsets, long long size)
{
  int bytes = expectArrayLine (source, "OFFSETS", offsets);
  std::vector<long long> starts (static_cast<std::size_t> (offsets));
  for (long long i = 0; i < offsets; ++i) {
    const long long offset = nextInteger (source, bytes, section + " offsets");
    if ((i == 0 && offset != 0) || (i > 0 && offset < starts[i - 1]) || offset > size)
      failInData (source, section + " offset " + std::to_string (i) + " is " + std::to_string (offset) +
                              "; offsets must start at 0 and rise to the connectivity size " + std::to_string (size));
    starts[i] = offset;
  }
  if ((offsets == 0 ? 0 : starts.back ()) != size)
    failInData (source, "the last " + section + " offset " + std::to_string (offsets == 0 ? 0 : starts.back ()) +
                            " is not the connectivity size " + std::to_string (size));
  bytes = expectArrayLine (source, "CONNECTIVITY", size);
  pcl::Indices connectivity (static_cast<std::size_t> (size));
  for (pcl::index_t& corner : connectivity)
    corner = pointIndex (source, nextInteger (source, bytes, section + " connectivity"), points, section);
  for (std::size_t c = 1; c < starts.size (); ++c)
    keepCell (source, section, pcl::Indices (connectivity.begin () + starts[c - 1], connectivity.begin () + starts[c]));
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
    skipValues (source, values, typeAt (source, 3), "FIELD array");
  }
}

/** One attribute of a POINT_DATA or CELL_DATA section of \a tuples tuples: its header line (read) and its values. */
void
checkAttribute (VtkSource& source, long long tuples)
{
  const std::string keyword = upper (source.tokens[0]);
  if (keyword == "NORMALS" || keyword == "VECTORS" || keyword == "TENSORS")
    skipValues (source, valueCount (source, keyword == "TENSORS" ? 9 : 3, tuples), typeAt (source, 2), keyword);
  else if (keyword == "TEXTURE_COORDINATES")
    skipValues (source, valueCount (source, headerCount (source, 2, "dimension"), tuples), typeAt (source, 3), keyword);
  else if (keyword == "COLOR_SCALARS")
    skipValues (source, valueCount (source, headerCount (source, 2, "component count"), tuples), 1, keyword);
  else if (keyword == "SCALARS") {
    const int bytes = typeAt (source, 2);
    const long long components = source.tokens.size () > 3 ? headerCount (source, 3, "component count") : 1;
    if (!nextKeywordLine (source) || upper (source.tokens[0]) != "LOOKUP_TABLE")
      source.reader.failAtLine ("expected 'LOOKUP_TABLE <name>' after SCALARS");
    skipValues (source, valueCount (source, components, tuples), bytes, keyword);
  }
  else if (keyword == "LOOKUP_TABLE")
    skipValues (source, valueCount (source, 4, headerCount (source, 2, "table size")), 1, keyword);
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

/** The points, the cells and the attributes after them. */
void
readSections (VtkSource& source)
{
  static const std::vector<std::string> cell_sections = {"VERTICES", "LINES", "POLYGONS", "TRIANGLE_STRIPS"};
  long long points = -1;
  while (nextKeywordLine (source)) {
    const std::string keyword = upper (source.tokens[0]);
    if (keyword == "POINTS" && points < 0)
      points = readPoints (source);
    else if (std::find (cell_sections.begin (), cell_sections.end (), keyword) != cell_sections.end () && points >= 0) {
      if (source.tokens.size () != 3) // VTK's reader misreads what follows extra words (found by fuzzing)
        source.reader.failAtLine ("expected '" + keyword + " <cells> <size>'");
      const long long cells = headerCount (source, 1, keyword + " cell count");
      const long long size = headerCount (source, 2, keyword + " size");
      source.major_version >= 5 ? readOffsetCells (source, points, keyword, cells, size)
                                : readClassicCells (source, points, keyword, cells, size);
    }
    else if (keyword == "METADATA" && source.tokens.size () == 1)
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

pcl::PolygonMesh
readVtkFile (const std::string& path)
{
  GeometryFileReader reader (path);
  VtkSource source (reader);
  checkHeader (source);
  readSections (source);
  pcl::PolygonMesh mesh;
  pcl::toPCLPointCloud2 (source.points, mesh.cloud);
  mesh.polygons = std::move (source.polygons);
  return mesh;
}

} // namespace morphreg

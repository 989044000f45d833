// SPDX-License-Identifier: BSD-3-Clause
#include "geometry_file_reader.h"
#include "geometry_validators.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>

namespace morphreg
{
namespace validation
{
namespace
{
struct PlyScalar
{
  int size = 0;
  bool integer = false;
  bool is_signed = false;
};

struct PlyProperty
{
  std::string name;
  PlyScalar type;
  bool is_list = false;
  PlyScalar count_type;
};

struct PlyElement
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
};

enum class PlyEncoding
{
  Ascii,
  LittleEndian,
  BigEndian
};

struct PlyHeader
{
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
  std::uint64_t vertex_count = 0;
};

PlyScalar
plyScalar (const GeometryFileReader& reader, std::string_view name)
{
  static const std::map<std::string, PlyScalar, std::less<>> types = {
      {"char", {1, true, true}},    {"int8", {1, true, true}},     {"uchar", {1, true, false}},
      {"uint8", {1, true, false}},  {"short", {2, true, true}},    {"int16", {2, true, true}},
      {"ushort", {2, true, false}}, {"uint16", {2, true, false}},  {"int", {4, true, true}},
      {"int32", {4, true, true}},   {"uint", {4, true, false}},    {"uint32", {4, true, false}},
      {"float", {4, false, true}},  {"float32", {4, false, true}}, {"double", {8, false, true}},
      {"float64", {8, false, true}}};
  const auto type = types.find (name);
  if (type == types.end ())
    reader.failAtLine ("unknown PLY property type '" + std::string (name) + "'");
  return type->second;
}

/** "property <type> <name>" or "property list <count type> <item type> <name>". */
PlyProperty
parseProperty (const GeometryFileReader& reader, const std::vector<std::string_view>& tokens)
{
  PlyProperty property;
  property.is_list = tokens.size () > 1 && tokens[1] == "list";
  if (tokens.size () != (property.is_list ? 5u : 3u))
    reader.failAtLine ("a property line must be 'property <type> <name>' or 'property list <count type> <type> "
                       "<name>'");
  if (property.is_list) {
    property.count_type = plyScalar (reader, tokens[2]);
    if (!property.count_type.integer)
      reader.failAtLine ("a list's count type must be an integer type");
  }
  property.type = plyScalar (reader, tokens[property.is_list ? 3 : 1]);
  property.name = std::string (tokens.back ());
  return property;
}

PlyElement
parseElement (const GeometryFileReader& reader, const std::vector<std::string_view>& tokens)
{
  long long count = 0;
  if (tokens.size () != 3 || !parseInteger (tokens[2], count) || count < 0)
    reader.failAtLine ("an element line must be 'element <name> <count>' with a count of 0 or more");
  PlyElement element;
  element.name = std::string (tokens[1]);
  element.count = static_cast<std::uint64_t> (count);
  return element;
}

PlyEncoding
parseFormat (const GeometryFileReader& reader, const std::vector<std::string_view>& tokens)
{
  if (tokens.size () == 3 && tokens[2] == "1.0") {
    if (tokens[1] == "ascii")
      return PlyEncoding::Ascii;
    if (tokens[1] == "binary_little_endian")
      return PlyEncoding::LittleEndian;
    if (tokens[1] == "binary_big_endian")
      return PlyEncoding::BigEndian;
  }
  reader.failAtLine ("the format line must be 'format ascii|binary_little_endian|binary_big_endian 1.0'");
}

/** Reads the header up to end_header. */
PlyHeader
parseHeader (GeometryFileReader& reader)
{
  std::string line;
  std::vector<std::string_view> tokens;
  reader.nextLine (line);
  PlyHeader header;
  bool has_format = false;
  while (true) {
    if (!reader.nextLine (line))
      reader.fail ("the PLY header has no end_header line (the file is cut short)");
    splitTokens (line, tokens);
    if (!tokens.empty () && std::isspace (static_cast<unsigned char> (line[0])))
      reader.failAtLine ("a PLY header line starts with white space");
    if (tokens.empty () || tokens[0] == "comment" || tokens[0] == "obj_info")
      continue;
    if (tokens[0] == "end_header")
      break;
    if (tokens[0] == "format") {
      header.encoding = parseFormat (reader, tokens);
      has_format = true;
    }
    else if (tokens[0] == "element")
      header.elements.push_back (parseElement (reader, tokens));
    else if (tokens[0] == "property" && !header.elements.empty ())
      header.elements.back ().properties.push_back (parseProperty (reader, tokens));
    else
      reader.failAtLine ("unexpected PLY header line '" + line.substr (0, 80) + "'");
  }
  if (!has_format)
    reader.fail ("the PLY header has no format line");
  for (const PlyElement& element : header.elements)
    if (element.name == "vertex")
      header.vertex_count = element.count;
  return header;
}

/** The fewest bytes a row of \a element can take: its scalars and list counts (binary), or one character and one
 *  separator per property (ASCII).
 */
double
minimalRowBytes (const PlyElement& element, PlyEncoding encoding)
{
  double bytes = 0.0;
  for (const PlyProperty& property : element.properties)
    bytes += encoding == PlyEncoding::Ascii ? 2.0 : (property.is_list ? property.count_type.size : property.type.size);
  return bytes;
}

/** A face's vertex index list, whose entries must name vertices. */
bool
isFaceIndexList (const PlyElement& element, const PlyProperty& property)
{
  return element.name == "face" && property.is_list &&
         (property.name == "vertex_indices" || property.name == "vertex_index");
}

/** The colour channel a vertex property is to PCL's reader (0 red, 1 green, 2 blue, 3 alpha), or -1: PCL packs uchar
 *  red, green and blue (or diffuse_red...) into one field and adds alpha to it. */
int
colourChannel (const PlyProperty& property)
{
  if (property.is_list || property.type.size != 1 || !property.type.integer || property.type.is_signed)
    return -1;
  static const std::map<std::string, int, std::less<>> channels = {
      {"red", 0},         {"green", 1},         {"blue", 2},        {"alpha", 3},
      {"diffuse_red", 0}, {"diffuse_green", 1}, {"diffuse_blue", 2}};
  const auto channel = channels.find (property.name);
  return channel == channels.end () ? -1 : channel->second;
}

/** The vertex properties PCL's PLY reader can take: scalars only, each name once, and colour channels as red, green,
 *  blue in this order (then alpha) or none of them; other layouts make it write outside its buffers. */
void
checkVertexProperties (const GeometryFileReader& reader, const PlyElement& vertex)
{
  std::set<std::string> names;
  int next_channel = 0;
  for (const PlyProperty& property : vertex.properties) {
    if (property.is_list)
      reader.fail ("the PLY vertex element has the list property '" + property.name +
                   "'; vertices take scalar properties only");
    if (!names.insert (property.name).second)
      reader.fail ("the PLY vertex element has the property '" + property.name + "' twice");
    const int channel = colourChannel (property);
    if (channel < 0)
      continue;
    if (channel != next_channel)
      reader.fail ("the PLY vertex colour property '" + property.name +
                   "' is out of order; colours must be red, green, blue (uchar, in this order), then alpha");
    ++next_channel;
  }
  if (next_channel > 0 && next_channel < 3)
    reader.fail ("the PLY vertex colours are incomplete; colours must be red, green and blue (uchar)");
}

/** Each element is declared once and has properties, the vertex properties are ones PCL reads (see
 *  checkVertexProperties), and the rows fit in what follows the header, checked before any row is read. */
void
checkElements (GeometryFileReader& reader, const PlyHeader& header)
{
  double available = static_cast<double> (reader.remaining ());
  std::set<std::string> declared;
  for (const PlyElement& element : header.elements) {
    if (!declared.insert (element.name).second)
      reader.fail ("PLY element '" + element.name + "' is declared twice");
    if (element.name == "vertex")
      checkVertexProperties (reader, element);
    if (element.properties.empty () && element.count > 0)
      reader.fail ("PLY element '" + element.name + "' has no properties");
    for (const PlyProperty& property : element.properties)
      if (isFaceIndexList (element, property) && !property.type.integer)
        reader.fail ("the face vertex indices must be a list of integers");
    const double row_bytes = minimalRowBytes (element, header.encoding);
    requireCountFits (reader.path (), element.count, row_bytes, static_cast<std::uint64_t> (std::max (available, 0.0)),
                      "'" + element.name + "' elements", header.encoding == PlyEncoding::Ascii);
    available -= static_cast<double> (element.count) * row_bytes;
  }
}

void
requireVertexIndex (const GeometryFileReader& reader, const PlyHeader& header, long long index, std::uint64_t row,
                    bool has_line)
{
  if (index >= 0 && static_cast<std::uint64_t> (index) < header.vertex_count)
    return;
  const std::string problem = "face " + std::to_string (row) + " has vertex index " + std::to_string (index) +
                              ", outside [0, " + std::to_string (header.vertex_count) + ")";
  has_line ? reader.failAtLine (problem) : reader.fail (problem);
}

[[noreturn]] void
failCutShort (const GeometryFileReader& reader, const PlyElement& element, std::uint64_t row)
{
  reader.fail ("the file ends inside '" + element.name + "' row " + std::to_string (row) + " of " +
               std::to_string (element.count) + " (the data is cut short)");
}

/** A binary integer of \a type; false if the file ends first. */
bool
readBinaryInteger (GeometryFileReader& reader, const PlyScalar& type, bool big_endian, long long& value)
{
  unsigned char bytes[8];
  if (!reader.readBytes (reinterpret_cast<char*> (bytes), static_cast<std::uint64_t> (type.size)))
    return false;
  std::uint64_t bits = 0;
  for (int i = 0; i < type.size; ++i)
    bits = (bits << 8) | bytes[big_endian ? i : type.size - 1 - i];
  const int sign_bit = 8 * type.size - 1;
  const bool negative = type.is_signed && type.size < 8 && ((bits >> sign_bit) & 1u);
  value = negative ? static_cast<long long> (bits) - (1LL << (sign_bit + 1)) : static_cast<long long> (bits);
  return true;
}

void
walkBinaryRow (GeometryFileReader& reader, const PlyHeader& header, const PlyElement& element, std::uint64_t row)
{
  const bool big_endian = header.encoding == PlyEncoding::BigEndian;
  for (const PlyProperty& property : element.properties) {
    if (!property.is_list) {
      if (!reader.skipBytes (static_cast<std::uint64_t> (property.type.size)))
        failCutShort (reader, element, row);
      continue;
    }
    long long count = 0;
    if (!readBinaryInteger (reader, property.count_type, big_endian, count))
      failCutShort (reader, element, row);
    if (count < 0)
      reader.fail ("'" + element.name + "' row " + std::to_string (row) + " has a list of " + std::to_string (count) +
                   " values");
    const std::uint64_t bytes = static_cast<std::uint64_t> (count) * static_cast<std::uint64_t> (property.type.size);
    if (bytes > reader.remaining ())
      failCutShort (reader, element, row);
    if (!isFaceIndexList (element, property)) {
      reader.skipBytes (bytes);
      continue;
    }
    for (long long i = 0; i < count; ++i) {
      long long index = 0;
      readBinaryInteger (reader, property.type, big_endian, index);
      requireVertexIndex (reader, header, index, row, false);
    }
  }
}

void
walkBinary (GeometryFileReader& reader, const PlyHeader& header)
{
  for (const PlyElement& element : header.elements) {
    bool has_list = false;
    double row_bytes = 0.0;
    for (const PlyProperty& property : element.properties) {
      has_list = has_list || property.is_list;
      row_bytes += property.type.size;
    }
    if (has_list) {
      for (std::uint64_t row = 0; row < element.count; ++row)
        walkBinaryRow (reader, header, element, row);
    }
    else if (!reader.skipBytes (element.count * static_cast<std::uint64_t> (row_bytes)))
      failCutShort (reader, element, reader.remaining () / static_cast<std::uint64_t> (row_bytes));
  }
}

void
checkAsciiValue (const GeometryFileReader& reader, std::string_view token, const PlyScalar& type,
                 const PlyProperty& property)
{
  long long whole = 0;
  if (type.integer ? parseInteger (token, whole) : isFiniteFloat (token))
    return;
  reader.failAtLine ("property '" + property.name + "' value '" + std::string (token) + "' is not " +
                     (type.integer ? "a whole number" : "a finite number"));
}

void
checkAsciiRow (const GeometryFileReader& reader, const PlyHeader& header, const PlyElement& element, std::uint64_t row,
               const std::vector<std::string_view>& tokens)
{
  std::size_t next = 0;
  const auto take = [&] () {
    if (next >= tokens.size ())
      reader.failAtLine ("'" + element.name + "' row " + std::to_string (row) + " has too few values (" +
                         std::to_string (tokens.size ()) + ")");
    return tokens[next++];
  };
  for (const PlyProperty& property : element.properties) {
    if (!property.is_list) {
      checkAsciiValue (reader, take (), property.type, property);
      continue;
    }
    long long count = 0;
    const std::string_view count_token = take ();
    if (!parseInteger (count_token, count) || count < 0 || static_cast<std::size_t> (count) > tokens.size () - next)
      reader.failAtLine ("list '" + property.name + "' count '" + std::string (count_token) +
                         "' is not the number of values that follow it");
    for (long long i = 0; i < count; ++i) {
      const std::string_view token = take ();
      checkAsciiValue (reader, token, property.type, property);
      long long index = 0;
      if (isFaceIndexList (element, property) && parseInteger (token, index))
        requireVertexIndex (reader, header, index, row, true);
    }
  }
  if (next != tokens.size ())
    reader.failAtLine ("'" + element.name + "' row " + std::to_string (row) + " has " +
                       std::to_string (tokens.size ()) + " values, expected " + std::to_string (next));
}

void
walkAscii (GeometryFileReader& reader, const PlyHeader& header)
{
  std::string line;
  std::vector<std::string_view> tokens;
  for (const PlyElement& element : header.elements)
    for (std::uint64_t row = 0; row < element.count; ++row) {
      if (!reader.nextLine (line))
        failCutShort (reader, element, row);
      splitTokens (line, tokens);
      checkAsciiRow (reader, header, element, row, tokens);
    }
}
} // namespace

void
validatePlyFile (const std::string& path)
{
  GeometryFileReader reader (path);
  const PlyHeader header = parseHeader (reader);
  if (header.vertex_count == 0) // PCL's conversions misbehave on an empty cloud, and it is no mesh or scan
    reader.fail ("the PLY file holds no vertices (no 'element vertex' with a count above 0)");
  checkElements (reader, header);
  if (header.encoding == PlyEncoding::Ascii)
    walkAscii (reader, header);
  else
    walkBinary (reader, header);
}

} // namespace validation
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include "geometry_file_reader.h"
#include "geometry_validators.h"
#include "obj_content.h"
#include "vertex_cloud.h"

#include <morphreg/io/atomic_file.h>
#include <morphreg/io/mesh_io.h>

#include <pcl/common/io.h>
#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <sstream>

namespace morphreg
{
namespace
{
using validation::GeometryFileReader;
using validation::isFiniteFloat;
using validation::parseInteger;
using validation::parseNumber;
using validation::splitTokens;
/** The v, vt or vn lines read so far, and the largest positive index a face gave for them (checked at the end, since
 *  a face may name a vertex defined after it).
 */
struct ObjIndexRange
{
  const char* what;
  const char* plural;
  std::uint64_t count = 0;
  long long max_positive = 0;
  std::uint64_t max_line = 0;
};

void
checkNumbers (const GeometryFileReader& reader, const std::vector<std::string_view>& tokens, std::size_t low,
              std::size_t high, const std::string& what)
{
  const std::size_t n = tokens.size () - 1;
  if (n < low || n > high)
    reader.failAtLine (what + " has " + std::to_string (n) + " coordinates, expected " +
                       (low == high ? std::to_string (low) : std::to_string (low) + " to " + std::to_string (high)));
  for (std::size_t i = 1; i < tokens.size (); ++i)
    if (!isFiniteFloat (tokens[i]))
      reader.failAtLine (what + " coordinate '" + std::string (tokens[i]) + "' is not a finite number");
}

/** "v x y z", "v x y z w" or "v x y z r g b", the keyword followed by a space (PCL's reader counts only those). */
void
checkVertex (const GeometryFileReader& reader, const std::string& line, const std::vector<std::string_view>& tokens)
{
  const std::size_t n = tokens.size () - 1;
  if (n != 3 && n != 4 && n != 6)
    reader.failAtLine ("vertex has " + std::to_string (n) +
                       " coordinates, expected 3 (x y z), 4 (x y z w) or 6 (x y z r g b)");
  if (line[line.find_first_not_of (" \t") + 1] != ' ')
    reader.failAtLine ("separate 'v' from its coordinates with a space");
  checkNumbers (reader, tokens, n, n, "vertex");
}

/** One index of a corner: a nonzero whole number, negative ones counting back from the last definition; returns
 *  the 0-based index (a positive one is checked against the count at the end of the file). */
long long
checkIndex (const GeometryFileReader& reader, std::string_view token, ObjIndexRange& range)
{
  long long index = 0;
  if (!parseInteger (token, index) || index == 0)
    reader.failAtLine (std::string ("face ") + range.what + " index '" + std::string (token) +
                       "' is not a nonzero whole number");
  if (index < 0 && static_cast<std::uint64_t> (-index) > range.count)
    reader.failAtLine (std::string ("face ") + range.what + " index " + std::to_string (index) +
                       " refers back past the " + std::to_string (range.count) + " " + range.plural +
                       " defined before it");
  if (index > range.max_positive) {
    range.max_positive = index;
    range.max_line = reader.lineNumber ();
  }
  return index > 0 ? index - 1 : static_cast<long long> (range.count) + index;
}

/** "f c1 c2 c3 ...", each corner v, v/t, v//n or v/t/n; returns the polygon's 0-based vertex indices and appends
 *  each corner's 0-based texture coordinate index (-1 for none) to \a corner_texcoords. */
pcl::Vertices
readFace (const GeometryFileReader& reader, const std::vector<std::string_view>& tokens, ObjIndexRange* ranges,
          std::vector<long long>& corner_texcoords)
{
  if (tokens.size () < 4)
    reader.failAtLine ("face has " + std::to_string (tokens.size () - 1) + " corners, expected at least 3");
  pcl::Vertices polygon;
  for (std::size_t c = 1; c < tokens.size (); ++c) {
    std::string_view corner = tokens[c];
    long long texcoord = -1;
    for (int part = 0; part < 3; ++part) {
      const std::size_t slash = corner.find ('/');
      const std::string_view index = corner.substr (0, slash);
      if (part == 0)
        polygon.vertices.push_back (static_cast<pcl::index_t> (checkIndex (reader, index, ranges[part])));
      else if (!(part == 1 && index.empty () && slash != std::string_view::npos)) {
        const long long resolved = checkIndex (reader, index, ranges[part]);
        if (part == 1)
          texcoord = resolved;
      }
      if (slash == std::string_view::npos)
        break;
      if (part == 2)
        reader.failAtLine ("face corner '" + std::string (tokens[c]) + "' has more than 3 indices");
      corner.remove_prefix (slash + 1);
    }
    corner_texcoords.push_back (texcoord);
  }
  return polygon;
}

void
checkRangesAtEnd (const GeometryFileReader& reader, const ObjIndexRange* ranges)
{
  if (ranges[0].count == 0)
    reader.fail ("the OBJ file has no vertices (v lines)");
  for (int part = 0; part < 3; ++part)
    if (static_cast<std::uint64_t> (ranges[part].max_positive) > ranges[part].count)
      throw FormatError (reader.path () + ":" + std::to_string (ranges[part].max_line) + ": face " + ranges[part].what +
                         " index " + std::to_string (ranges[part].max_positive) + " is beyond the file's " +
                         std::to_string (ranges[part].count) + " " + ranges[part].plural);
}
void
addNumbers (const std::vector<std::string_view>& tokens, std::size_t first, std::size_t count, std::vector<float>& out)
{
  for (std::size_t i = first; i < first + count; ++i) {
    double value = 0.0;
    parseNumber (tokens[i], value);
    out.push_back (static_cast<float> (value));
  }
}

/** A v line: x y z (w dropped) and an r g b colour in [0, 1] if it has one. */
void
addVertex (const std::vector<std::string_view>& tokens, ObjContent& content)
{
  addNumbers (tokens, 1, 3, content.positions);
  if (tokens.size () == 7)
    addNumbers (tokens, 4, 3, content.colours);
}

/** A vt line: u and v (0 if absent; w dropped). */
void
addTexcoord (const std::vector<std::string_view>& tokens, ObjContent& content)
{
  addNumbers (tokens, 1, 1, content.texcoords);
  if (tokens.size () >= 3)
    addNumbers (tokens, 2, 1, content.texcoords);
  else
    content.texcoords.push_back (0.0f);
}

/** "usemtl name": the polygons after it have that material. */
void
useMaterial (const std::vector<std::string_view>& tokens, ObjContent& content, int& material)
{
  const std::string name = tokens.size () > 1 ? std::string (tokens[1]) : std::string ();
  const auto known = std::find (content.materials.begin (), content.materials.end (), name);
  material = static_cast<int> (known - content.materials.begin ());
  if (known == content.materials.end ())
    content.materials.push_back (name);
}

/** The line's keyword and numbers checked, and what it holds added to \a content. */
void
readObjLine (const GeometryFileReader& reader, const std::string& line, const std::vector<std::string_view>& tokens,
             ObjIndexRange* ranges, ObjContent& content, int& material)
{
  const std::string_view keyword = tokens[0];
  if (keyword == "v") {
    checkVertex (reader, line, tokens);
    addVertex (tokens, content);
    ++ranges[0].count;
  }
  else if (keyword == "vt") {
    checkNumbers (reader, tokens, 1, 3, "texture coordinate");
    addTexcoord (tokens, content);
    ++ranges[1].count;
  }
  else if (keyword == "vn") {
    checkNumbers (reader, tokens, 3, 3, "vertex normal");
    addNumbers (tokens, 1, 3, content.normals);
    ++ranges[2].count;
  }
  else if (keyword == "f") {
    content.polygons.push_back (readFace (reader, tokens, ranges, content.corner_texcoords));
    content.polygon_material.push_back (material);
  }
  else if (keyword == "usemtl")
    useMaterial (tokens, content, material);
  else if (keyword == "mtllib")
    for (std::size_t i = 1; i < tokens.size (); ++i)
      content.libraries.emplace_back (tokens[i]);
}

pcl::PolygonMesh
toPolygonMesh (ObjContent content)
{
  const auto count = static_cast<Eigen::Index> (content.positions.size () / 3);
  const Eigen::Map<const Eigen::Matrix3Xf> positions (content.positions.data (), 3, count);
  const bool with_normals = content.normals.size () == content.positions.size ();
  const Eigen::Map<const Eigen::Matrix3Xf> normals (content.normals.data (), 3, with_normals ? count : 0);
  pcl::PolygonMesh mesh;
  mesh.cloud = vertexCloud (positions, normals, vertexColours (content));
  mesh.polygons = std::move (content.polygons);
  return mesh;
}
} // namespace

ObjContent
parseObjFile (const std::string& path)
{
  GeometryFileReader reader (path);
  ObjIndexRange ranges[3] = {
      {"vertex", "vertices"}, {"texture coordinate", "texture coordinates"}, {"normal", "normals"}};
  ObjContent content;
  int material = -1;
  std::string line;
  std::vector<std::string_view> tokens;
  while (reader.nextLine (line)) {
    splitTokens (line, tokens);
    if (!tokens.empty () && tokens[0][0] != '#')
      readObjLine (reader, line, tokens, ranges, content, material);
  }
  checkRangesAtEnd (reader, ranges);
  return content;
}

VertexColours
vertexColours (const ObjContent& content)
{
  if (content.colours.size () != content.positions.size ())
    return {};
  const Eigen::Map<const Eigen::Matrix3Xf> colours (content.colours.data (), 3,
                                                    static_cast<Eigen::Index> (content.colours.size () / 3));
  return (colours.array ().max (0.0f).min (1.0f) * 255.0f + 0.5f).cast<unsigned char> ();
}

pcl::PolygonMesh
readObjFile (const std::string& path)
{
  return toPolygonMesh (parseObjFile (path));
}

namespace
{
/** The 4 bytes of field \a field of point \a i (a float, or PCL's packed rgb / rgba). */
template <typename T>
T
fieldValue (const pcl::PCLPointCloud2& cloud, int field, std::size_t i)
{
  static_assert (sizeof (T) == 4, "float and packed colour fields are 4 bytes");
  T value;
  std::memcpy (&value, cloud.data.data () + i * cloud.point_step + cloud.fields[field].offset, sizeof (T));
  return value;
}

/** " r g b" in [0, 1] of PCL's packed colour (0x00RRGGBB in the low bytes). */
std::string
colourText (std::uint32_t packed)
{
  std::ostringstream text;
  text.precision (6);
  for (int shift : {16, 8, 0})
    text << ' ' << ((packed >> shift) & 0xffu) / 255.0;
  return text.str ();
}
} // namespace

void
saveObjFile (const std::string& path, const pcl::PolygonMesh& mesh)
{
  pcl::PointCloud<pcl::PointXYZ> points;
  pcl::fromPCLPointCloud2 (mesh.cloud, points);
  const int normal[3] = {pcl::getFieldIndex (mesh.cloud, "normal_x"), pcl::getFieldIndex (mesh.cloud, "normal_y"),
                         pcl::getFieldIndex (mesh.cloud, "normal_z")};
  const bool normals = std::min ({normal[0], normal[1], normal[2]}) >= 0;
  const int colour = std::max (pcl::getFieldIndex (mesh.cloud, "rgb"), pcl::getFieldIndex (mesh.cloud, "rgba"));
  std::ostringstream text;
  text.precision (9);
  text << "# " << points.size () << " vertices, " << mesh.polygons.size () << " faces"
       << (colour >= 0 ? "; vertex colours as v x y z r g b, r g b in [0, 1]" : "") << '\n';
  for (std::size_t i = 0; i < points.size (); ++i)
    text << "v " << points[i].x << ' ' << points[i].y << ' ' << points[i].z
         << (colour >= 0 ? colourText (fieldValue<std::uint32_t> (mesh.cloud, colour, i)) : std::string ()) << '\n';
  if (normals)
    for (std::size_t i = 0; i < points.size (); ++i)
      text << "vn " << fieldValue<float> (mesh.cloud, normal[0], i) << ' '
           << fieldValue<float> (mesh.cloud, normal[1], i) << ' ' << fieldValue<float> (mesh.cloud, normal[2], i)
           << '\n';
  for (const auto& polygon : mesh.polygons) {
    text << 'f';
    for (const auto corner : polygon.vertices)
      text << ' ' << corner + 1 << (normals ? "//" + std::to_string (corner + 1) : std::string ());
    text << '\n';
  }
  writeFileAtomically (path, text.str ());
}

namespace validation
{
void
validateObjFile (const std::string& path)
{
  readObjFile (path);
}
} // namespace validation
} // namespace morphreg

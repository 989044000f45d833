#include "geometry_file_reader.h"
#include "geometry_validators.h"

namespace morphreg
{
namespace validation
{
namespace
{
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

/** One index of a corner: a nonzero whole number, negative ones counting back from the last definition. */
void
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
}

/** "f c1 c2 c3 ...", each corner v, v/t, v//n or v/t/n. */
void
checkFace (const GeometryFileReader& reader, const std::vector<std::string_view>& tokens, ObjIndexRange* ranges)
{
  if (tokens.size () < 4)
    reader.failAtLine ("face has " + std::to_string (tokens.size () - 1) + " corners, expected at least 3");
  for (std::size_t c = 1; c < tokens.size (); ++c) {
    std::string_view corner = tokens[c];
    for (int part = 0; part < 3; ++part) {
      const std::size_t slash = corner.find ('/');
      const std::string_view index = corner.substr (0, slash);
      if (!(part == 1 && index.empty () && slash != std::string_view::npos))
        checkIndex (reader, index, ranges[part]);
      if (slash == std::string_view::npos)
        break;
      if (part == 2)
        reader.failAtLine ("face corner '" + std::string (tokens[c]) + "' has more than 3 indices");
      corner.remove_prefix (slash + 1);
    }
  }
}

void
checkRangesAtEnd (const GeometryFileReader& reader, const ObjIndexRange* ranges)
{
  if (ranges[0].count == 0)
    reader.fail ("the OBJ file has no vertices (v lines)");
  if (ranges[2].count > ranges[0].count)
    reader.fail ("the OBJ file has more vertex normals (" + std::to_string (ranges[2].count) + ") than vertices (" +
                 std::to_string (ranges[0].count) + "); PCL's reader keeps one normal per vertex");
  for (int part = 0; part < 3; ++part)
    if (static_cast<std::uint64_t> (ranges[part].max_positive) > ranges[part].count)
      throw FormatError (reader.path () + ":" + std::to_string (ranges[part].max_line) + ": face " + ranges[part].what +
                         " index " + std::to_string (ranges[part].max_positive) + " is beyond the file's " +
                         std::to_string (ranges[part].count) + " " + ranges[part].plural);
}
} // namespace

void
validateObjFile (const std::string& path)
{
  GeometryFileReader reader (path);
  ObjIndexRange ranges[3] = {
      {"vertex", "vertices"}, {"texture coordinate", "texture coordinates"}, {"normal", "normals"}};
  std::string line;
  std::vector<std::string_view> tokens;
  while (reader.nextLine (line)) {
    splitTokens (line, tokens);
    if (tokens.empty () || tokens[0][0] == '#')
      continue;
    const std::string_view keyword = tokens[0];
    if (keyword == "v") {
      checkVertex (reader, line, tokens);
      ++ranges[0].count;
    }
    else if (keyword == "vt") {
      checkNumbers (reader, tokens, 1, 3, "texture coordinate");
      ++ranges[1].count;
    }
    else if (keyword == "vn") {
      checkNumbers (reader, tokens, 3, 3, "vertex normal");
      ++ranges[2].count;
    }
    else if (keyword == "f")
      checkFace (reader, tokens, ranges);
    else if ((keyword == "mtllib" || keyword == "usemtl") && tokens.size () < 2)
      reader.failAtLine (std::string (keyword) + " has no name");
  }
  checkRangesAtEnd (reader, ranges);
}

} // namespace validation
} // namespace morphreg

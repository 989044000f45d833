// SPDX-License-Identifier: BSD-3-Clause
#include "geometry_file_reader.h"
#include "geometry_validators.h"

#include <algorithm>
#include <string>

namespace morphreg
{
namespace validation
{
namespace
{
/** Throws naming the line when \a line holds a byte that is not text. VTK's STL reader takes a file whose first 256
 *  bytes hold a few that are not text (above 127, or control characters other than tab and line ends) for binary,
 *  whatever it starts with, and allocates for a triangle count from bytes 80 to 83: an ASCII STL holds text alone. */
void
requireText (const GeometryFileReader& reader, const std::string& line)
{
  const auto not_text = std::find_if (line.begin (), line.end (), [] (char c) {
    const auto byte = static_cast<unsigned char> (c);
    return byte > 126 || (byte < 32 && byte != '\t' && byte != '\r');
  });
  if (not_text != line.end ())
    reader.failAtLine ("byte " + std::to_string (static_cast<unsigned char> (*not_text)) +
                       " is not text, in an ASCII STL file");
}

/** Reads the next non-blank line into \a tokens, every line checked to be text; false at the end of the file. */
bool
nextTokens (GeometryFileReader& reader, std::string& line, std::vector<std::string_view>& tokens)
{
  while (reader.nextLine (line)) {
    requireText (reader, line);
    splitTokens (line, tokens);
    if (!tokens.empty ())
      return true;
  }
  return false;
}

/** The next line must start with \a first (and \a second, if given). */
void
expectLine (GeometryFileReader& reader, std::string& line, std::vector<std::string_view>& tokens,
            const std::string& first, const std::string& second = "")
{
  const std::string expected = second.empty () ? first : first + " " + second;
  if (!nextTokens (reader, line, tokens))
    reader.fail ("the file ends inside a facet, before '" + expected + "' (the file is cut short)");
  if (tokens[0] != first || (!second.empty () && (tokens.size () < 2 || tokens[1] != second)))
    reader.failAtLine ("expected '" + expected + "', found '" + line.substr (0, 80) + "'");
}

/** "facet normal nx ny nz" (its first line already read), the loop of 3 vertices, "endfacet". */
void
checkFacet (GeometryFileReader& reader, std::string& line, std::vector<std::string_view>& tokens)
{
  double number = 0.0;
  if (tokens.size () != 5 || tokens[1] != "normal" || !parseNumber (tokens[2], number) ||
      !parseNumber (tokens[3], number) || !parseNumber (tokens[4], number))
    reader.failAtLine ("expected 'facet normal nx ny nz', found '" + line.substr (0, 80) + "'");
  expectLine (reader, line, tokens, "outer", "loop");
  for (int corner = 0; corner < 3; ++corner) {
    expectLine (reader, line, tokens, "vertex");
    if (tokens.size () != 4)
      reader.failAtLine ("vertex has " + std::to_string (tokens.size () - 1) + " coordinates, expected 3");
    for (std::size_t i = 1; i < 4; ++i)
      if (!isFiniteFloat (tokens[i]))
        reader.failAtLine ("vertex coordinate '" + std::string (tokens[i]) + "' is not a finite number");
  }
  expectLine (reader, line, tokens, "endloop");
  expectLine (reader, line, tokens, "endfacet");
}
} // namespace

void
validateAsciiStlFile (const std::string& path)
{
  GeometryFileReader reader (path);
  std::string line;
  std::vector<std::string_view> tokens;
  bool in_solid = false;
  std::size_t facets = 0;
  while (nextTokens (reader, line, tokens)) {
    if (!in_solid && tokens[0] == "solid")
      in_solid = true;
    else if (in_solid && tokens[0] == "endsolid")
      in_solid = false;
    else if (in_solid && tokens[0] == "facet" && ++facets)
      checkFacet (reader, line, tokens);
    else
      reader.failAtLine ("expected '" + std::string (in_solid ? "facet normal' or 'endsolid" : "solid") + "', found '" +
                         line.substr (0, 80) + "'");
  }
  if (in_solid)
    reader.fail ("the STL file has no 'endsolid' (the file is cut short)");
  if (facets == 0)
    reader.fail ("the STL file has no triangles (no 'facet' between 'solid' and 'endsolid')");
}

} // namespace validation
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include "mesh_output.h"

#include <morphreg/io/file_checks.h>
#include <morphreg/io/mesh_io.h>

namespace morphreg
{
namespace tools
{
std::string
meshContents (const std::string& path, const std::string& colours, const std::string& quality)
{
  const SavedVertexData kept = savedVertexData (path);
  const std::string format = fileExtension (path).substr (1);
  std::string text = "vertex colours" + std::string (format == "obj" ? " (v x y z r g b)" : "") + ": " + colours;
  if (!quality.empty ())
    text += kept.quality ? "; vertex quality: " + quality
                         : "; " + format + " has no field for the " + quality + ": write .ply for it";
  return "(" + text + ")";
}

std::string
meshOutputHelp (const std::string& what, const std::string& colours, const std::string& quality)
{
  return what + ": .ply (vertex colours: " + colours + (quality.empty () ? "" : "; vertex quality: " + quality) +
         "), .obj (colours as v x y z r g b) or .vtk (colours)";
}
} // namespace tools
} // namespace morphreg

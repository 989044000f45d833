// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/pipeline/scan_colours.h>

#include <morphreg/common/error.h>
#include <morphreg/io/coloured_surface_io.h>

namespace morphreg
{
std::optional<VertexColours>
scanColoursAt (const std::string& scan_file, double scale_to_mm, const std::string& mode,
               const Eigen::Matrix3Xd& vertices, std::ostream& warnings)
{
  if (mode != "scan" && mode != "auto")
    return std::nullopt;
  ColouredSurface surface;
  try {
    surface = loadColouredSurface (scan_file);
  }
  catch (const IoError& e) {
    if (mode == "scan")
      throw;
    warnings << "warning: the scan's colours cannot be read (" << e.what () << "); the mesh keeps its own colours\n";
    return std::nullopt;
  }
  if (!surface.hasColours ()) {
    if (mode == "scan")
      throw InvalidInputError (scan_file +
                               ": scan colours asked for, but the scan has no colours (neither vertex colours nor "
                               "a texture)");
    return std::nullopt;
  }
  surface.points *= scale_to_mm;
  return sampleNearestColours (surface, vertices);
}

} // namespace morphreg

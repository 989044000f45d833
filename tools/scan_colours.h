// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The scan's colours on the meshes register and resample write: sampled at the nearest scan surface point, or left
// to the command's own colouring (residuals, observed / filled) as --colours says.
#include <morphreg/common/colour_map.h>

#include <Eigen/Core>

#include <optional>
#include <ostream>
#include <string>

namespace morphreg
{
namespace tools
{
/** The colours of the scan \a scan_file (see loadColouredSurface) at \a vertices (mm, the scan's frame once scaled
 *  by \a scale_to_mm), each the colour of the nearest scan surface point, when \a mode is "scan", or "auto" and the
 *  scan has colours; none otherwise (the caller colours the mesh its own way). With "auto" a scan whose colours
 *  cannot be read (a missing texture) is said on \a warnings and gives none; with "scan" it is an error, as is a
 *  scan without colours (InvalidInputError naming the file).
 */
std::optional<VertexColours>
scanColoursAt (const std::string& scan_file, double scale_to_mm, const std::string& mode,
               const Eigen::Matrix3Xd& vertices, std::ostream& warnings);

/** What the vertex colours of a mesh coloured by scanColoursAt() are, for messages. */
inline const char* const kScanColoursText = "the scan's, at the nearest scan surface point";
} // namespace tools
} // namespace morphreg

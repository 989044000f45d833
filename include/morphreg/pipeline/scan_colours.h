// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file scan_colours.h
 *  \brief The scan's colours on the meshes a registration or a resampling writes: sampled at the nearest scan
 *  surface point, or left to the caller's own colouring (residuals, observed / filled) as the colour mode says.
 */
#include <morphreg/common/colour_map.h>

#include <Eigen/Core>

#include <optional>
#include <ostream>
#include <string>

namespace morphreg
{
/** \brief The colours of the scan \a scan_file (see loadColouredSurface) at \a vertices (mm, the scan's frame once
 *  scaled by \a scale_to_mm), each the colour of the nearest scan surface point, when \a mode is "scan", or "auto"
 *  and the scan has colours; none otherwise (the caller colours the mesh its own way). With "auto" a scan whose
 *  colours cannot be read (a missing texture) is said on \a warnings and gives none; with "scan" it is an error, as
 *  is a scan without colours (InvalidInputError naming the file).
 *  \param[in] scan_file the scan file
 *  \param[in] scale_to_mm the scan's scale to mm
 *  \param[in] mode "auto", "scan" or another mode (none)
 *  \param[in] vertices the mesh's vertices (mm)
 *  \param[out] warnings where an unreadable scan colour is said ("auto")
 *  \return the colours, or none
 */
std::optional<VertexColours>
scanColoursAt (const std::string& scan_file, double scale_to_mm, const std::string& mode,
               const Eigen::Matrix3Xd& vertices, std::ostream& warnings);

/** \brief What the vertex colours of a mesh coloured by scanColoursAt() are, for messages. */
inline const char* const kScanColoursText = "the scan's, at the nearest scan surface point";
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file warp_quality.h
 *  \brief How good a warp is against a known true mesh in the same topology: vertex errors, and what happens at
 *  segment borders (edge stretching across seams and in a band around them, folded triangles).
 */
#include <morphreg/mesh/triangle_mesh.h>

#include <vector>

namespace morphreg
{
/** \brief Figures of a warped mesh against the truth (mm, or ratios for edges). */
struct WarpQuality
{
  double mean_error = 0.0; ///< mean vertex distance to the truth (mm)
  double rms_error = 0.0;  ///< RMS vertex distance (mm)
  double max_error = 0.0;  ///< largest vertex distance (mm)
  double seam = 0.0;       ///< largest |edge length / true length - 1| over edges crossing a segment border
  double band = 0.0;       ///< the same over all edges within the band width of a border
  int folded = 0;          ///< triangles whose normal points against the true triangle's normal
  int folded_in_band = 0;  ///< of those, the ones within the band width of a border
  int collapsed = 0;       ///< true triangles shrunk to less than half their source area (not counted as folded)
};

/** \brief Compares \a warped with \a truth (same topology) given the per-vertex segment \a labels; distances from
 *  the borders are measured along \a truth. When the unwarped \a source is given, triangles that the truth itself
 *  collapses to less than half their source area (skinning artefacts of a synthetic truth, where no smooth warp can
 *  follow) are counted in \a collapsed and left out of the fold counts. Throws InvalidInputError if the topologies
 *  or label count differ.
 *  \param[in] warped the warped mesh
 *  \param[in] truth the true mesh, same topology
 *  \param[in] labels the segment of each vertex
 *  \param[in] band_width the width (mm) of the band around the borders
 *  \param[in] source the unwarped mesh, or nullptr
 *  \return the figures
 */

WarpQuality
evaluateWarp (const TriangleMesh& warped, const TriangleMesh& truth, const std::vector<int>& labels,
              double band_width = 100.0, const TriangleMesh* source = nullptr);

/** \brief Triangles where the surface doubles back on itself: those with an edge neighbour whose normal points more
 *  than 90 degrees away from theirs. Intrinsic to one mesh, so a warp and the true target can be compared (a
 *  re-posturing should fold no more triangles than the truth does) without matching normals between postures.
 *  \param[in] mesh the mesh
 *  \return the number of folded triangles
 */
int
countFoldedTriangles (const TriangleMesh& mesh);

} // namespace morphreg

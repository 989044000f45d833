// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file planar_cap.h
 *  \brief Finds a flat cap that closes a surface, such as the plane that closes an MRI scalp surface below the
 *  head: not anatomy, so evaluations leave it out.
 */
#include <morphreg/mesh/triangle_mesh.h>

#include <vector>

namespace morphreg
{
/** \brief How the cap is seeded and grown. */
struct PlanarCapSettings
{
  Eigen::Vector3d direction = -Eigen::Vector3d::UnitZ (); ///< the cap's outward normal, roughly (unit)
  double seed_cosine = 0.95;                              ///< seed triangles: normal . direction above this
  double max_distance = 3.0;                              ///< mm: all three vertices this close to the plane
  double max_angle_deg = 25.0;                            ///< normal within this angle of the plane's normal
  int rounds = 3;                                         ///< plane fit and selection are repeated this often
};

/** \brief Flags the triangles of the cap: seeds the cap with the triangles facing \a settings.direction, fits a
 *  plane to their centroids (least squares), then selects the triangles whose vertices lie within max_distance of
 *  the plane and whose normal is within max_angle_deg of the plane's normal (oriented like direction); the plane
 *  is refitted to the selection and the selection repeated, \a settings.rounds times in all. Returns all false
 *  when no triangle qualifies as a seed. Throws InvalidInputError for an invalid mesh or settings.
 *  \param[in] mesh the mesh, e.g. a head with a flat cut below the neck
 *  \param[in] settings the seed direction, tolerances and rounds
 *  \return one flag per triangle: true on the cap
 */

std::vector<bool>
findPlanarCap (const TriangleMesh& mesh, const PlanarCapSettings& settings = {});

} // namespace morphreg

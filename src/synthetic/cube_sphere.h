// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Internal: the fixed tessellation of the unit sphere every synthetic head is built on.
#include <morphreg/mesh/triangle_mesh.h>

namespace morphreg
{
namespace synthetic
{
/** \brief A closed, mirror-symmetric (x -> -x) triangulation of the unit sphere: a cube with \a resolution
 *  (even) cells per edge projected equal-angle onto the sphere, then remapped so that vertices crowd towards
 *  +Z by \a front_density (the face gets up to 1/(1-front_density)^2 times more vertices than the back).
 *  Vertices: 6 resolution^2 + 2. The plane x = 0 holds an exact loop of vertices (the profile line).
 */
TriangleMesh
makeCubeSphere (int resolution, double front_density);

} // namespace synthetic
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private to the library: ScanResampler's holes (connected missed vertices) and their thin plate spline fills.
#include <morphreg/mesh/mesh_topology.h>

#include <Eigen/Core>

#include <vector>

namespace morphreg
{
namespace detail
{
/** The connected components (over the mesh's edges) of the vertices whose \a missed flag is set. */
std::vector<std::vector<int>>
connectedMisses (const MeshTopology& topology, const std::vector<char>& missed);

/** Sets the displacement of the \a hole's vertices by a thin plate spline (smoothing \a lambda) interpolating the
 *  displacements of the observed vertices in \a rings rings around it (every observed vertex when none is that close:
 *  a mesh component the scan missed entirely); returns how many observed vertices the spline was fitted to. */
int
fillHole (const MeshTopology& topology, const Eigen::Matrix3Xd& reference, const std::vector<int>& hole,
          const std::vector<char>& missed, int rings, double lambda, Eigen::Matrix3Xd& displacement);
} // namespace detail
} // namespace morphreg

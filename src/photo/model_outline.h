// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Where a posed model's outline lies in a photo: the vertices at which its surface turns away from the camera (the
// contour generator), and of those the ones on the outer boundary of its projection (the silhouette a person traces).
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/photo/photo_camera.h>

#include <Eigen/Core>

#include <vector>

namespace morphreg
{
namespace detail
{
/** The posed model seen by one camera: each vertex's pixel, and how it faces the camera. */
struct ProjectedModel
{
  Eigen::Matrix2Xd pixels;  ///< 2 x N
  Eigen::VectorXd facing;   ///< the unit normal dotted with the direction to the camera (> 0: faces it)
  Eigen::Matrix3Xd normals; ///< unit vertex normals (world frame)
};

/** \a mesh (posed, world frame) projected by \a camera. */
ProjectedModel
projectModel (const TriangleMesh& mesh, const PhotoCamera& camera);

/** Whether vertex \a v faces the camera while one of its neighbours faces away: it lies on the contour generator. */
bool
onContourGenerator (const MeshTopology& topology, const Eigen::VectorXd& facing, int v);

/** The contour-generator vertices whose pixel lies on the outer boundary of the projection of \a triangles, rasterised
 *  in cells of \a cell pixels: a cell with an empty neighbour within one cell. */
std::vector<int>
silhouetteVertices (const MeshTopology& topology, const TriangleMesh::Triangles& triangles,
                    const ProjectedModel& projected, double cell);
} // namespace detail
} // namespace morphreg

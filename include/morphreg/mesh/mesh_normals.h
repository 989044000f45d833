// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file mesh_normals.h
 *  \brief Face and area-weighted vertex normals of a triangle mesh, and the plane (normal) of a point neighbourhood.
 */
#include <morphreg/mesh/triangle_mesh.h>

namespace morphreg
{
/** \brief Unit normal per triangle (counter-clockwise = outward); zero for degenerate triangles.
 *  \param[in] mesh the mesh
 *  \return 3 x numTriangles normals
 */
Eigen::Matrix3Xd
faceNormals (const TriangleMesh& mesh);

/** \brief Area-weighted unit normal per vertex; zero for vertices without (non-degenerate) triangles.
 *  \param[in] mesh the mesh
 *  \return 3 x numVertices normals
 */
Eigen::Matrix3Xd
vertexNormals (const TriangleMesh& mesh);

/** \brief Area of each triangle (mm^2).
 *  \param[in] mesh the mesh
 *  \return one area per triangle
 */
Eigen::VectorXd
triangleAreas (const TriangleMesh& mesh);

/** \brief The least-squares plane through a set of points: their centroid and the unit normal. */
struct PointPlane
{
  Eigen::Vector3d centroid; ///< the mean of the points
  Eigen::Vector3d normal;   ///< the direction of least spread (sign arbitrary; any unit vector for collinear points)
};

/** \brief The least-squares plane of \a points (3 x K, K >= 1), e.g. a scan point's k nearest neighbours.
 *  \param[in] points the points
 *  \return their centroid and plane normal
 */

PointPlane
fitPlane (const Eigen::Matrix3Xd& points);

} // namespace morphreg

#pragma once
/** \file mesh_normals.h
 *  \brief Face and area-weighted vertex normals of a triangle mesh.
 */
#include <morphreg/mesh/triangle_mesh.h>

namespace morphreg
{
/** \brief Unit normal per triangle (counter-clockwise = outward); zero for degenerate triangles. */
Eigen::Matrix3Xd
faceNormals (const TriangleMesh& mesh);

/** \brief Area-weighted unit normal per vertex; zero for vertices without (non-degenerate) triangles. */
Eigen::Matrix3Xd
vertexNormals (const TriangleMesh& mesh);

/** \brief Area of each triangle (mm^2). */
Eigen::VectorXd
triangleAreas (const TriangleMesh& mesh);

} // namespace morphreg

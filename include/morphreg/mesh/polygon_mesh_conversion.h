// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file polygon_mesh_conversion.h
 *  \brief Conversion between morphreg::TriangleMesh and pcl::PolygonMesh.
 */
#include <morphreg/mesh/triangle_mesh.h>

#include <pcl/PolygonMesh.h>

#include <string>

namespace morphreg
{
/** \brief Extracts vertices and triangles from \a mesh; throws InvalidInputError naming \a name if a
 *  polygon is not a triangle or the cloud has no x/y/z fields.
 *  \param[in] mesh the PCL mesh
 *  \param[in] name what the mesh is (e.g. its file), for messages
 *  \return its vertices (mm, double) and triangles
 */
TriangleMesh
fromPolygonMesh (const pcl::PolygonMesh& mesh, const std::string& name = "mesh");

/** \brief Builds a pcl::PolygonMesh with PointNormal vertices (normals computed from the triangles).
 *  \param[in] mesh the mesh
 *  \return the PCL mesh
 */
pcl::PolygonMesh
toPolygonMesh (const TriangleMesh& mesh);

/** \brief As toPolygonMesh, with per-vertex colours (3 x N, 0-255): fields x y z, rgb and the normal (no curvature,
 *  which nothing computes).
 *  \param[in] mesh the mesh
 *  \param[in] colours one RGB colour per vertex
 *  \return the PCL mesh
 */
pcl::PolygonMesh
toPolygonMesh (const TriangleMesh& mesh, const Eigen::Matrix<unsigned char, 3, Eigen::Dynamic>& colours);

/** \brief As the coloured toPolygonMesh, with one scalar per vertex in the float field "quality" as well (MeshLab's
 *  per-vertex quality, e.g. the residual in mm behind the colours, which its quality mapper can rescale).
 *  Throws InvalidInputError unless there is one colour and one value per vertex.
 *  \param[in] mesh the mesh
 *  \param[in] colours one RGB colour per vertex
 *  \param[in] quality one value per vertex
 *  \return the PCL mesh
 */

pcl::PolygonMesh
toPolygonMesh (const TriangleMesh& mesh, const Eigen::Matrix<unsigned char, 3, Eigen::Dynamic>& colours,
               const Eigen::VectorXd& quality);

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file triangle_mesh.h
 *  \brief A plain triangle mesh (Eigen matrices, millimetres) used by the numerics; convertible to pcl::PolygonMesh.
 */
#include <Eigen/Core>

#include <string>

namespace morphreg
{
/** \brief Vertex positions (3 x N, mm) and triangles (3 x M, 0-based vertex indices).
 *  Algorithms work on this compact form; pcl::PolygonMesh is the exchange format (see polygon_mesh_conversion.h).
 */
struct TriangleMesh
{
  using Vertices = Eigen::Matrix<double, 3, Eigen::Dynamic>; ///< one column per vertex
  using Triangles = Eigen::Matrix<int, 3, Eigen::Dynamic>;   ///< one column of vertex indices per triangle

  Vertices vertices;   ///< positions, mm
  Triangles triangles; ///< 0-based vertex indices; counter-clockwise order gives the outward normal

  /** \brief The number of vertices.
   *  \return vertices.cols ()
   */
  Eigen::Index
  numVertices () const
  {
    return vertices.cols ();
  }

  /** \brief The number of triangles.
   *  \return triangles.cols ()
   */
  Eigen::Index
  numTriangles () const
  {
    return triangles.cols ();
  }
};

/** \brief Throws InvalidInputError naming \a name if the mesh has no vertices or triangles, non-finite
 *  vertices, or triangle indices out of range.
 *  \param[in] mesh the mesh to check
 *  \param[in] name what the mesh is (e.g. its file), for the message
 */
void
validateMesh (const TriangleMesh& mesh, const std::string& name);

/** \brief Throws InvalidInputError naming \a name if \a b does not share \a a's vertex count and triangles.
 *  \param[in] a the reference mesh
 *  \param[in] b the mesh to check
 *  \param[in] name what \a b is, for the message
 */

void
requireSameTopology (const TriangleMesh& a, const TriangleMesh& b, const std::string& name);

} // namespace morphreg

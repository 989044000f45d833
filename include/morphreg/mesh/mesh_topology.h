// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file mesh_topology.h
 *  \brief Vertex adjacency, edges with their faces, boundaries, k-ring growth and edge-graph geodesics.
 */
#include <morphreg/mesh/triangle_mesh.h>

#include <array>
#include <limits>
#include <memory>
#include <vector>

namespace morphreg
{
/** \brief Connectivity of a triangle mesh, built once and queried often (adjacency in CSR form). */
class MeshTopology
{
public:
  using Ptr = std::shared_ptr<MeshTopology>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const MeshTopology>; ///< shared pointer to const

  /** \brief An undirected edge (a < b) and the number of triangles that share it. */
  struct Edge
  {
    int a;          ///< the lower vertex index
    int b;          ///< the higher vertex index
    int face_count; ///< triangles that use the edge: 2 inside a closed surface, 1 on a border
  };

  /** \brief Builds the topology of \a triangles over \a num_vertices vertices (indices must be valid).
   *  \param[in] triangles 3 x M vertex indices
   *  \param[in] num_vertices the number of vertices, including any no triangle uses
   */
  MeshTopology (const TriangleMesh::Triangles& triangles, Eigen::Index num_vertices);

  /** \brief Convenience: the topology of \a mesh.
   *  \param[in] mesh the mesh
   */
  explicit MeshTopology (const TriangleMesh& mesh);

  /** \brief The number of vertices.
   *  \return the vertex count given at construction
   */
  Eigen::Index
  numVertices () const
  {
    return static_cast<Eigen::Index> (offsets_.size ()) - 1;
  }

  /** \brief The number of triangles.
   *  \return the triangle count
   */
  Eigen::Index
  numTriangles () const
  {
    return num_triangles_;
  }

  /** \brief Sorted vertex neighbours of \a v as [begin, end) pointers into the CSR array.
   *  \param[in] v a vertex index
   *  \return the range of its neighbours' indices
   */
  std::pair<const int*, const int*>
  neighbours (int v) const
  {
    return {neighbours_.data () + offsets_[v], neighbours_.data () + offsets_[v + 1]};
  }

  /** \brief Number of neighbours (valence) of \a v.
   *  \param[in] v a vertex index
   *  \return its valence
   */
  int
  valence (int v) const
  {
    return offsets_[v + 1] - offsets_[v];
  }

  /** \brief All undirected edges, each once.
   *  \return the edges
   */
  const std::vector<Edge>&
  edges () const
  {
    return edges_;
  }

  /** \brief Edges used by exactly one triangle (the borders of holes).
   *  \return the border edges as vertex pairs
   */
  std::vector<std::array<int, 2>>
  boundaryEdges () const;

  /** \brief Per-vertex flag: true on a boundary edge.
   *  \return one flag per vertex
   */
  std::vector<bool>
  boundaryVertexMask () const;

  /** \brief Indices of the vertices on boundary edges.
   *  \return the vertex indices, ascending
   */
  std::vector<int>
  boundaryVertices () const;

  /** \brief V - E + F (2 for a closed genus-0 surface).
   *  \return the Euler characteristic
   */
  long
  eulerCharacteristic () const;

  /** \brief Whether every edge has exactly two triangles and every vertex's star is a single fan.
   *  \return true for a closed 2-manifold
   */
  bool
  isClosedManifold () const;

  /** \brief Ring index of each vertex grown from \a seeds over the adjacency: 0 for seeds, k for the
   *  k-th ring, -1 for vertices farther than \a max_rings.
   *  \param[in] seeds the vertices of ring 0
   *  \param[in] max_rings the number of rings grown
   *  \return one ring index per vertex
   */
  std::vector<int>
  ringIndex (const std::vector<int>& seeds, int max_rings) const;

  /** \brief Shortest edge-path lengths from the nearest of \a sources (Dijkstra over the edges with
   *  Euclidean lengths from \a vertices); +inf beyond \a max_distance or where unreachable.
   *  \param[in] vertices the vertex positions (3 x N, mm)
   *  \param[in] sources the vertices at distance 0
   *  \param[in] max_distance the search stops beyond this distance (mm)
   *  \return one distance per vertex (mm)
   */

  std::vector<double>
  geodesicDistances (const TriangleMesh::Vertices& vertices, const std::vector<int>& sources,
                     double max_distance = std::numeric_limits<double>::infinity ()) const;

private:
  std::vector<int> offsets_;
  std::vector<int> neighbours_;
  std::vector<Edge> edges_;
  Eigen::Index num_triangles_ = 0;
  bool stars_are_fans_ = true;
};

} // namespace morphreg

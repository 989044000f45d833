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
  using Ptr = std::shared_ptr<MeshTopology>;
  using ConstPtr = std::shared_ptr<const MeshTopology>;

  /** \brief An undirected edge (a < b) and the number of triangles that share it. */
  struct Edge
  {
    int a;
    int b;
    int face_count;
  };

  /** \brief Builds the topology of \a triangles over \a num_vertices vertices (indices must be valid). */
  MeshTopology (const TriangleMesh::Triangles& triangles, Eigen::Index num_vertices);

  /** \brief Convenience: the topology of \a mesh. */
  explicit MeshTopology (const TriangleMesh& mesh);

  Eigen::Index
  numVertices () const
  {
    return static_cast<Eigen::Index> (offsets_.size ()) - 1;
  }

  Eigen::Index
  numTriangles () const
  {
    return num_triangles_;
  }

  /** \brief Sorted vertex neighbours of \a v as [begin, end) pointers into the CSR array. */
  std::pair<const int*, const int*>
  neighbours (int v) const
  {
    return {neighbours_.data () + offsets_[v], neighbours_.data () + offsets_[v + 1]};
  }

  /** \brief Number of neighbours (valence) of \a v. */
  int
  valence (int v) const
  {
    return offsets_[v + 1] - offsets_[v];
  }

  /** \brief All undirected edges, each once. */
  const std::vector<Edge>&
  edges () const
  {
    return edges_;
  }

  /** \brief Edges used by exactly one triangle (the borders of holes). */
  std::vector<std::array<int, 2>>
  boundaryEdges () const;

  /** \brief Per-vertex flag: true on a boundary edge. */
  std::vector<bool>
  boundaryVertexMask () const;

  /** \brief Indices of the vertices on boundary edges. */
  std::vector<int>
  boundaryVertices () const;

  /** \brief V - E + F (2 for a closed genus-0 surface). */
  long
  eulerCharacteristic () const;

  /** \brief True if every edge has exactly two triangles and every vertex's star is a single fan. */
  bool
  isClosedManifold () const;

  /** \brief Ring index of each vertex grown from \a seeds over the adjacency: 0 for seeds, k for the
   *  k-th ring, -1 for vertices farther than \a max_rings.
   */
  std::vector<int>
  ringIndex (const std::vector<int>& seeds, int max_rings) const;

  /** \brief Shortest edge-path lengths from the nearest of \a sources (Dijkstra over the edges with
   *  Euclidean lengths from \a vertices); +inf beyond \a max_distance or where unreachable.
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

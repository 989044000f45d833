// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_topology.h>

#include <algorithm>
#include <array>
#include <functional>
#include <queue>

namespace morphreg
{
namespace
{
/** Builds a CSR list of the triangles incident to each vertex. */
void
vertexFaces (const TriangleMesh::Triangles& triangles, Eigen::Index num_vertices, std::vector<int>& offsets,
             std::vector<int>& faces)
{
  offsets.assign (num_vertices + 1, 0);
  for (Eigen::Index t = 0; t < triangles.cols (); ++t)
    for (int c = 0; c < 3; ++c)
      ++offsets[triangles (c, t) + 1];
  for (Eigen::Index v = 0; v < num_vertices; ++v)
    offsets[v + 1] += offsets[v];
  faces.resize (offsets.back ());
  std::vector<int> fill (offsets.begin (), offsets.end () - 1);
  for (Eigen::Index t = 0; t < triangles.cols (); ++t)
    for (int c = 0; c < 3; ++c)
      faces[fill[triangles (c, t)]++] = static_cast<int> (t);
}
/** Each undirected edge once (a < b, sorted) with the number of triangles that use it, gathered per lower vertex
 *  from its incident triangles (\a face_offsets, \a faces: vertexFaces). */
std::vector<MeshTopology::Edge>
countEdges (const TriangleMesh::Triangles& triangles, Eigen::Index num_vertices, const std::vector<int>& face_offsets,
            const std::vector<int>& faces)
{
  std::vector<MeshTopology::Edge> edges;
  std::vector<int> higher;
  for (Eigen::Index a = 0; a < num_vertices; ++a) {
    higher.clear ();
    for (int f = face_offsets[a]; f < face_offsets[a + 1]; ++f) {
      if (f > face_offsets[a] && faces[f] == faces[f - 1])
        continue; // a triangle that uses a twice is listed twice
      for (int c = 0; c < 3; ++c) {
        const int x = triangles (c, faces[f]), y = triangles ((c + 1) % 3, faces[f]);
        if (std::min (x, y) == a)
          higher.push_back (std::max (x, y));
      }
    }
    std::sort (higher.begin (), higher.end ());
    for (std::size_t k = 0; k < higher.size (); ++k)
      if (k > 0 && higher[k] == higher[k - 1])
        ++edges.back ().face_count;
      else
        edges.push_back ({static_cast<int> (a), higher[k], 1});
  }
  return edges;
}

/** The CSR adjacency of \a edges: sorted neighbours of vertex v in neighbours[offsets[v], offsets[v + 1]). */
void
adjacency (const std::vector<MeshTopology::Edge>& edges, Eigen::Index num_vertices, std::vector<int>& offsets,
           std::vector<int>& neighbours)
{
  offsets.assign (num_vertices + 1, 0);
  for (const auto& e : edges) {
    ++offsets[e.a + 1];
    ++offsets[e.b + 1];
  }
  for (Eigen::Index v = 0; v < num_vertices; ++v)
    offsets[v + 1] += offsets[v];
  neighbours.resize (offsets.back ());
  std::vector<int> fill (offsets.begin (), offsets.end () - 1);
  for (const auto& e : edges) {
    neighbours[fill[e.a]++] = e.b;
    neighbours[fill[e.b]++] = e.a;
  }
  for (Eigen::Index v = 0; v < num_vertices; ++v)
    std::sort (neighbours.begin () + offsets[v], neighbours.begin () + offsets[v + 1]);
}

/** The link of vertex \a v: its triangles' edges opposite it; false if a triangle uses v twice or not at all. */
bool
vertexLink (const TriangleMesh::Triangles& triangles, const int* first_face, const int* last_face, int v,
            std::vector<std::array<int, 2>>& link)
{
  link.clear ();
  for (const int* face = first_face; face != last_face; ++face) {
    std::array<int, 2> others{};
    int n = 0;
    for (int c = 0; c < 3; ++c)
      if (triangles (c, *face) != v) {
        if (n < 2)
          others[n] = triangles (c, *face);
        ++n;
      }
    if (n != 2)
      return false;
    link.push_back (others);
  }
  return true;
}

/** True if the edges \a link form one cycle (the link of a closed manifold vertex): every vertex on two of them
 *  and a walk through them comes back after all of them. */
bool
isSingleCycle (const std::vector<std::array<int, 2>>& link, std::vector<int>& ends)
{
  ends.clear ();
  for (const auto& edge : link)
    ends.insert (ends.end (), edge.begin (), edge.end ());
  std::sort (ends.begin (), ends.end ());
  for (std::size_t k = 0; k < ends.size (); k += 2)
    if (ends[k] != ends[k + 1] || (k + 2 < ends.size () && ends[k + 2] == ends[k]))
      return false;
  const int start = link[0][0];
  int current = link[0][1];
  std::size_t walked = 1, last = 0;
  while (current != start && walked <= link.size ()) {
    std::size_t next = 0;
    while (next < link.size () && (next == last || (link[next][0] != current && link[next][1] != current)))
      ++next;
    if (next == link.size ())
      return false;
    current = link[next][0] == current ? link[next][1] : link[next][0];
    last = next;
    ++walked;
  }
  return walked == link.size ();
}

/** True if the star of every vertex of \a triangles is a single fan (vertices in no triangle pass). */
bool
starsAreFans (const TriangleMesh::Triangles& triangles, Eigen::Index num_vertices, const std::vector<int>& face_offsets,
              const std::vector<int>& faces)
{
  std::vector<std::array<int, 2>> link;
  std::vector<int> ends;
  for (Eigen::Index v = 0; v < num_vertices; ++v) {
    if (!vertexLink (triangles, faces.data () + face_offsets[v], faces.data () + face_offsets[v + 1],
                     static_cast<int> (v), link))
      return false;
    if (!link.empty () && !isSingleCycle (link, ends))
      return false;
  }
  return true;
}
} // namespace

MeshTopology::MeshTopology (const TriangleMesh& mesh) : MeshTopology (mesh.triangles, mesh.numVertices ()) {}

MeshTopology::MeshTopology (const TriangleMesh::Triangles& triangles, Eigen::Index num_vertices)
  : num_triangles_ (triangles.cols ())
{
  if (triangles.size () > 0 && (triangles.minCoeff () < 0 || triangles.maxCoeff () >= num_vertices))
    throw InvalidInputError ("MeshTopology: triangle indices out of range of the vertex count");
  std::vector<int> face_offsets, faces;
  vertexFaces (triangles, num_vertices, face_offsets, faces);
  edges_ = countEdges (triangles, num_vertices, face_offsets, faces);
  adjacency (edges_, num_vertices, offsets_, neighbours_);
  stars_are_fans_ = starsAreFans (triangles, num_vertices, face_offsets, faces);
}

std::vector<std::array<int, 2>>
MeshTopology::boundaryEdges () const
{
  std::vector<std::array<int, 2>> result;
  for (const auto& e : edges_)
    if (e.face_count == 1)
      result.push_back ({e.a, e.b});
  return result;
}

std::vector<bool>
MeshTopology::boundaryVertexMask () const
{
  std::vector<bool> mask (numVertices (), false);
  for (const auto& e : edges_)
    if (e.face_count == 1)
      mask[e.a] = mask[e.b] = true;
  return mask;
}

std::vector<int>
MeshTopology::boundaryVertices () const
{
  const auto mask = boundaryVertexMask ();
  std::vector<int> result;
  for (size_t v = 0; v < mask.size (); ++v)
    if (mask[v])
      result.push_back (static_cast<int> (v));
  return result;
}

long
MeshTopology::eulerCharacteristic () const
{
  return static_cast<long> (numVertices ()) - static_cast<long> (edges_.size ()) + static_cast<long> (num_triangles_);
}

bool
MeshTopology::isClosedManifold () const
{
  if (!stars_are_fans_)
    return false;
  for (const auto& e : edges_)
    if (e.face_count != 2)
      return false;
  for (Eigen::Index v = 0; v < numVertices (); ++v)
    if (valence (v) == 0)
      return false;
  return true;
}

std::vector<int>
MeshTopology::ringIndex (const std::vector<int>& seeds, int max_rings) const
{
  std::vector<int> ring (numVertices (), -1);
  std::vector<int> frontier;
  for (int s : seeds) {
    if (s < 0 || s >= numVertices ())
      throw InvalidInputError ("MeshTopology::ringIndex: seed vertex out of range");
    if (ring[s] != 0) {
      ring[s] = 0;
      frontier.push_back (s);
    }
  }
  for (int k = 1; k <= max_rings && !frontier.empty (); ++k) {
    std::vector<int> next;
    for (int v : frontier) {
      auto [begin, end] = neighbours (v);
      for (const int* n = begin; n != end; ++n)
        if (ring[*n] < 0) {
          ring[*n] = k;
          next.push_back (*n);
        }
    }
    frontier.swap (next);
  }
  return ring;
}

std::vector<double>
MeshTopology::geodesicDistances (const TriangleMesh::Vertices& vertices, const std::vector<int>& sources,
                                 double max_distance) const
{
  if (vertices.cols () != numVertices ())
    throw InvalidInputError ("MeshTopology::geodesicDistances: vertex count does not match the topology");
  const double inf = std::numeric_limits<double>::infinity ();
  std::vector<double> distance (numVertices (), inf);
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> queue;
  for (int s : sources) {
    if (s < 0 || s >= numVertices ())
      throw InvalidInputError ("MeshTopology::geodesicDistances: source vertex out of range");
    distance[s] = 0.0;
    queue.push ({0.0, s});
  }
  while (!queue.empty ()) {
    const auto [d, v] = queue.top ();
    queue.pop ();
    if (d > distance[v])
      continue;
    auto [begin, end] = neighbours (v);
    for (const int* n = begin; n != end; ++n) {
      const double candidate = d + (vertices.col (*n) - vertices.col (v)).norm ();
      if (candidate < distance[*n] && candidate <= max_distance) {
        distance[*n] = candidate;
        queue.push ({candidate, *n});
      }
    }
  }
  return distance;
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/triangle_mesh.h>

#include <sstream>

namespace morphreg
{
void
validateMesh (const TriangleMesh& mesh, const std::string& name)
{
  if (mesh.numVertices () == 0)
    throw InvalidInputError (name + ": mesh has no vertices");
  if (mesh.numTriangles () == 0)
    throw InvalidInputError (name + ": mesh has no triangles");
  for (Eigen::Index i = 0; i < mesh.numVertices (); ++i)
    if (!mesh.vertices.col (i).allFinite ()) {
      std::ostringstream msg;
      msg << name << ": vertex " << i << " is not finite (NaN or Inf)";
      throw InvalidInputError (msg.str ());
    }
  for (Eigen::Index t = 0; t < mesh.numTriangles (); ++t)
    for (int c = 0; c < 3; ++c) {
      const int v = mesh.triangles (c, t);
      if (v < 0 || v >= mesh.numVertices ()) {
        std::ostringstream msg;
        msg << name << ": triangle " << t << " references vertex " << v << ", but the mesh has " << mesh.numVertices ()
            << " vertices";
        throw InvalidInputError (msg.str ());
      }
    }
}

void
requireSameTopology (const TriangleMesh& a, const TriangleMesh& b, const std::string& name)
{
  if (a.numVertices () != b.numVertices ()) {
    std::ostringstream msg;
    msg << name << ": " << b.numVertices () << " vertices, expected " << a.numVertices ()
        << " (meshes must be in correspondence)";
    throw InvalidInputError (msg.str ());
  }
  if (a.triangles != b.triangles)
    throw InvalidInputError (name + ": triangles differ from the reference (meshes must share one topology)");
}

} // namespace morphreg

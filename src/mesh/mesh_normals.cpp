// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/mesh/mesh_normals.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

namespace morphreg
{
namespace
{
Eigen::Vector3d
triangleCross (const TriangleMesh& mesh, Eigen::Index t)
{
  const Eigen::Vector3d a = mesh.vertices.col (mesh.triangles (0, t));
  const Eigen::Vector3d b = mesh.vertices.col (mesh.triangles (1, t));
  const Eigen::Vector3d c = mesh.vertices.col (mesh.triangles (2, t));
  return (b - a).cross (c - a);
}
} // namespace

Eigen::Matrix3Xd
faceNormals (const TriangleMesh& mesh)
{
  Eigen::Matrix3Xd normals (3, mesh.numTriangles ());
  for (Eigen::Index t = 0; t < mesh.numTriangles (); ++t) {
    const Eigen::Vector3d n = triangleCross (mesh, t);
    const double length = n.norm ();
    normals.col (t) = length > 0.0 ? Eigen::Vector3d (n / length) : Eigen::Vector3d::Zero ();
  }
  return normals;
}

Eigen::Matrix3Xd
vertexNormals (const TriangleMesh& mesh)
{
  Eigen::Matrix3Xd normals = Eigen::Matrix3Xd::Zero (3, mesh.numVertices ());
  for (Eigen::Index t = 0; t < mesh.numTriangles (); ++t) {
    const Eigen::Vector3d n = triangleCross (mesh, t); // length = 2 * area: area weighting for free
    for (int c = 0; c < 3; ++c)
      normals.col (mesh.triangles (c, t)) += n;
  }
  for (Eigen::Index v = 0; v < normals.cols (); ++v) {
    const double length = normals.col (v).norm ();
    if (length > 0.0)
      normals.col (v) /= length;
  }
  return normals;
}

Eigen::VectorXd
triangleAreas (const TriangleMesh& mesh)
{
  Eigen::VectorXd areas (mesh.numTriangles ());
  for (Eigen::Index t = 0; t < mesh.numTriangles (); ++t)
    areas[t] = 0.5 * triangleCross (mesh, t).norm ();
  return areas;
}

PointPlane
fitPlane (const Eigen::Matrix3Xd& points)
{
  PointPlane plane;
  plane.centroid = points.rowwise ().mean ();
  const Eigen::Matrix3Xd centred = points.colwise () - plane.centroid;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (centred * centred.transpose ());
  plane.normal = solver.eigenvectors ().col (0);
  return plane;
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include "cube_sphere.h"

#include <morphreg/common/error.h>

#include <Eigen/Geometry>

#include <cmath>
#include <map>
#include <tuple>
#include <vector>

namespace morphreg
{
namespace synthetic
{
namespace
{
using Lattice = std::tuple<int, int, int>;

/** Equal-angle projection of a cube-lattice point (coordinates in [-h, h]) to the unit sphere. */
Eigen::Vector3d
latticeToSphere (const Lattice& p, int h)
{
  const double quarter = M_PI / 4.0;
  Eigen::Vector3d d (std::tan (quarter * std::get<0> (p) / h), std::tan (quarter * std::get<1> (p) / h),
                     std::tan (quarter * std::get<2> (p) / h));
  return d.normalized ();
}

/** Moves a unit direction towards +Z: polar angle t -> t - density * sin(t) (azimuth kept, so x = 0 stays x = 0). */
Eigen::Vector3d
crowdTowardsFront (const Eigen::Vector3d& d, double density)
{
  const double polar = std::acos (std::clamp (d.z (), -1.0, 1.0));
  const double radial = std::hypot (d.x (), d.y ());
  if (radial < 1e-12)
    return d;
  const double remapped = polar - density * std::sin (polar);
  const double s = std::sin (remapped) / radial;
  return Eigen::Vector3d (d.x () * s, d.y () * s, std::cos (remapped));
}

/** One face of the cube: lattice point for (u, v) in [-h, h]^2 on the face with normal axis `axis` and sign. */
Lattice
facePoint (int axis, int sign, int u, int v, int h)
{
  int c[3];
  c[axis] = sign * h;
  c[(axis + 1) % 3] = u;
  c[(axis + 2) % 3] = v;
  return {c[0], c[1], c[2]};
}
} // namespace

TriangleMesh
makeCubeSphere (int resolution, double front_density)
{
  if (resolution < 2 || resolution % 2 != 0)
    throw InvalidInputError ("makeCubeSphere: resolution must be an even number >= 2");
  if (front_density < 0.0 || front_density >= 1.0)
    throw InvalidInputError ("makeCubeSphere: front_density must be in [0, 1)");
  const int h = resolution / 2;
  std::map<Lattice, int> index;
  std::vector<Eigen::Vector3d> vertices;
  auto vertexOf = [&] (const Lattice& p) {
    auto it = index.find (p);
    if (it != index.end ())
      return it->second;
    const int id = static_cast<int> (vertices.size ());
    index.emplace (p, id);
    vertices.push_back (crowdTowardsFront (latticeToSphere (p, h), front_density));
    return id;
  };

  std::vector<Eigen::Vector3i> triangles;
  for (int axis = 0; axis < 3; ++axis)
    for (int sign : {-1, 1})
      for (int u = -h; u < h; ++u)
        for (int v = -h; v < h; ++v) {
          const int q[4] = {vertexOf (facePoint (axis, sign, u, v, h)), vertexOf (facePoint (axis, sign, u + 1, v, h)),
                            vertexOf (facePoint (axis, sign, u + 1, v + 1, h)),
                            vertexOf (facePoint (axis, sign, u, v + 1, h))};
          // Split along the shorter diagonal; ties by the side of x = 0 so the mesh stays mirror-symmetric.
          const double d02 = (vertices[q[0]] - vertices[q[2]]).squaredNorm ();
          const double d13 = (vertices[q[1]] - vertices[q[3]]).squaredNorm ();
          const Eigen::Vector3d centre = (vertices[q[0]] + vertices[q[2]]) / 2.0;
          const bool split02 = std::abs (d02 - d13) > 1e-12 * (d02 + d13) ? d02 < d13 : centre.x () > 0.0;
          const Eigen::Vector3i t1 = split02 ? Eigen::Vector3i (q[0], q[1], q[2]) : Eigen::Vector3i (q[0], q[1], q[3]);
          const Eigen::Vector3i t2 = split02 ? Eigen::Vector3i (q[0], q[2], q[3]) : Eigen::Vector3i (q[1], q[2], q[3]);
          for (Eigen::Vector3i t : {t1, t2}) {
            const Eigen::Vector3d a = vertices[t[0]], b = vertices[t[1]], c = vertices[t[2]];
            if ((b - a).cross (c - a).dot (a + b + c) < 0.0)
              std::swap (t[1], t[2]); // outward, counter-clockwise
            triangles.push_back (t);
          }
        }

  TriangleMesh mesh;
  mesh.vertices.resize (3, static_cast<Eigen::Index> (vertices.size ()));
  for (size_t i = 0; i < vertices.size (); ++i)
    mesh.vertices.col (i) = vertices[i];
  mesh.triangles.resize (3, static_cast<Eigen::Index> (triangles.size ()));
  for (size_t t = 0; t < triangles.size (); ++t)
    mesh.triangles.col (t) = triangles[t];
  return mesh;
}

} // namespace synthetic
} // namespace morphreg

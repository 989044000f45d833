// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/mesh/surface_sampling.h>

#include <cmath>
#include <random>

namespace morphreg
{
SurfaceSamples
sampleSurfaceUniformly (const TriangleMesh& mesh, double area_per_sample, std::uint64_t seed,
                        const std::vector<bool>& excluded)
{
  validateMesh (mesh, "sampleSurfaceUniformly mesh");
  if (!(area_per_sample > 0.0) || !std::isfinite (area_per_sample))
    throw InvalidInputError ("sampleSurfaceUniformly: the area per sample must be positive and finite, got " +
                             std::to_string (area_per_sample));
  if (!excluded.empty () && excluded.size () != static_cast<size_t> (mesh.numTriangles ()))
    throw InvalidInputError ("sampleSurfaceUniformly: " + std::to_string (excluded.size ()) + " exclusion flags for " +
                             std::to_string (mesh.numTriangles ()) + " triangles");
  Eigen::VectorXd weights = triangleAreas (mesh);
  for (size_t t = 0; t < excluded.size (); ++t)
    if (excluded[t])
      weights[static_cast<Eigen::Index> (t)] = 0.0;
  const double area = weights.sum ();
  if (!(area > 0.0))
    throw InvalidInputError ("sampleSurfaceUniformly: the mesh has no area left to sample");

  const auto count = static_cast<Eigen::Index> (std::max (1.0, std::round (area / area_per_sample)));
  std::mt19937_64 rng (seed);
  std::discrete_distribution<int> pick (weights.data (), weights.data () + weights.size ());
  std::uniform_real_distribution<double> unit;
  SurfaceSamples samples;
  samples.points.resize (3, count);
  samples.triangles.resize (static_cast<size_t> (count));
  for (Eigen::Index i = 0; i < count; ++i) {
    const int t = pick (rng);
    double a = unit (rng), b = unit (rng);
    if (a + b > 1.0) { // fold the unit square onto the triangle: uniform by area
      a = 1.0 - a;
      b = 1.0 - b;
    }
    samples.points.col (i) = (1.0 - a - b) * mesh.vertices.col (mesh.triangles (0, t)) +
                             a * mesh.vertices.col (mesh.triangles (1, t)) +
                             b * mesh.vertices.col (mesh.triangles (2, t));
    samples.triangles[static_cast<size_t> (i)] = t;
  }
  return samples;
}

} // namespace morphreg

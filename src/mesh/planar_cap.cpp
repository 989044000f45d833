// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/mesh/planar_cap.h>

#include <Eigen/Eigenvalues>

#include <cmath>

namespace morphreg
{
namespace
{
/** Least-squares plane (unit normal oriented like \a direction, offset) through the centroids of \a selected. */
std::pair<Eigen::Vector3d, double>
fitPlane (const Eigen::Matrix3Xd& centroids, const Eigen::Matrix3Xd& normals, const std::vector<bool>& selected,
          const Eigen::Vector3d& direction)
{
  Eigen::Vector3d mean = Eigen::Vector3d::Zero (), mean_normal = Eigen::Vector3d::Zero ();
  double count = 0.0;
  for (Eigen::Index t = 0; t < centroids.cols (); ++t)
    if (selected[static_cast<size_t> (t)]) {
      mean += centroids.col (t);
      mean_normal += normals.col (t);
      count += 1.0;
    }
  mean /= count;
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero ();
  for (Eigen::Index t = 0; t < centroids.cols (); ++t)
    if (selected[static_cast<size_t> (t)])
      scatter += (centroids.col (t) - mean) * (centroids.col (t) - mean).transpose ();
  Eigen::Vector3d normal = Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> (scatter).eigenvectors ().col (0);
  // Fewer than three centroids do not determine a plane: their triangles' mean normal does.
  if (count < 3.0)
    normal = mean_normal.normalized ();
  if (normal.dot (direction) < 0.0)
    normal = -normal;
  return {normal, normal.dot (mean)};
}
} // namespace

std::vector<bool>
findPlanarCap (const TriangleMesh& mesh, const PlanarCapSettings& settings)
{
  validateMesh (mesh, "findPlanarCap mesh");
  const double direction_norm = settings.direction.norm ();
  if (!(direction_norm > 0.0) || !settings.direction.allFinite () || !(settings.max_distance >= 0.0) ||
      !(settings.max_angle_deg >= 0.0 && settings.max_angle_deg <= 180.0) || settings.rounds < 1 ||
      !(std::abs (settings.seed_cosine) <= 1.0))
    throw InvalidInputError ("findPlanarCap: need a non-zero direction, a distance >= 0, an angle in [0, 180] "
                             "degrees, a seed cosine in [-1, 1] and at least one round");
  const Eigen::Vector3d direction = settings.direction / direction_norm;
  const Eigen::Matrix3Xd normals = faceNormals (mesh);
  const Eigen::Index m = mesh.numTriangles ();
  Eigen::Matrix3Xd centroids (3, m);
  std::vector<bool> cap (static_cast<size_t> (m), false);
  bool any = false;
  for (Eigen::Index t = 0; t < m; ++t) {
    centroids.col (t) = (mesh.vertices.col (mesh.triangles (0, t)) + mesh.vertices.col (mesh.triangles (1, t)) +
                         mesh.vertices.col (mesh.triangles (2, t))) /
                        3.0;
    cap[static_cast<size_t> (t)] = normals.col (t).dot (direction) > settings.seed_cosine;
    any = any || cap[static_cast<size_t> (t)];
  }
  const double min_cosine = std::cos (settings.max_angle_deg * M_PI / 180.0);
  for (int round = 0; round < settings.rounds && any; ++round) {
    const auto [normal, offset] = fitPlane (centroids, normals, cap, direction);
    any = false;
    for (Eigen::Index t = 0; t < m; ++t) {
      bool near = normals.col (t).dot (normal) >= min_cosine;
      for (int k = 0; k < 3 && near; ++k)
        near = std::abs (normal.dot (mesh.vertices.col (mesh.triangles (k, t))) - offset) <= settings.max_distance;
      cap[static_cast<size_t> (t)] = near;
      any = any || near;
    }
  }
  return cap;
}

} // namespace morphreg

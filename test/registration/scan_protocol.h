// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The scan protocol of the registration accuracy tests: a random similarity, an area-uniform scan with a crown cap and
// an under-chin hole, Gaussian noise, uniform outliers and noisy landmarks, with the posed truth kept.
#include <morphreg/common/landmarks.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/mesh/triangle_mesh.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <numeric>
#include <random>

namespace morphreg
{
namespace test
{
struct ProtocolSettings
{
  int points = 40000;
  double max_rotation_deg = 30.0;
  double min_scale = 0.8;
  double max_scale = 1.2;
  double translation_sigma = 50.0;
  double crown_fraction = 0.12; ///< of the surface area, taken from the top (+Y)
  double chin_fraction = 0.08;  ///< of the surface area, the most downward-facing triangles in front
  double noise_sigma = 1.0;
  double outlier_fraction = 0.05; ///< uniform in the head's bounding box grown by 20 %
  double landmark_sigma = 2.0;
};

struct ProtocolScan
{
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud;
  Eigen::Matrix3Xd truth;      ///< the head's vertices posed into the scan frame
  Eigen::Matrix4d pose;        ///< head -> scan similarity
  LandmarkPositions landmarks; ///< noisy landmark positions in the scan frame
};

/** Triangles removed as holes: the top crown cap and the most downward-facing front triangles (under the chin). */
inline std::vector<bool>
protocolHoles (const TriangleMesh& head, const Eigen::VectorXd& areas, const ProtocolSettings& settings)
{
  const Eigen::Index m = head.numTriangles ();
  const double total = areas.sum ();
  std::vector<bool> removed (m, false);
  std::vector<double> height (m), downward (m);
  const Eigen::Matrix3Xd normals = faceNormals (head);
  for (Eigen::Index t = 0; t < m; ++t) {
    Eigen::Vector3d c = Eigen::Vector3d::Zero ();
    for (int k = 0; k < 3; ++k)
      c += head.vertices.col (head.triangles (k, t)) / 3.0;
    height[t] = c.y ();
    downward[t] = c.z () > 0.0 ? -normals (1, t) : -2.0;
  }
  auto take = [&] (const std::vector<double>& key, double fraction) {
    std::vector<Eigen::Index> order (m);
    std::iota (order.begin (), order.end (), 0);
    std::sort (order.begin (), order.end (), [&] (Eigen::Index a, Eigen::Index b) { return key[a] > key[b]; });
    double area = 0.0;
    for (Eigen::Index t : order) {
      if (area >= fraction * total)
        break;
      if (!removed[t]) {
        removed[t] = true;
        area += areas[t];
      }
    }
  };
  take (height, settings.crown_fraction);
  take (downward, settings.chin_fraction);
  return removed;
}

inline ProtocolScan
simulateProtocolScan (const TriangleMesh& head, const LandmarkVertices& landmarks, std::uint64_t seed,
                      const ProtocolSettings& settings = {})
{
  std::mt19937_64 rng (seed);
  std::normal_distribution<double> gauss;
  std::uniform_real_distribution<double> unit;
  const Eigen::Vector3d axis = Eigen::Vector3d (gauss (rng), gauss (rng), gauss (rng)).normalized ();
  const double angle = unit (rng) * settings.max_rotation_deg * M_PI / 180.0;
  const double scale = settings.min_scale + unit (rng) * (settings.max_scale - settings.min_scale);
  const Eigen::Matrix3d rotation = Eigen::AngleAxisd (angle, axis).toRotationMatrix ();
  const Eigen::Vector3d translation (settings.translation_sigma * gauss (rng), settings.translation_sigma * gauss (rng),
                                     settings.translation_sigma * gauss (rng));
  ProtocolScan scan;
  scan.pose.setIdentity ();
  scan.pose.topLeftCorner<3, 3> () = scale * rotation;
  scan.pose.topRightCorner<3, 1> () = translation;
  scan.truth = (scale * rotation * head.vertices).colwise () + translation;

  const Eigen::VectorXd areas = triangleAreas (head);
  const std::vector<bool> removed = protocolHoles (head, areas, settings);
  std::vector<double> weights (areas.size ());
  for (Eigen::Index t = 0; t < areas.size (); ++t)
    weights[t] = removed[t] ? 0.0 : areas[t];
  std::discrete_distribution<Eigen::Index> pick (weights.begin (), weights.end ());
  const Eigen::Matrix3Xd normals = faceNormals (head);

  const int outliers = static_cast<int> (settings.outlier_fraction * settings.points);
  const int surface = settings.points - outliers;
  scan.cloud.reset (new pcl::PointCloud<pcl::PointNormal>);
  for (int i = 0; i < surface; ++i) {
    const Eigen::Index t = pick (rng);
    double a = unit (rng), b = unit (rng);
    if (a + b > 1.0) {
      a = 1.0 - a;
      b = 1.0 - b;
    }
    const Eigen::Vector3d p = scan.truth.col (head.triangles (0, t)) * (1.0 - a - b) +
                              scan.truth.col (head.triangles (1, t)) * a + scan.truth.col (head.triangles (2, t)) * b;
    const Eigen::Vector3d noise (gauss (rng), gauss (rng), gauss (rng));
    pcl::PointNormal point;
    point.getVector3fMap () = (p + settings.noise_sigma * noise).cast<float> ();
    point.getNormalVector3fMap () = (rotation * normals.col (t)).cast<float> ();
    scan.cloud->push_back (point);
  }
  Eigen::Vector3d low = scan.truth.rowwise ().minCoeff (), high = scan.truth.rowwise ().maxCoeff ();
  const Eigen::Vector3d grow = 0.1 * (high - low);
  low -= grow;
  high += grow;
  for (int i = 0; i < outliers; ++i) {
    pcl::PointNormal point;
    for (int d = 0; d < 3; ++d)
      point.data[d] = static_cast<float> (low[d] + unit (rng) * (high[d] - low[d]));
    point.getNormalVector3fMap () =
        Eigen::Vector3d (gauss (rng), gauss (rng), gauss (rng)).normalized ().cast<float> ();
    scan.cloud->push_back (point);
  }
  for (const auto& landmark : landmarks)
    scan.landmarks[landmark.first] = scan.truth.col (landmark.second) +
                                     settings.landmark_sigma * Eigen::Vector3d (gauss (rng), gauss (rng), gauss (rng));
  return scan;
}

/** RMS distance (mm) between corresponding columns. */
inline double
vertexRms (const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b)
{
  return std::sqrt ((a - b).colwise ().squaredNorm ().mean ());
}

} // namespace test
} // namespace morphreg

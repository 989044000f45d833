// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/visualization/fit_layers.h>

#include <morphreg/common/colour_map.h>
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/visualization/registration_visualizer.h>

#include <pcl/correspondence.h>
#include <pcl/search/kdtree.h>

#include <cmath>

namespace morphreg
{
pcl::PointCloud<pcl::PointXYZ>::Ptr
addScanFile (RegistrationVisualizer& viewer, const std::string& path, bool over_mesh, int width, int height,
             const std::string& id)
{
  const pcl::PointCloud<pcl::PointXYZ>::Ptr cloud = loadCloud<pcl::PointXYZ> (path);
  try {
    if (over_mesh)
      viewer.addScanOverlay (*cloud, static_cast<std::size_t> (width) * static_cast<std::size_t> (height) / 60, id);
    else
      viewer.addTargetCloud (*cloud, id, 0, 2.0);
  }
  catch (const InvalidInputError& e) {
    throw InvalidInputError (path + ": " + e.what ());
  }
  return cloud;
}

FittedMeshFile
addFittedMeshFile (RegistrationVisualizer& viewer, const std::string& path, double colour_max, double opacity,
                   const std::string& id, int viewport)
{
  FittedMeshFile file = loadFittedMesh (path);
  if (file.residuals)
    viewer.addResidualHeatMap (file.mesh, *file.residuals, residualColourScale (*file.residuals, colour_max), id,
                               viewport);
  else
    viewer.addModelMesh (file.mesh, opacity, id, viewport);
  return file;
}

void
addFitCorrespondences (RegistrationVisualizer& viewer, const pcl::PointCloud<pcl::PointXYZ>& scan,
                       const TriangleMesh& fit, const std::optional<Eigen::VectorXd>& residuals, std::size_t most,
                       const std::string& id)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr valid (new pcl::PointCloud<pcl::PointXYZ>);
  for (const pcl::PointXYZ& p : scan)
    if (std::isfinite (p.x) && std::isfinite (p.y) && std::isfinite (p.z))
      valid->push_back (p);
  if (valid->empty ())
    throw InvalidInputError ("the fit's correspondences: the scan has no valid point");
  pcl::search::KdTree<pcl::PointXYZ> tree;
  tree.setInputCloud (valid);
  pcl::PointCloud<pcl::PointXYZ> vertices;
  pcl::Correspondences pairs;
  for (Eigen::Index v = 0; v < fit.numVertices (); ++v) {
    const Eigen::Vector3f position = fit.vertices.col (v).cast<float> ();
    vertices.push_back (pcl::PointXYZ (position.x (), position.y (), position.z ()));
    if (residuals && !std::isfinite ((*residuals)[v]))
      continue; // the fit found no scan point for this vertex
    pcl::Indices nearest (1);
    std::vector<float> distances (1);
    if (tree.nearestKSearch (vertices.back (), 1, nearest, distances) == 1)
      pairs.emplace_back (static_cast<int> (v), nearest[0], distances[0]);
  }
  viewer.addCorrespondences (vertices, *valid, pairs, most, id);
}

void
saveFitOverlay (RegistrationVisualizer& viewer, const pcl::PointCloud<pcl::PointNormal>& scan,
                const TriangleMesh& fitted, const Eigen::VectorXd& residuals, double colour_scale,
                const Eigen::Matrix4d& pose, const std::string& path, int width, int height)
{
  const std::size_t scan_points = static_cast<std::size_t> (width) * static_cast<std::size_t> (height) / 60;
  viewer.addScanOverlay (scan, scan_points, "scan");
  viewer.addResidualHeatMap (fitted, residuals, colour_scale, "residuals");
  viewer.setFramedShapes ({"residuals"});
  const Eigen::Matrix3d linear = pose.topLeftCorner<3, 3> ();
  const Eigen::Matrix3d rotation = linear / std::cbrt (linear.determinant ());
  viewer.resetCamera (rotation * Eigen::Vector3d (0.5, 0.15, 1.0).normalized (), rotation * Eigen::Vector3d::UnitY ());
  viewer.saveScreenshot (path, width, height);
}
} // namespace morphreg

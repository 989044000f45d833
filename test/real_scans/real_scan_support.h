// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The shared real head-and-shoulders scan (Lee Perry-Smith, ../shared/data/real_head_scans), the ICT-FaceKit
// 7-region model with 30 components per region, random similarity poses and the scan's evaluation convention:
// area samples of the scan mesh to the fitted surface, over the model's face triangles.
#include "../registration/ict_data.h"

#include <morphreg/io/cloud_io.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/model/ict_region_model.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/registration/surface_distance.h>

#include <Eigen/Geometry>

#include <filesystem>
#include <random>
#include <string>

namespace morphreg
{
namespace test
{
inline std::string
realScanPath (const std::string& file)
{
  return sharedDataPath ("real_head_scans/" + file);
}

inline bool
realScanDataAvailable ()
{
  return std::filesystem::exists (realScanPath ("leeperrysmith_scan_82k_mm.ply")) && ictAvailable ();
}

/** The 7-region ICT model with 30 components per region, built once per executable as the README's
 *  `build-model --from-ict ... --samples 300 --components 30` builds it. */
inline const MorphableModel::ConstPtr&
ictModel30 ()
{
  static const MorphableModel::ConstPtr model = [] {
    ModelBuilderSettings settings;
    settings.max_components = 30;
    return MorphableModel::ConstPtr (buildIctRegionModel (*ictModel (), 300, 1, settings));
  }();
  return model;
}

/** The ICT face: model triangles whose three vertices are all below 9409 (ICT's face range, ears included). */
inline std::vector<bool>
ictFaceTriangles (const MorphableModel& model)
{
  std::vector<bool> face (static_cast<size_t> (model.triangles ().cols ()));
  for (Eigen::Index t = 0; t < model.triangles ().cols (); ++t)
    face[static_cast<size_t> (t)] = (model.triangles ().col (t).array () < 9409).all ();
  return face;
}

inline const TriangleMesh&
leeHeadMesh ()
{
  static const TriangleMesh mesh = loadTriangleMesh (realScanPath ("leeperrysmith_head_mm.ply"));
  return mesh;
}

/** The 82k-point cloud with normals as the scanner delivers it. */
inline pcl::PointCloud<pcl::PointNormal>::Ptr
leeScan82k ()
{
  return loadCloud<pcl::PointNormal> (realScanPath ("leeperrysmith_scan_82k_mm.ply"));
}

/** The mesh's 8,838 vertices as a cloud with their vertex normals. */
inline pcl::PointCloud<pcl::PointNormal>::Ptr
leeVertexCloud ()
{
  const TriangleMesh& mesh = leeHeadMesh ();
  const Eigen::Matrix3Xd normals = vertexNormals (mesh);
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud (new pcl::PointCloud<pcl::PointNormal>);
  cloud->resize (mesh.vertices.cols ());
  for (Eigen::Index i = 0; i < mesh.vertices.cols (); ++i) {
    (*cloud)[i].getVector3fMap () = mesh.vertices.col (i).cast<float> ();
    (*cloud)[i].getNormalVector3fMap () = normals.col (i).cast<float> ();
  }
  return cloud;
}

/** A random similarity: rotation uniform over SO(3), scale in [0.85, 1.15], translation up to 1 m; fixed by \a seed. */
inline Eigen::Matrix4d
randomPose (unsigned seed)
{
  std::mt19937 random (seed);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform (0.0, 1.0);
  const Eigen::Quaterniond rotation =
      Eigen::Quaterniond (normal (random), normal (random), normal (random), normal (random)).normalized ();
  const double scale = 0.85 + 0.3 * uniform (random);
  const Eigen::Vector3d direction = Eigen::Vector3d (normal (random), normal (random), normal (random)).normalized ();
  Eigen::Matrix4d pose = Eigen::Matrix4d::Identity ();
  pose.topLeftCorner<3, 3> () = scale * rotation.toRotationMatrix ();
  pose.topRightCorner<3, 1> () = 1000.0 * uniform (random) * direction;
  return pose;
}

/** \a cloud under \a pose, its coordinates then multiplied by \a unit_scale (0.001: written in metres). */
inline pcl::PointCloud<pcl::PointNormal>::Ptr
posed (const pcl::PointCloud<pcl::PointNormal>& cloud, const Eigen::Matrix4d& pose, double unit_scale = 1.0)
{
  const Eigen::Matrix3d linear = pose.topLeftCorner<3, 3> ();
  const Eigen::Matrix3d rotation = linear / std::cbrt (linear.determinant ());
  pcl::PointCloud<pcl::PointNormal>::Ptr result (new pcl::PointCloud<pcl::PointNormal> (cloud));
  for (auto& point : *result) {
    const Eigen::Vector3d p = linear * point.getVector3fMap ().cast<double> () + pose.topRightCorner<3, 1> ();
    point.getVector3fMap () = (unit_scale * p).cast<float> ();
    point.getNormalVector3fMap () = (rotation * point.getNormalVector3fMap ().cast<double> ()).cast<float> ();
  }
  return result;
}

/** MorphableICP as the README registers real scans with the ICT model: 30 components per region, no landmarks,
 *  area weighting, prior 1.5, tangential weight 0.1, and the raw scan points (no target smoothing: projecting each
 *  point onto its 20 neighbours' plane pulls a curved, sparsely sampled surface inwards; from the true pose the
 *  8.8k-vertex cloud's face median is 0.945 mm with smoothing and 1.29 mm with the one-to-one rejector as well,
 *  0.80 mm without either). */
inline void
configureIctIcp (MorphableICP<pcl::PointNormal>& icp, const MorphableModel::ConstPtr& model)
{
  icp.setModel (model);
  icp.setComponentSelection (model->firstComponents (30));
  icp.setMaximumIterations (100);
  icp.setSimilarityIterations (60);
  icp.setPointToPlane (true, 0.1);
  icp.setShapePriorWeight (1.5);
  icp.setAreaWeighting (true);
  icp.setTargetSmoothing (false);
}

/** The fitted vertices of \a icp mapped back through \a pose (and \a unit_scale) into the scan's original frame. */
inline TriangleMesh
fitInScanFrame (const MorphableICP<pcl::PointNormal>& icp, const Eigen::Matrix4d& pose, double unit_scale = 1.0)
{
  const Eigen::Matrix3Xd in_mm = icp.getFittedVertices () / unit_scale;
  const Eigen::Matrix4d inverse = pose.inverse ();
  return TriangleMesh{(inverse.topLeftCorner<3, 3> () * in_mm).colwise () + inverse.topRightCorner<3, 1> (),
                      icp.getModel ()->triangles ()};
}

/** Face statistics of \a fitted (original scan frame) against the scan mesh. */
inline SurfaceDistance
faceDistance (const TriangleMesh& fitted)
{
  const SurfaceDistance all = surfaceDistance (leeHeadMesh (), fitted);
  return surfaceDistanceOver (all, ictFaceTriangles (*ictModel30 ()));
}

} // namespace test
} // namespace morphreg

#define MORPHREG_REQUIRE_REAL_SCANS()                                                                                  \
  if (!morphreg::test::realScanDataAvailable ())                                                                       \
  GTEST_SKIP () << "the real head scan or ICT-FaceKit is not in " << MORPHREG_SHARED_DATA_DIR                          \
                << " (../shared/data is absent)"

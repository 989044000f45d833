// SPDX-License-Identifier: BSD-3-Clause
// The real-scan zoo's helper (scripts/real_scan_zoo.sh): poses scans, renders depth-camera frames of them, and scores
// a fit against the scan's surface by the convention of ../shared/data/real_head_scans/README.md.
//   morphreg_zoo_tool pose SCAN OUT.ply SEED [m]            the scan under a random similarity (randomPose), in mm or m
//   morphreg_zoo_tool depth MESH OUT.pcd VIEW DISTANCE SEED [scene]
//                                                          a Kinect-v1-like frame (metres, camera frame) from the front,
//                                                          45 degrees or the profile; the head crop unless "scene"; also
//                                                          as OUT.png (16-bit, mm) with OUT.intrinsics.json
//   morphreg_zoo_tool score FIT.ply TRUTH [POSE.json]       the face median and more, as one JSON line
// Each OUT gets OUT.pose.json: the mm mesh-to-output similarity and the output's unit (1 for mm, 0.001 for m).
#include "../real_scan_support.h"

#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/depth_image_io.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/registration/surface_distance.h>
#include <morphreg/synthetic/depth_camera_simulator.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using namespace morphreg;

constexpr int kIctFaceVertices = 9409; ///< ICT's face range (ears included): the convention's face

void
writePose (const std::string& out, const Eigen::Matrix4d& pose, double unit)
{
  std::vector<double> rows;
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c)
      rows.push_back (pose (r, c));
  writeJsonFile (out + ".pose.json", {{"mesh_to_output_mm", rows}, {"unit", unit}});
}

/** A scan (cloud or mesh) as points with normals: a mesh's vertices with the normals of its triangles. */
pcl::PointCloud<pcl::PointNormal>::Ptr
scanPoints (const std::string& path)
{
  TriangleMesh mesh;
  try {
    mesh = loadTriangleMesh (path);
  }
  catch (const Error&) { // a cloud without triangles
    return loadCloud<pcl::PointNormal> (path);
  }
  const Eigen::Matrix3Xd normals = vertexNormals (mesh);
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud (new pcl::PointCloud<pcl::PointNormal>);
  cloud->resize (mesh.vertices.cols ());
  for (Eigen::Index i = 0; i < mesh.vertices.cols (); ++i) {
    (*cloud)[i].getVector3fMap () = mesh.vertices.col (i).cast<float> ();
    (*cloud)[i].getNormalVector3fMap () = normals.col (i).cast<float> ();
  }
  return cloud;
}

int
pose (const std::vector<std::string>& args)
{
  const Eigen::Matrix4d similarity = test::randomPose (static_cast<unsigned> (std::stoul (args.at (2))));
  const double unit = args.size () > 3 && args[3] == "m" ? 1e-3 : 1.0;
  saveCloud (args.at (1), *test::posed (*scanPoints (args.at (0)), similarity, unit));
  writePose (args.at (1), similarity, unit);
  return 0;
}

/** The camera pose of \a view ("frontal", "oblique" or "profile") looking at the top of \a mesh (its head) from
 *  \a distance mm; the mesh faces +Z and has +Y up. */
Eigen::Isometry3d
cameraPose (const TriangleMesh& mesh, const std::string& view, double distance)
{
  const Eigen::Vector3d high = mesh.vertices.rowwise ().maxCoeff ();
  const Eigen::Vector3d low = mesh.vertices.rowwise ().minCoeff ();
  const Eigen::Vector3d head (0.5 * (low.x () + high.x ()), high.y () - 120.0, 0.5 * (low.z () + high.z ()));
  const double angle = view == "frontal" ? 0.0 : view == "oblique" ? M_PI / 4.0 : M_PI / 2.0;
  if (view != "frontal" && view != "oblique" && view != "profile")
    throw InvalidInputError ("view '" + view + "' is none of frontal, oblique, profile");
  const Eigen::Vector3d eye = head + distance * Eigen::Vector3d (std::sin (angle), 0.1, std::cos (angle)).normalized ();
  return synthetic::DepthCameraSimulator::lookAt (head, eye);
}

/** Keeps only the pixels of \a frame that show \a mesh's triangles (the person, not the room) within \a height mm
 *  of its top: the head crop a user would make. */
void
cropToHead (synthetic::DepthFrame& frame, const TriangleMesh& mesh, double height)
{
  const double top = mesh.vertices.row (1).maxCoeff ();
  for (std::size_t pixel = 0; pixel < frame.depth.size (); ++pixel) {
    const int t = frame.source_triangle[pixel];
    const bool keep =
        t >= 0 && t < mesh.numTriangles () && mesh.vertices.col (mesh.triangles (0, t)).y () > top - height;
    if (!keep) {
      (*frame.cloud)[pixel].x = (*frame.cloud)[pixel].y = (*frame.cloud)[pixel].z =
          std::numeric_limits<float>::quiet_NaN ();
    }
  }
}

int
depth (const std::vector<std::string>& args)
{
  const TriangleMesh mesh = loadTriangleMesh (args.at (0));
  const bool scene = args.size () > 5 && args[5] == "scene";
  const Eigen::Isometry3d camera = cameraPose (mesh, args.at (2), std::stod (args.at (3)));
  synthetic::DepthFrame frame = synthetic::DepthCameraSimulator ().render (scene ? synthetic::stageInRoom (mesh) : mesh,
                                                                           camera, std::stoull (args.at (4)));
  if (!scene)
    cropToHead (frame, mesh, 300.0);
  saveCloud (args.at (1), *frame.cloud);
  writePose (args.at (1), camera.matrix (), 1e-3);
  // The same frame as a depth camera saves it: a 16-bit PNG in mm and the intrinsics.
  const std::string stem = args.at (1).substr (0, args.at (1).find_last_of ('.'));
  DepthImage image{frame.intrinsics.width, frame.intrinsics.height, frame.depth};
  for (std::size_t pixel = 0; pixel < image.depth.size (); ++pixel)
    if (!std::isfinite ((*frame.cloud)[pixel].z))
      image.depth[pixel] = 0;
  saveDepthPng (stem + ".png", image);
  const DepthIntrinsics& k = frame.intrinsics;
  writeJsonFile (stem + ".intrinsics.json",
                 {{"width", k.width}, {"height", k.height}, {"fx", k.fx}, {"fy", k.fy}, {"cx", k.cx}, {"cy", k.cy}});
  return 0;
}

int
score (const std::vector<std::string>& args)
{
  TriangleMesh fit = loadTriangleMesh (args.at (0));
  const TriangleMesh truth = loadTriangleMesh (args.at (1));
  if (args.size () > 2) { // the fit is in the output's frame and unit: map it back into the truth's
    const nlohmann::json pose = readJsonFile (args[2]);
    const std::vector<double> rows = pose.at ("mesh_to_output_mm").get<std::vector<double>> ();
    const Eigen::Matrix4d inverse =
        Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>> (rows.data ()).inverse ();
    fit.vertices = (inverse.topLeftCorner<3, 3> () * fit.vertices).colwise () + inverse.topRightCorner<3, 1> ();
  }
  std::vector<bool> face (static_cast<std::size_t> (fit.numTriangles ()));
  for (Eigen::Index t = 0; t < fit.numTriangles (); ++t)
    face[static_cast<std::size_t> (t)] = (fit.triangles.col (t).array () < kIctFaceVertices).all ();
  const SurfaceDistance all = surfaceDistance (truth, fit);
  const SurfaceDistance over_face = surfaceDistanceOver (all, face);
  const nlohmann::json result = {{"samples", all.samples},
                                 {"kept", all.distances.size ()},
                                 {"face_samples", over_face.distances.size ()},
                                 {"face_median", over_face.median},
                                 {"face_p95", over_face.percentile95},
                                 {"median", all.median},
                                 {"p95", all.percentile95}};
  std::cout << result.dump () << '\n';
  return 0;
}
} // namespace

int
main (int argc, char** argv)
{
  const std::vector<std::string> args (argv + std::min (argc, 2), argv + argc);
  const std::string verb = argc > 1 ? argv[1] : "";
  try {
    if (verb == "pose")
      return pose (args);
    if (verb == "depth")
      return depth (args);
    if (verb == "score")
      return score (args);
    std::cerr << "usage: morphreg_zoo_tool pose|depth|score ... (see the source's first lines)\n";
    return 2;
  }
  catch (const std::exception& e) {
    std::cerr << "morphreg_zoo_tool " << verb << ": " << e.what () << '\n';
    return 1;
  }
}

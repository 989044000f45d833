// SPDX-License-Identifier: BSD-3-Clause
// The depth-camera simulator against scenes whose depth is known: a wall seen square-on (the axial noise, the
// quantisation steps, metres and NaN as PCL's grabbers deliver them), a board in front of the wall (the projector's
// shadow and the flying pixels at its edges), a wall seen obliquely (no return beyond the incidence limit), and a
// head (what a frame of a person looks like).
#include <morphreg/common/depth_intrinsics.h>
#include <morphreg/common/error.h>
#include <morphreg/synthetic/depth_camera_simulator.h>

#include "support/expect_error.h"
#include "support/synthetic_heads.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace
{
using morphreg::TriangleMesh;
using morphreg::synthetic::DepthCameraSimulator;
using morphreg::synthetic::DepthFrame;

/** A square of side \a side mm at depth \a z in front of the camera (camera frame: the mesh frame is the camera's). */
TriangleMesh
square (double side, double z, double x = 0.0)
{
  TriangleMesh mesh;
  mesh.vertices.resize (3, 4);
  mesh.vertices << x - side / 2, x + side / 2, x + side / 2, x - side / 2, -side / 2, -side / 2, side / 2, side / 2, z,
      z, z, z;
  mesh.triangles.resize (3, 2);
  mesh.triangles << 0, 0, 1, 2, 2, 3;
  return mesh;
}

TriangleMesh
joined (const TriangleMesh& a, const TriangleMesh& b)
{
  TriangleMesh mesh;
  mesh.vertices.resize (3, a.numVertices () + b.numVertices ());
  mesh.vertices << a.vertices, b.vertices;
  mesh.triangles.resize (3, a.numTriangles () + b.numTriangles ());
  mesh.triangles << a.triangles, (b.triangles.array () + static_cast<int> (a.numVertices ())).matrix ();
  return mesh;
}

const Eigen::Isometry3d kCameraFrame = Eigen::Isometry3d::Identity ();

TEST (DepthCameraSimulatorTest, AWallAtOneMetreHasTheSensorsNoiseAndSteps)
{
  const DepthFrame frame = DepthCameraSimulator ().render (square (5000.0, 1000.0), kCameraFrame, 3);
  ASSERT_EQ (frame.cloud->width, 640u);
  ASSERT_EQ (frame.cloud->height, 480u);
  EXPECT_FALSE (frame.cloud->is_dense);
  double sum = 0.0, squares = 0.0;
  std::set<std::uint16_t> levels;
  int valid = 0;
  for (std::uint16_t z : frame.depth)
    if (z > 0) {
      sum += z, squares += double (z) * z, ++valid;
      levels.insert (z);
    }
  const double mean = sum / valid, sigma = std::sqrt (squares / valid - mean * mean);
  // Nguyen et al.: 1.2 + 1.9 * 0.6^2 = 1.88 mm at 1 m; quantisation adds its steps' 2.9 mm / sqrt(12) = 0.83 mm.
  EXPECT_GT (valid, 0.99 * 640 * 480) << "a square-on wall returns nearly every pixel";
  EXPECT_NEAR (mean, 1000.0, 0.3);
  EXPECT_NEAR (sigma, std::hypot (1.88, 0.83), 0.25);
  EXPECT_LT (levels.size (), 12u) << "disparity steps of 1/8 px give a few depth levels 2.9 mm apart, not every mm";
  const pcl::PointXYZ& centre = (*frame.cloud) (320, 240);
  EXPECT_NEAR (centre.z, mean / 1000.0, 0.02) << "metres, as PCL's grabbers deliver them";
}

TEST (DepthCameraSimulatorTest, ABoardBeforeTheWallCastsTheProjectorsShadowAndFlyingPixels)
{
  DepthCameraSimulator::Parameters parameters;
  parameters.axial_noise = parameters.axial_noise_growth = parameters.lateral_noise = 0.0;
  parameters.disparity_step = 0.0;
  const DepthFrame frame = DepthCameraSimulator (parameters)
                               .render (joined (square (200.0, 900.0), square (5000.0, 1500.0)), kCameraFrame, 5);
  const auto depthAt = [&frame] (int u, int v) { return frame.depth[static_cast<std::size_t> (v) * 640 + u]; };
  // The board spans u = 319.5 -+ 580 * 100 / 900, pixels 256 to 383. The projector, 75 mm to the right (+x), throws
  // the board's shadow on the wall beside its left edge: 580 * 75 * (1/900 - 1/1500) = 19 px without depth there.
  EXPECT_EQ (depthAt (320, 240), 900);
  EXPECT_EQ (depthAt (200, 240), 1500);
  int shadow = 0;
  for (int u = 220; u < 256; ++u)
    shadow += depthAt (u, 240) == 0 ? 1 : 0;
  EXPECT_NEAR (shadow, 19, 2) << "the projector's shadow beside the board";
  EXPECT_EQ (depthAt (400, 240), 1500) << "the wall beside the other edge is lit";
  int flying = 0, board_edge = 0;
  for (int v = 200; v < 280; ++v) {
    const std::uint16_t z = depthAt (383, v); // the board's right edge, beside the lit wall
    board_edge += 1;
    flying += z > 900 && z < 1500 ? 1 : 0;
  }
  EXPECT_NEAR (flying, 0.5 * board_edge, 0.2 * board_edge) << "half the pixels at the board's left edge fly";
}

TEST (DepthCameraSimulatorTest, GrazingSurfacesReturnNothing)
{
  // A wall through the point 1.5 m ahead, turned about the vertical: the central column's rays meet it at the turn.
  const auto centreColumnReturns = [] (double degrees) {
    TriangleMesh wall = square (4000.0, 0.0);
    const Eigen::AngleAxisd turn (degrees * M_PI / 180.0, Eigen::Vector3d::UnitY ());
    wall.vertices = (turn.toRotationMatrix () * wall.vertices).colwise () + Eigen::Vector3d (0.0, 0.0, 1500.0);
    const DepthFrame frame = DepthCameraSimulator ().render (wall, kCameraFrame, 1);
    int returns = 0;
    for (int v = 0; v < 480; ++v)
      returns += frame.depth[static_cast<std::size_t> (v) * 640 + 320] > 0 ? 1 : 0;
    return returns;
  };
  EXPECT_GT (centreColumnReturns (60.0), 400) << "60 degrees: within the 75 degree limit";
  EXPECT_EQ (centreColumnReturns (80.0), 0) << "80 degrees: beyond it";
}

TEST (DepthCameraSimulatorTest, AHeadSeenFromTheFrontFillsAPartOfTheFrame)
{
  const TriangleMesh& head = morphreg::test::headGenerator ().sample (3).mesh;
  const Eigen::Vector3d centre = 0.5 * (head.vertices.rowwise ().minCoeff () + head.vertices.rowwise ().maxCoeff ());
  const Eigen::Isometry3d pose = DepthCameraSimulator::lookAt (centre, centre + Eigen::Vector3d (0.0, 0.0, 1000.0));
  const DepthFrame frame = DepthCameraSimulator ().render (head, pose, 11);
  int valid = 0;
  double worst = 0.0;
  for (std::size_t pixel = 0; pixel < frame.depth.size (); ++pixel)
    if (frame.depth[pixel] > 0 && frame.source_triangle[pixel] >= 0) {
      ++valid;
      const pcl::PointXYZ& p = (*frame.cloud)[pixel];
      const Eigen::Vector3d in_mesh = pose.inverse () * (1000.0 * Eigen::Vector3d (p.x, p.y, p.z));
      const int t = frame.source_triangle[pixel];
      const Eigen::Vector3d a = head.vertices.col (head.triangles (0, t));
      const Eigen::Vector3d n = (head.vertices.col (head.triangles (1, t)) - a)
                                    .cross (head.vertices.col (head.triangles (2, t)) - a)
                                    .normalized ();
      worst = std::max (worst, std::abs (n.dot (in_mesh - a)));
    }
  // A head 1 m away: about 90 x 130 px of face and skull, each point within the noise's reach of its triangle.
  EXPECT_GT (valid, 6000);
  EXPECT_LT (valid, 20000);
  EXPECT_LT (worst, 25.0) << "every point lies near the triangle it came from (noise, steps and grazing sides)";
  EXPECT_TRUE (std::isnan ((*frame.cloud) (0, 0).z)) << "no depth in the frame's corner: NaN, as PCL marks it";
}

TEST (DepthCameraSimulatorTest, BadSettingsAndScenesAreNamed)
{
  DepthCameraSimulator::Parameters bad;
  bad.max_incidence_deg = 120.0;
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> ([&] { DepthCameraSimulator simulator (bad); },
                                                                      "max_incidence_deg = 120");
  bad = {};
  bad.intrinsics.fx = 0.0;
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> ([&] { DepthCameraSimulator simulator (bad); },
                                                                      "focal lengths");
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> (
      [] { DepthCameraSimulator ().render (square (100.0, -1000.0), kCameraFrame, 1); }, "sees nothing");
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> (
      [] { DepthCameraSimulator::lookAt (Eigen::Vector3d::Zero (), Eigen::Vector3d::UnitY ()); }, "looks along up");
}

TEST (DepthImageToCloudTest, PixelsBecomeCameraPointsAndHolesNaN)
{
  morphreg::DepthIntrinsics k;
  k.width = 4, k.height = 3, k.fx = 2.0, k.fy = 4.0, k.cx = 1.5, k.cy = 1.0;
  std::vector<std::uint16_t> depth (12, 0);
  depth[1 * 4 + 3] = 1000; // u = 3, v = 1
  const auto cloud = morphreg::depthImageToCloud (depth, k);
  EXPECT_FLOAT_EQ ((*cloud) (3, 1).x, (3 - 1.5) * 1000 / 2.0);
  EXPECT_FLOAT_EQ ((*cloud) (3, 1).y, 0.0f);
  EXPECT_FLOAT_EQ ((*cloud) (3, 1).z, 1000.0f);
  EXPECT_TRUE (std::isnan ((*cloud) (0, 0).x));
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> (
      [&] { morphreg::depthImageToCloud (std::vector<std::uint16_t> (11, 1), k); }, "11 pixels, the camera 4 x 3");
}
} // namespace

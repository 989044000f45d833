// SPDX-License-Identifier: BSD-3-Clause
#include "../common/number_text.h"

#include <morphreg/common/error.h>
#include <morphreg/synthetic/depth_camera_simulator.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace morphreg
{
namespace synthetic
{
namespace
{
constexpr int kTile = 16; ///< pixels per side of the tiles the triangles are binned into

/** The nearest surface along each pixel's ray, from one centre of projection. */
struct DepthBuffer
{
  std::vector<double> depth;  ///< mm along the optical axis, +inf where nothing was hit
  std::vector<int> triangle;  ///< the triangle hit, or -1
  std::vector<double> cosine; ///< |cos| of the incidence angle at the hit
};

/** Rays through every pixel of a camera at \a origin (camera frame), each through its (jittered) pixel position. */
struct RayFan
{
  Eigen::Vector3d origin = Eigen::Vector3d::Zero ();
  std::vector<Eigen::Vector3d> directions; ///< per pixel, z component 1
};

void
requireSetting (bool ok, const std::string& name, double value, const std::string& allowed)
{
  if (!ok)
    throw InvalidInputError ("DepthCameraSimulator: " + name + " = " + detail::numberText (value, 6) +
                             " is invalid; it must be " + allowed);
}

/** The distance t along \a direction from \a origin at which the ray meets triangle (a, b, c), or +inf. */
double
intersect (const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, const Eigen::Vector3d& a,
           const Eigen::Vector3d& b, const Eigen::Vector3d& c)
{
  const Eigen::Vector3d ab = b - a, ac = c - a;
  const Eigen::Vector3d p = direction.cross (ac);
  const double determinant = ab.dot (p);
  if (std::abs (determinant) < 1e-12)
    return HUGE_VAL;
  const Eigen::Vector3d s = origin - a;
  const double u = s.dot (p) / determinant;
  if (u < 0.0 || u > 1.0)
    return HUGE_VAL;
  const Eigen::Vector3d q = s.cross (ab);
  const double v = direction.dot (q) / determinant;
  if (v < 0.0 || u + v > 1.0)
    return HUGE_VAL;
  const double t = ac.dot (q) / determinant;
  return t > 0.0 ? t : HUGE_VAL;
}

/** Per tile of the image, the triangles whose projection (grown by \a margin px) may cover it. */
std::vector<std::vector<int>>
binTriangles (const TriangleMesh& mesh, const Eigen::Vector3d& origin, const DepthIntrinsics& k, double margin)
{
  const int tiles_x = (k.width + kTile - 1) / kTile, tiles_y = (k.height + kTile - 1) / kTile;
  std::vector<std::vector<int>> bins (static_cast<std::size_t> (tiles_x * tiles_y));
  for (Eigen::Index t = 0; t < mesh.numTriangles (); ++t) {
    double low_u = HUGE_VAL, low_v = HUGE_VAL, high_u = -HUGE_VAL, high_v = -HUGE_VAL;
    bool behind = false;
    for (int corner = 0; corner < 3; ++corner) {
      const Eigen::Vector3d p = mesh.vertices.col (mesh.triangles (corner, t)) - origin;
      behind = behind || p.z () < 1.0;
      const double u = k.cx + k.fx * p.x () / p.z (), v = k.cy + k.fy * p.y () / p.z ();
      low_u = std::min (low_u, u), high_u = std::max (high_u, u);
      low_v = std::min (low_v, v), high_v = std::max (high_v, v);
    }
    if (behind) // crosses the camera plane: its projection is unbounded, try every tile
      low_u = low_v = -HUGE_VAL, high_u = high_v = HUGE_VAL;
    const int x0 = std::max (0, static_cast<int> (std::floor ((low_u - margin) / kTile)));
    const int x1 = std::min (tiles_x - 1, static_cast<int> (std::floor (std::min (high_u + margin, 1e9) / kTile)));
    const int y0 = std::max (0, static_cast<int> (std::floor ((low_v - margin) / kTile)));
    const int y1 = std::min (tiles_y - 1, static_cast<int> (std::floor (std::min (high_v + margin, 1e9) / kTile)));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x)
        bins[static_cast<std::size_t> (y * tiles_x + x)].push_back (static_cast<int> (t));
  }
  return bins;
}

/** Casts \a rays at \a mesh (camera frame, mm): the nearest hit per pixel, its triangle and incidence. */
DepthBuffer
castRays (const TriangleMesh& mesh, const Eigen::Matrix3Xd& face_normals, const RayFan& rays, const DepthIntrinsics& k,
          double margin)
{
  const std::vector<std::vector<int>> bins = binTriangles (mesh, rays.origin, k, margin);
  const int tiles_x = (k.width + kTile - 1) / kTile;
  const std::size_t pixels = static_cast<std::size_t> (k.width) * k.height;
  DepthBuffer buffer{std::vector<double> (pixels, HUGE_VAL), std::vector<int> (pixels, -1),
                     std::vector<double> (pixels, 0.0)};
#pragma omp parallel for schedule(dynamic)
  for (int tile = 0; tile < static_cast<int> (bins.size ()); ++tile) {
    const int x0 = (tile % tiles_x) * kTile, y0 = (tile / tiles_x) * kTile;
    for (int v = y0; v < std::min (y0 + kTile, k.height); ++v)
      for (int u = x0; u < std::min (x0 + kTile, k.width); ++u) {
        const std::size_t pixel = static_cast<std::size_t> (v) * k.width + u;
        const Eigen::Vector3d& direction = rays.directions[pixel];
        for (int t : bins[static_cast<std::size_t> (tile)]) {
          const double along =
              intersect (rays.origin, direction, mesh.vertices.col (mesh.triangles (0, t)),
                         mesh.vertices.col (mesh.triangles (1, t)), mesh.vertices.col (mesh.triangles (2, t)));
          if (along < buffer.depth[pixel]) { // direction.z () is 1: the distance along the ray is the depth
            buffer.depth[pixel] = along;
            buffer.triangle[pixel] = t;
          }
        }
        if (buffer.triangle[pixel] >= 0)
          buffer.cosine[pixel] = std::abs (face_normals.col (buffer.triangle[pixel]).dot (direction.normalized ()));
      }
  }
  return buffer;
}

/** Unit normals of \a mesh's triangles (zero for degenerate ones). */
Eigen::Matrix3Xd
faceNormals (const TriangleMesh& mesh)
{
  Eigen::Matrix3Xd normals (3, mesh.numTriangles ());
  for (Eigen::Index t = 0; t < mesh.numTriangles (); ++t) {
    const Eigen::Vector3d a = mesh.vertices.col (mesh.triangles (0, t));
    const Eigen::Vector3d n =
        (mesh.vertices.col (mesh.triangles (1, t)) - a).cross (mesh.vertices.col (mesh.triangles (2, t)) - a);
    normals.col (t) = n.norm () > 0.0 ? Eigen::Vector3d (n.normalized ()) : Eigen::Vector3d::Zero ();
  }
  return normals;
}

/** The rays of a camera at \a origin through every pixel, each pixel's position jittered by \a jitter px. */
RayFan
rayFan (const DepthIntrinsics& k, const Eigen::Vector3d& origin, double jitter, std::mt19937_64& random)
{
  std::normal_distribution<double> normal (0.0, 1.0);
  RayFan rays{origin, {}};
  rays.directions.reserve (static_cast<std::size_t> (k.width) * k.height);
  for (int v = 0; v < k.height; ++v)
    for (int u = 0; u < k.width; ++u) {
      const double du = jitter > 0.0 ? jitter * normal (random) : 0.0;
      const double dv = jitter > 0.0 ? jitter * normal (random) : 0.0;
      rays.directions.emplace_back ((u + du - k.cx) / k.fx, (v + dv - k.cy) / k.fy, 1.0);
    }
  return rays;
}

/** The projector's pattern covers more than the camera's view (half the image more on every side): the camera's
 *  own intrinsics, widened. */
DepthIntrinsics
projectorIntrinsics (const DepthIntrinsics& camera)
{
  DepthIntrinsics pattern = camera;
  pattern.width = 2 * camera.width;
  pattern.height = 2 * camera.height;
  pattern.cx = camera.cx + 0.5 * camera.width;
  pattern.cy = camera.cy + 0.5 * camera.height;
  return pattern;
}

/** Whether the projector (at \a projector, looking along +z) lights the camera-frame point \a point: no surface of
 *  \a lit (the projector's depth buffer) lies more than a few mm in front of it. */
bool
lit (const Eigen::Vector3d& point, const Eigen::Vector3d& projector, const DepthBuffer& lit_buffer,
     const DepthIntrinsics& k)
{
  const Eigen::Vector3d p = point - projector;
  const double u = k.cx + k.fx * p.x () / p.z (), v = k.cy + k.fy * p.y () / p.z ();
  const int u0 = static_cast<int> (std::floor (u)), v0 = static_cast<int> (std::floor (v));
  double nearest_behind = -HUGE_VAL; // the farthest of the 2 x 2 projector pixels around the point
  for (int dv = 0; dv <= 1; ++dv)
    for (int du = 0; du <= 1; ++du) {
      const int x = u0 + du, y = v0 + dv;
      if (x >= 0 && y >= 0 && x < k.width && y < k.height)
        nearest_behind = std::max (nearest_behind, lit_buffer.depth[static_cast<std::size_t> (y) * k.width + x]);
    }
  return p.z () <= nearest_behind + 5.0;
}

/** sigma_z (mm) of the axial noise at depth \a z (mm) and incidence cosine \a cosine. */
double
axialSigma (const DepthCameraSimulator::Parameters& parameters, double z, double cosine)
{
  const double metres = z / 1000.0;
  const double theta = std::acos (std::clamp (cosine, 0.0, 1.0));
  const double grazing = theta * theta / std::pow (std::max (M_PI / 2.0 - theta, 1e-3), 2.0);
  return parameters.axial_noise + parameters.axial_noise_growth * (metres - 0.4) * (metres - 0.4) +
         parameters.incidence_noise / std::sqrt (metres) * grazing;
}

/** \a z (mm) after the disparity's quantisation. */
double
quantised (const DepthCameraSimulator::Parameters& parameters, double z)
{
  if (parameters.disparity_step <= 0.0)
    return z;
  const double focal_baseline = parameters.intrinsics.fx * parameters.baseline;
  const double disparity = std::round (focal_baseline / z / parameters.disparity_step) * parameters.disparity_step;
  return disparity > 0.0 ? focal_baseline / disparity : HUGE_VAL;
}

/** Flying pixels: beside a depth jump, a share of the pixels take a depth between the two sides. */
void
addFlyingPixels (const DepthCameraSimulator::Parameters& parameters, DepthFrame& frame, std::mt19937_64& random)
{
  const DepthIntrinsics& k = frame.intrinsics;
  const std::vector<std::uint16_t> original = frame.depth;
  std::uniform_real_distribution<double> uniform (0.0, 1.0);
  for (int v = 1; v + 1 < k.height; ++v)
    for (int u = 1; u + 1 < k.width; ++u) {
      const std::size_t pixel = static_cast<std::size_t> (v) * k.width + u;
      if (original[pixel] == 0)
        continue;
      double farthest = original[pixel];
      for (const std::size_t neighbour : {pixel - 1, pixel + 1, pixel - k.width, pixel + k.width})
        if (original[neighbour] > 0)
          farthest = std::max (farthest, static_cast<double> (original[neighbour]));
      if (farthest - original[pixel] > parameters.flying_pixel_jump &&
          uniform (random) < parameters.flying_pixel_share) {
        frame.depth[pixel] = static_cast<std::uint16_t> (
            std::lround (original[pixel] + uniform (random) * (farthest - original[pixel])));
        frame.source_triangle[pixel] = -1;
      }
    }
}
} // namespace

DepthCameraSimulator::DepthCameraSimulator (const Parameters& parameters) : parameters_ (parameters)
{
  requireValidIntrinsics (parameters.intrinsics, "DepthCameraSimulator");
  const Parameters& p = parameters;
  requireSetting (p.baseline >= 0.0 && p.baseline < 1000.0, "baseline", p.baseline, "0 to 1000 mm");
  requireSetting (p.disparity_step >= 0.0 && p.disparity_step <= 1.0, "disparity_step", p.disparity_step, "0 to 1 px");
  for (const auto& [name, value] : {std::pair<const char*, double>{"axial_noise", p.axial_noise},
                                    {"axial_noise_growth", p.axial_noise_growth},
                                    {"incidence_noise", p.incidence_noise},
                                    {"lateral_noise", p.lateral_noise}})
    requireSetting (value >= 0.0 && value <= 100.0, name, value, "0 to 100");
  requireSetting (p.max_incidence_deg > 0.0 && p.max_incidence_deg <= 90.0, "max_incidence_deg", p.max_incidence_deg,
                  "in (0, 90] degrees");
  requireSetting (p.min_range > 0.0 && p.max_range > p.min_range, "max_range", p.max_range, "above min_range > 0 mm");
  requireSetting (p.flying_pixel_jump > 0.0, "flying_pixel_jump", p.flying_pixel_jump, "positive (mm)");
  requireSetting (p.flying_pixel_share >= 0.0 && p.flying_pixel_share <= 1.0, "flying_pixel_share",
                  p.flying_pixel_share, "0 to 1");
}

Eigen::Isometry3d
DepthCameraSimulator::lookAt (const Eigen::Vector3d& target, const Eigen::Vector3d& eye, const Eigen::Vector3d& up)
{
  const Eigen::Vector3d forward = (target - eye).normalized ();
  const Eigen::Vector3d side = forward.cross (up);
  if ((target - eye).norm () == 0.0 || side.norm () < 1e-9 * up.norm () || !side.allFinite ())
    throw InvalidInputError ("DepthCameraSimulator::lookAt: the eye coincides with the target or looks along up");
  const Eigen::Vector3d right = side.normalized ();
  const Eigen::Vector3d down = forward.cross (right);
  Eigen::Matrix3d rotation; // rows: the camera's axes in mesh coordinates
  rotation.row (0) = right.transpose ();
  rotation.row (1) = down.transpose ();
  rotation.row (2) = forward.transpose ();
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity ();
  pose.linear () = rotation;
  pose.translation () = -rotation * eye;
  return pose;
}

DepthFrame
DepthCameraSimulator::render (const TriangleMesh& mesh, const Eigen::Isometry3d& mesh_to_camera,
                              std::uint64_t seed) const
{
  validateMesh (mesh, "DepthCameraSimulator: the mesh");
  const Parameters& p = parameters_;
  const DepthIntrinsics& k = p.intrinsics;
  TriangleMesh scene = mesh;
  scene.vertices = mesh_to_camera * mesh.vertices;
  const Eigen::Matrix3Xd normals = faceNormals (scene);
  std::mt19937_64 random (seed);
  const double margin = 4.0 * p.lateral_noise + 1.0;
  const DepthBuffer seen =
      castRays (scene, normals, rayFan (k, Eigen::Vector3d::Zero (), p.lateral_noise, random), k, margin);
  const Eigen::Vector3d projector (p.baseline, 0.0, 0.0);
  const DepthIntrinsics pattern = projectorIntrinsics (k);
  const DepthBuffer lit_buffer = castRays (scene, normals, rayFan (pattern, projector, 0.0, random), pattern, 1.0);

  DepthFrame frame{k, std::vector<std::uint16_t> (seen.depth.size (), 0), nullptr, mesh_to_camera,
                   std::vector<int> (seen.depth.size (), -1)};
  std::normal_distribution<double> normal (0.0, 1.0);
  const double min_cosine = std::cos (p.max_incidence_deg * M_PI / 180.0);
  for (std::size_t pixel = 0; pixel < seen.depth.size (); ++pixel) {
    const double z = seen.depth[pixel];
    if (seen.triangle[pixel] < 0 || z < p.min_range || z > p.max_range || seen.cosine[pixel] < min_cosine)
      continue;
    const int u = static_cast<int> (pixel % k.width), v = static_cast<int> (pixel / k.width);
    const Eigen::Vector3d point ((u - k.cx) / k.fx * z, (v - k.cy) / k.fy * z, z);
    if (!lit (point, projector, lit_buffer, pattern))
      continue;
    const double measured = quantised (p, z + axialSigma (p, z, seen.cosine[pixel]) * normal (random));
    if (measured < p.min_range || measured > p.max_range)
      continue;
    frame.depth[pixel] = static_cast<std::uint16_t> (std::lround (measured));
    frame.source_triangle[pixel] = seen.triangle[pixel];
  }
  addFlyingPixels (p, frame, random);
  if (std::none_of (frame.depth.begin (), frame.depth.end (), [] (std::uint16_t d) { return d > 0; }))
    throw InvalidInputError ("DepthCameraSimulator: the camera sees nothing of the mesh");
  frame.cloud = depthImageToCloud (frame.depth, k);
  for (auto& point : *frame.cloud)
    point.getVector3fMap () *= 1e-3f; // metres, as PCL's grabbers deliver them
  return frame;
}

TriangleMesh
stageInRoom (const TriangleMesh& person, double wall_distance, double floor_depth)
{
  validateMesh (person, "stageInRoom: the person");
  const Eigen::Vector3d low = person.vertices.rowwise ().minCoeff ();
  const Eigen::Vector3d high = person.vertices.rowwise ().maxCoeff ();
  const Eigen::Vector3d centre = 0.5 * (low + high);
  const double reach = 6000.0; // half the width of the wall and the floor: they fill any frame
  const double wall_z = low.z () - wall_distance, floor_y = low.y () - floor_depth;
  TriangleMesh room = person;
  const Eigen::Index first = person.numVertices ();
  room.vertices.conservativeResize (3, first + 8);
  room.vertices.block<3, 4> (0, first) << centre.x () - reach, centre.x () + reach, centre.x () + reach,
      centre.x () - reach, floor_y, floor_y, high.y () + reach, high.y () + reach, wall_z, wall_z, wall_z, wall_z;
  room.vertices.block<3, 4> (0, first + 4) << centre.x () - reach, centre.x () + reach, centre.x () + reach,
      centre.x () - reach, floor_y, floor_y, floor_y, floor_y, wall_z, wall_z, wall_z + 2.0 * reach,
      wall_z + 2.0 * reach;
  const Eigen::Index triangles = person.numTriangles ();
  room.triangles.conservativeResize (3, triangles + 4);
  const int w = static_cast<int> (first), f = static_cast<int> (first + 4);
  room.triangles.block<3, 4> (0, triangles) << w, w, f, f, w + 1, w + 2, f + 1, f + 2, w + 2, w + 3, f + 2, f + 3;
  return room;
}

} // namespace synthetic
} // namespace morphreg

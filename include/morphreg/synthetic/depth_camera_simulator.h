// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file depth_camera_simulator.h
 *  \brief Simulated frames of a consumer structured-light depth camera (Kinect v1 class) looking at a mesh, with the
 *  sensor's errors, so that tests of depth-camera input have the truth.
 */
#include <morphreg/common/depth_intrinsics.h>
#include <morphreg/mesh/triangle_mesh.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace morphreg
{
namespace synthetic
{
/** \brief One simulated frame: the depth image, its organised cloud as PCL's grabbers deliver it, and the pose. */
struct DepthFrame
{
  DepthIntrinsics intrinsics;       ///< the camera
  std::vector<std::uint16_t> depth; ///< mm per pixel, row by row, 0 where nothing came back
  /** width x height points in metres in the camera frame (x right, y down, z forward), NaN without depth. */
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud;
  /** Mesh coordinates (mm) to camera coordinates (mm): camera = mesh_to_camera * mesh. */
  Eigen::Isometry3d mesh_to_camera = Eigen::Isometry3d::Identity ();
  std::vector<int> source_triangle; ///< per pixel: the mesh triangle seen, or -1 (no depth, or a flying pixel)
};

/** \brief Renders a triangle mesh as a structured-light depth camera sees it: a ray per pixel returns the nearest
 *  surface, and the frame then carries the sensor's errors. The defaults are a Kinect v1's:
 *  - 640 x 480 pixels, focal length 580 px, projector 75 mm beside the camera, disparity measured in steps of 1/8
 *    pixel, so that depth comes in steps of z^2 / (8 f b): 2.9 mm at 1 m, 6.5 mm at 1.5 m (Khoshelham and
 *    Elberink 2012, "Accuracy and resolution of Kinect depth data for indoor mapping applications", Sensors 12);
 *  - axial noise sigma_z = 1.2 + 1.9 (z - 0.4)^2 mm (z in m) plus 0.1 / sqrt(z) theta^2 / (pi/2 - theta)^2 mm at
 *    incidence theta, and lateral noise of 0.8 px (Nguyen, Izadi and Lovell 2012, "Modeling Kinect sensor noise for
 *    improved 3D reconstruction and tracking", 3DIMPVT);
 *  - no return where the surface is seen beyond 75 degrees of incidence or is hidden from the projector (the
 *    shadow beside every silhouette), nor nearer than 0.5 m or beyond 4 m;
 *  - flying pixels: at a depth jump of more than 20 mm, half the pixels beside it take a depth between the two.
 *
 *  \code
 *  morphreg::synthetic::DepthCameraSimulator camera;
 *  auto frame = camera.render (mesh, camera.lookAt (face_centre, eye), 7); // frame.cloud: metres, NaN holes
 *  \endcode
 */
class DepthCameraSimulator
{
public:
  /** \brief The sensor; the defaults are a Kinect v1's (see the class). */
  struct Parameters
  {
    DepthIntrinsics intrinsics;      ///< the camera (640 x 480, f = 580 px)
    double baseline = 75.0;          ///< mm from the camera to the projector, along +x
    double disparity_step = 0.125;   ///< px: the disparity's quantisation (0: none)
    double axial_noise = 1.2;        ///< mm: sigma_z at 0.4 m, the constant of the axial model
    double axial_noise_growth = 1.9; ///< mm per m^2 of (z - 0.4 m)^2 in sigma_z
    double incidence_noise = 0.1;    ///< mm: the incidence term's constant
    double lateral_noise = 0.8;      ///< px: sigma of the lateral error
    double max_incidence_deg = 75.0; ///< surfaces seen more obliquely return nothing
    double min_range = 500.0;        ///< mm: nearer surfaces return nothing
    double max_range = 4000.0;       ///< mm: farther surfaces return nothing
    double flying_pixel_jump = 20.0; ///< mm: a depth jump this large makes flying pixels beside it
    double flying_pixel_share = 0.5; ///< share of the pixels beside such a jump that fly
  };

  /** \brief A camera with the default (Kinect v1) Parameters. */
  DepthCameraSimulator () = default;

  /** \brief Throws InvalidInputError naming the setting if \a parameters are out of range.
   *  \param[in] parameters the sensor settings
   */
  explicit DepthCameraSimulator (const Parameters& parameters);

  /** \brief The sensor's settings.
   *  \return the parameters
   */
  const Parameters&
  parameters () const
  {
    return parameters_;
  }

  /** \brief The camera pose that looks from \a eye (mesh frame, mm) at \a target with the mesh's \a up (default +Y)
   *  upwards in the image.
   *  \param[in] target the point seen at the image centre (mm, mesh frame)
   *  \param[in] eye the camera centre (mm, mesh frame)
   *  \param[in] up the mesh's up direction
   *  \return mesh coordinates to camera coordinates (mm; x right, y down, z forward)
   */
  static Eigen::Isometry3d
  lookAt (const Eigen::Vector3d& target, const Eigen::Vector3d& eye,
          const Eigen::Vector3d& up = Eigen::Vector3d::UnitY ());

  /** \brief Renders \a mesh (validated; mm) seen from \a mesh_to_camera with the sensor's errors drawn from \a seed.
   *  Throws InvalidInputError if the camera sees nothing of the mesh.
   *  \param[in] mesh the scene
   *  \param[in] mesh_to_camera the camera pose (mesh mm to camera mm)
   *  \param[in] seed the seed of the noise
   *  \return the frame
   */
  DepthFrame
  render (const TriangleMesh& mesh, const Eigen::Isometry3d& mesh_to_camera, std::uint64_t seed) const;

private:
  Parameters parameters_;
};

/** \brief A person mesh (mm, +Y up) staged in a room as a depth camera sees it: a wall \a wall_distance mm behind
 *  the person's back and a floor \a floor_depth mm below the mesh's lowest point, both wide enough to fill a frame.
 *  \param[in] person the person (or head) mesh
 *  \param[in] wall_distance mm from the person's back (lowest z) to the wall
 *  \param[in] floor_depth mm from the person's lowest point down to the floor
 *  \return the person's triangles first, then the wall's and the floor's
 */
TriangleMesh
stageInRoom (const TriangleMesh& person, double wall_distance = 800.0, double floor_depth = 900.0);

} // namespace synthetic
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file scan_simulator.h
 *  \brief Simulated laser scans of a head mesh, with the ground truth a registration test needs.
 */
#include <morphreg/mesh/triangle_mesh.h>

#include <pcl/PolygonMesh.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Geometry>

#include <cstdint>
#include <vector>

namespace morphreg
{
namespace synthetic
{
/** \brief What a simulated scanner returned, and where every point truly came from. */
struct SimulatedScan
{
  /** Scan points (mm, in the scanner's frame) with the surface normal at each point; outliers last. */
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud;
  /** The triangulated range image (vertices = \a cloud, outliers unconnected); empty unless requested. */
  pcl::PolygonMesh range_mesh;
  /** The similarity that maps head coordinates into the scan: scan = head_to_scan * head (scale * R, t). */
  Eigen::Affine3d head_to_scan = Eigen::Affine3d::Identity ();
  double scale = 1.0; ///< the scale factor contained in head_to_scan
  /** Per point: the head triangle it lies on, or -1 for an outlier. */
  std::vector<int> source_triangle;
  /** Per point: barycentric coordinates of the noise-free point in source_triangle (zero for outliers). */
  Eigen::Matrix3Xd barycentric;
  /** Number of outliers (the last points of the cloud). */
  int num_outliers = 0;
};

/** \brief A cylindrical laser scanner (Cyberware-style): a horizontal ray from every angle around the vertical
 *  axis and every height row returns the first surface it meets, if that surface also faces the triangulating
 *  camera above the laser plane. Surfaces seen at grazing angles by the laser or facing away from the camera are
 *  lost (the crown, under the chin, the nostrils, the hollows behind the ears), as are surfaces hidden behind
 *  others. Range noise is
 *  Gaussian along the ray; outliers are spread uniformly over the scan's bounding box grown by 20%.
 *
 *  \code
 *  morphreg::synthetic::ScanSimulator scanner;              // defaults: about 60k points, sigma 0.2 mm
 *  auto scan = scanner.scan (head.mesh, 7);                 // deterministic from the seed
 *  \endcode
 */
class ScanSimulator
{
public:
  static constexpr int kMaxAngularSamples = 100000; ///< the most rays per turn (a scan must fit in memory)
  static constexpr double kMinRowSpacing = 0.01;    ///< mm, the closest scan rows

  /** \brief Scanner settings; the defaults give about 60k points on an average head. */
  struct Parameters
  {
    int angular_samples = 400;         ///< rays per turn around the vertical axis (8 to kMaxAngularSamples)
    double row_spacing = 1.5;          ///< mm between scan rows (at least kMinRowSpacing)
    double max_incidence_deg = 65;     ///< surfaces seen more obliquely than this by the laser or camera are lost
    double camera_elevation_deg = 25;  ///< the triangulating camera looks down at the laser plane from above
    double noise_sigma = 0.2;          ///< mm, Gaussian range noise along each ray
    double outlier_fraction = 0.01;    ///< outliers as a fraction of all returned points
    double max_rotation_deg = 20;      ///< the random pose: rotation angle up to this, about a random axis
    double max_scale_deviation = 0.05; ///< scale uniform in [1 - d, 1 + d]
    double max_translation = 100;      ///< mm, translation uniform in a ball of this radius
    bool range_mesh = false;           ///< also triangulate the range image
    double max_edge_length = 6;        ///< mm, range-image neighbours further apart are not connected
  };

  /** \brief A scanner with the default Parameters. */
  ScanSimulator () = default;

  /** \brief Throws InvalidInputError naming the setting if \a parameters are out of range.
   *  \param[in] parameters the scanner settings
   */
  explicit ScanSimulator (const Parameters& parameters);

  /** \brief The scanner's settings.
   *  \return the parameters
   */
  const Parameters&
  parameters () const
  {
    return parameters_;
  }

  /** \brief Scans \a head (validated; mm) with noise, outliers and pose drawn from \a seed. Throws
   *  InvalidInputError if the scanner sees nothing of it.
   *  \param[in] head the head mesh
   *  \param[in] seed the seed of the noise, outliers and pose
   *  \return the scan and its ground truth
   */

  SimulatedScan
  scan (const TriangleMesh& head, std::uint64_t seed) const;

private:
  Parameters parameters_;
};

} // namespace synthetic
} // namespace morphreg

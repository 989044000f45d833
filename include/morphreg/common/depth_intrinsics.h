// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file depth_intrinsics.h
 *  \brief A depth camera's pinhole intrinsics, and a depth image (mm per pixel, 0 where nothing came back) turned
 *  into the organised cloud PCL's grabbers deliver (width x height, NaN where the image has no depth).
 */
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief Pinhole intrinsics of a depth camera (pixels; x right, y down, the optical axis along +z). */
struct DepthIntrinsics
{
  int width = 640;   ///< image columns
  int height = 480;  ///< image rows
  double fx = 580.0; ///< focal length along x (px)
  double fy = 580.0; ///< focal length along y (px)
  double cx = 319.5; ///< principal point x (px, 0 at the first column's centre)
  double cy = 239.5; ///< principal point y (px, 0 at the first row's centre)
};

/** \brief Throws InvalidInputError naming \a name if \a intrinsics are not a usable camera: a size of 1 to 16384
 *  pixels a side, positive finite focal lengths and a finite principal point.
 *  \param[in] intrinsics the intrinsics to check
 *  \param[in] name what they are (e.g. their file), for the message
 */
void
requireValidIntrinsics (const DepthIntrinsics& intrinsics, const std::string& name);

/** \brief The organised cloud of a depth image: pixel (u, v) with depth z mm becomes the point
 *  ((u - cx) z / fx, (v - cy) z / fy, z) in mm, in the camera frame; pixels without depth (0) become NaN points.
 *  Throws InvalidInputError if \a depth_mm does not hold width x height values or the intrinsics are invalid.
 *  \param[in] depth_mm the depth per pixel, row by row (mm; 0 = no depth)
 *  \param[in] intrinsics the camera
 *  \return the organised cloud (width x height, mm, is_dense false)
 */
pcl::PointCloud<pcl::PointXYZ>::Ptr
depthImageToCloud (const std::vector<std::uint16_t>& depth_mm, const DepthIntrinsics& intrinsics);

} // namespace morphreg

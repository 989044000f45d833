// SPDX-License-Identifier: BSD-3-Clause
#include "number_text.h"

#include <morphreg/common/depth_intrinsics.h>
#include <morphreg/common/error.h>

#include <cmath>
#include <limits>

namespace morphreg
{
namespace
{
constexpr int kMaxImageSide = 16384;
}

void
requireValidIntrinsics (const DepthIntrinsics& intrinsics, const std::string& name)
{
  using detail::numberText;
  if (intrinsics.width < 1 || intrinsics.width > kMaxImageSide || intrinsics.height < 1 ||
      intrinsics.height > kMaxImageSide)
    throw InvalidInputError (name + ": the image size " + std::to_string (intrinsics.width) + " x " +
                             std::to_string (intrinsics.height) + " is not 1 to " + std::to_string (kMaxImageSide) +
                             " pixels a side");
  if (!(intrinsics.fx > 0.0 && intrinsics.fy > 0.0 && std::isfinite (intrinsics.fx) && std::isfinite (intrinsics.fy)))
    throw InvalidInputError (name + ": the focal lengths fx = " + numberText (intrinsics.fx) +
                             ", fy = " + numberText (intrinsics.fy) + " px must be positive and finite");
  if (!std::isfinite (intrinsics.cx) || !std::isfinite (intrinsics.cy))
    throw InvalidInputError (name + ": the principal point (" + numberText (intrinsics.cx) + ", " +
                             numberText (intrinsics.cy) + ") px is not finite");
}

pcl::PointCloud<pcl::PointXYZ>::Ptr
depthImageToCloud (const std::vector<std::uint16_t>& depth_mm, const DepthIntrinsics& intrinsics)
{
  requireValidIntrinsics (intrinsics, "the depth camera");
  const std::size_t pixels = static_cast<std::size_t> (intrinsics.width) * static_cast<std::size_t> (intrinsics.height);
  if (depth_mm.size () != pixels)
    throw InvalidInputError ("the depth image has " + std::to_string (depth_mm.size ()) + " pixels, the camera " +
                             std::to_string (intrinsics.width) + " x " + std::to_string (intrinsics.height));
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ> (
      static_cast<std::uint32_t> (intrinsics.width), static_cast<std::uint32_t> (intrinsics.height)));
  cloud->is_dense = false;
  const float missing = std::numeric_limits<float>::quiet_NaN ();
  for (int v = 0; v < intrinsics.height; ++v)
    for (int u = 0; u < intrinsics.width; ++u) {
      const std::uint16_t z = depth_mm[static_cast<std::size_t> (v) * intrinsics.width + u];
      pcl::PointXYZ& point = (*cloud) (u, v);
      if (z == 0) {
        point.x = point.y = point.z = missing;
        continue;
      }
      point.x = static_cast<float> ((u - intrinsics.cx) * z / intrinsics.fx);
      point.y = static_cast<float> ((v - intrinsics.cy) * z / intrinsics.fy);
      point.z = static_cast<float> (z);
    }
  return cloud;
}

} // namespace morphreg

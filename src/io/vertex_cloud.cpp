// SPDX-License-Identifier: BSD-3-Clause
#include "vertex_cloud.h"

#include <pcl/conversions.h>
#include <pcl/point_types.h>

namespace morphreg
{
namespace
{
template <typename PointT>
pcl::PCLPointCloud2
toCloud (const Eigen::Matrix3Xf& positions, const Eigen::Matrix3Xf& normals, const VertexColours& colours)
{
  pcl::PointCloud<PointT> cloud;
  cloud.resize (positions.cols ());
  for (Eigen::Index i = 0; i < positions.cols (); ++i) {
    auto& point = cloud[i];
    point.getVector3fMap () = positions.col (i);
    if constexpr (pcl::traits::has_normal_v<PointT>)
      point.getNormalVector3fMap () = normals.col (i);
    if constexpr (pcl::traits::has_color_v<PointT>)
      point.r = colours (0, i), point.g = colours (1, i), point.b = colours (2, i);
  }
  pcl::PCLPointCloud2 blob;
  pcl::toPCLPointCloud2 (cloud, blob);
  return blob;
}
} // namespace

pcl::PCLPointCloud2
vertexCloud (const Eigen::Matrix3Xf& positions, const Eigen::Matrix3Xf& normals, const VertexColours& colours)
{
  const bool with_normals = normals.cols () == positions.cols (), with_colours = colours.cols () == positions.cols ();
  if (with_normals && with_colours)
    return toCloud<pcl::PointXYZRGBNormal> (positions, normals, colours);
  if (with_colours)
    return toCloud<pcl::PointXYZRGB> (positions, normals, colours);
  if (with_normals)
    return toCloud<pcl::PointNormal> (positions, normals, colours);
  return toCloud<pcl::PointXYZ> (positions, normals, colours);
}
} // namespace morphreg

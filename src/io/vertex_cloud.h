// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private to the mesh readers: the vertex cloud of a mesh file with the fields it has.
#include <morphreg/common/colour_map.h>

#include <pcl/PCLPointCloud2.h>

namespace morphreg
{
/** The vertices as a cloud: x y z, with normals when \a normals has one per vertex and an rgb colour when \a colours
 *  has one per vertex (PointXYZ, PointNormal, PointXYZRGB or PointXYZRGBNormal fields). */
pcl::PCLPointCloud2
vertexCloud (const Eigen::Matrix3Xf& positions, const Eigen::Matrix3Xf& normals, const VertexColours& colours);
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file field_precision.h
 *  \brief Double-precision fields of a loaded cloud narrowed to float, so that PCL's point types receive them:
 *  pcl::fromPCLPointCloud2 copies a field only when its type matches the point's (float), and leaves x, y and z of a
 *  PLY written with "property double x" (Open3D, trimesh, MeshLab's double option) at zero otherwise.
 */
#include <pcl/PCLPointCloud2.h>

#include <string>

namespace morphreg
{
/** \brief Rewrites every FLOAT64 field of \a cloud as FLOAT32, in place (the other fields are kept byte for byte).
 *  Throws FormatError naming \a path, the field and the point when a finite value lies beyond float's range (its
 *  magnitude above 3.4e38), which would otherwise turn into infinity; NaN and infinity stay what they were.
 *  \param[in,out] cloud the cloud as a reader gave it
 *  \param[in] path the file it came from, for the message
 */
void
narrowDoubleFields (pcl::PCLPointCloud2& cloud, const std::string& path);

} // namespace morphreg

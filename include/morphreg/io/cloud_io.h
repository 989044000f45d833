// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file cloud_io.h
 *  \brief Reading and writing point clouds (PCD, PLY, OBJ; STL, OFF and glTF/GLB meshes read as their vertices) of
 *  any PCL point type, with errors that name the file.
 */
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <string>

namespace morphreg
{
/** \brief Loads a cloud (.pcd, .ply, .obj, .stl, .off, .gltf or .glb; for a mesh file, its vertices; glTF's metres
 *  converted to mm, its colours kept, see gltf_reader.h). Throws IoError if the file is missing or unreadable,
 *  FormatError if it has no points.
 *  \param[in] path the file
 *  \return the cloud, fields the file lacks left at their defaults
 */
template <typename PointT>
typename pcl::PointCloud<PointT>::Ptr
loadCloud (const std::string& path);

/** \brief Saves a cloud as binary .pcd or .ply, or as .obj vertices, whole or not at all (as savePolygonMesh());
 *  throws IoError naming the file on failure, a full disk included.
 *  \param[in] path the file; its extension chooses the format
 *  \param[in] cloud the points to write
 */
template <typename PointT>
void
saveCloud (const std::string& path, const pcl::PointCloud<PointT>& cloud);

} // namespace morphreg

/// \cond
#define MORPHREG_DECLARE_CLOUD_IO(T)                                                                                   \
  extern template pcl::PointCloud<T>::Ptr morphreg::loadCloud<T> (const std::string&);                                 \
  extern template void morphreg::saveCloud<T> (const std::string&, const pcl::PointCloud<T>&);
MORPHREG_DECLARE_CLOUD_IO (pcl::PointXYZ)
MORPHREG_DECLARE_CLOUD_IO (pcl::PointNormal)
MORPHREG_DECLARE_CLOUD_IO (pcl::PointXYZRGBNormal)
#undef MORPHREG_DECLARE_CLOUD_IO
/// \endcond

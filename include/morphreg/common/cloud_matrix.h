// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file cloud_matrix.h
 *  \brief Point clouds as 3 x N double matrices, the layout the solvers and mesh code work on.
 */
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

namespace morphreg
{
/** \brief The positions of \a cloud as columns (double precision).
 *  \param[in] cloud any point type with x, y, z
 *  \return a 3 x cloud.size () matrix
 */
template <typename PointT>
Eigen::Matrix3Xd
pointsOf (const pcl::PointCloud<PointT>& cloud)
{
  Eigen::Matrix3Xd points (3, static_cast<Eigen::Index> (cloud.size ()));
  for (size_t i = 0; i < cloud.size (); ++i)
    points.col (static_cast<Eigen::Index> (i)) = cloud[i].getVector3fMap ().template cast<double> ();
  return points;
}

/** \brief The normals of \a cloud as columns (double precision), as stored (not renormalised).
 *  \param[in] cloud a point type with normal_x, normal_y, normal_z
 *  \return a 3 x cloud.size () matrix
 */
template <typename PointT>
Eigen::Matrix3Xd
normalsOf (const pcl::PointCloud<PointT>& cloud)
{
  static_assert (pcl::traits::has_normal_v<PointT>, "normalsOf needs a point type with normals");
  Eigen::Matrix3Xd normals (3, static_cast<Eigen::Index> (cloud.size ()));
  for (size_t i = 0; i < cloud.size (); ++i)
    normals.col (static_cast<Eigen::Index> (i)) = cloud[i].getNormalVector3fMap ().template cast<double> ();
  return normals;
}

/** \brief The normals of \a cloud as columns when its point type has normals, else an empty matrix (the caller then
 *  estimates them).
 *  \param[in] cloud any point type with x, y, z
 *  \return a 3 x cloud.size () matrix, or 3 x 0
 */
template <typename PointT>
Eigen::Matrix3Xd
normalsIfAny (const pcl::PointCloud<PointT>& cloud)
{
  if constexpr (pcl::traits::has_normal_v<PointT>)
    return normalsOf (cloud);
  else
    return Eigen::Matrix3Xd (3, 0);
}
} // namespace morphreg

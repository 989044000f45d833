// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file cloud_checks.h
 *  \brief Checks of a point cloud before an algorithm uses it, with errors that name the cloud.
 */
#include <pcl/point_cloud.h>

#include <string>

namespace morphreg
{
/** \brief Throws InvalidInputError naming \a name if \a cloud is empty or has a non-finite point.
 *  \param[in] cloud the cloud to check
 *  \param[in] name what the cloud is (e.g. its file), for the message
 */
template <typename PointT>
void
requireFiniteNonEmpty (const pcl::PointCloud<PointT>& cloud, const std::string& name);

} // namespace morphreg

#include <morphreg/common/impl/cloud_checks.hpp>

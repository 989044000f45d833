// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/registration/impl/cached_correspondence_estimation.hpp>

#include <pcl/point_types.h>

template class morphreg::CachedCorrespondenceEstimation<pcl::PointXYZ, pcl::PointXYZ, float>;
template class morphreg::CachedCorrespondenceEstimation<pcl::PointNormal, pcl::PointNormal, float>;
template class morphreg::CachedCorrespondenceEstimation<pcl::PointXYZRGBNormal, pcl::PointXYZRGBNormal, float>;

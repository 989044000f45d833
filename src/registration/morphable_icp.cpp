// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/registration/impl/morphable_icp.hpp>

template class morphreg::MorphableICP<pcl::PointXYZ, float>;
template class morphreg::MorphableICP<pcl::PointNormal, float>;
template class morphreg::MorphableICP<pcl::PointXYZRGBNormal, float>;

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/warp/impl/transformation_estimation_tps.hpp>

#define MORPHREG_INSTANTIATE_TPS_ESTIMATION(T)                                                                         \
  template class morphreg::TransformationEstimationTPS<T, T, double>;                                                  \
  template class morphreg::TransformationEstimationTPS<T, T, float>;
MORPHREG_INSTANTIATE_TPS_ESTIMATION (pcl::PointXYZ)
MORPHREG_INSTANTIATE_TPS_ESTIMATION (pcl::PointNormal)
MORPHREG_INSTANTIATE_TPS_ESTIMATION (pcl::PointXYZRGBNormal)

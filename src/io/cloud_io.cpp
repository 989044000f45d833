// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/io/impl/cloud_io.hpp>

#define MORPHREG_INSTANTIATE_CLOUD_IO(T)                                                                               \
  template pcl::PointCloud<T>::Ptr morphreg::loadCloud<T> (const std::string&);                                        \
  template void morphreg::saveCloud<T> (const std::string&, const pcl::PointCloud<T>&);
MORPHREG_INSTANTIATE_CLOUD_IO (pcl::PointXYZ)
MORPHREG_INSTANTIATE_CLOUD_IO (pcl::PointNormal)
MORPHREG_INSTANTIATE_CLOUD_IO (pcl::PointXYZRGBNormal)

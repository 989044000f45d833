// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/warp/impl/thin_plate_spline.hpp>

#define MORPHREG_INSTANTIATE_TPS_POINT(S, D, T)                                                                        \
  template void morphreg::ThinPlateSpline<S, D>::fit<T, T> (const pcl::PointCloud<T>&, const pcl::PointCloud<T>&);     \
  template void morphreg::ThinPlateSpline<S, D>::fit<T, T> (const pcl::PointCloud<T>&, const pcl::PointCloud<T>&,      \
                                                            const pcl::Correspondences&);                              \
  template void morphreg::ThinPlateSpline<S, D>::transformCloud<T> (const pcl::PointCloud<T>&, pcl::PointCloud<T>&)    \
      const;                                                                                                           \
  template Eigen::Matrix<S, D, Eigen::Dynamic> morphreg::cloudCoordinates<S, D, T> (const pcl::PointCloud<T>&,         \
                                                                                    const pcl::Indices&);
#define MORPHREG_INSTANTIATE_TPS(S, D)                                                                                 \
  template class morphreg::ThinPlateSpline<S, D>;                                                                      \
  MORPHREG_INSTANTIATE_TPS_POINT (S, D, pcl::PointXYZ)                                                                 \
  MORPHREG_INSTANTIATE_TPS_POINT (S, D, pcl::PointNormal)                                                              \
  MORPHREG_INSTANTIATE_TPS_POINT (S, D, pcl::PointXYZRGBNormal)
MORPHREG_INSTANTIATE_TPS (double, 3)
MORPHREG_INSTANTIATE_TPS (float, 3)
MORPHREG_INSTANTIATE_TPS (double, 2)
MORPHREG_INSTANTIATE_TPS (float, 2)

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/common/error.h>
#include <morphreg/warp/impl/thin_plate_spline.hpp>
#include <morphreg/warp/transformation_estimation_tps.h>

namespace morphreg
{
namespace detail
{
/** \brief Throws InvalidInputError naming \a which if \a indices is empty (empty would otherwise mean "all"). */
inline void
requireIndices (const pcl::Indices& indices, const char* which)
{
  if (indices.empty ())
    throw InvalidInputError (std::string ("TransformationEstimationTPS::estimateTransformation: ") + which +
                             " is empty");
}
} // namespace detail

template <typename PointSource, typename PointTarget, typename Scalar>
typename TransformationEstimationTPS<PointSource, PointTarget, Scalar>::Spline&
TransformationEstimationTPS<PointSource, PointTarget, Scalar>::configure (Spline& spline) const
{
  spline.setRegularization (settings_.getRegularization ());
  spline.setMaxConditionNumber (settings_.getMaxConditionNumber ());
  return spline;
}

template <typename PointSource, typename PointTarget, typename Scalar>
void
TransformationEstimationTPS<PointSource, PointTarget, Scalar>::estimateTransformation (
    const PointCloudSource& cloud_src, const PointCloudTarget& cloud_tgt, Spline& spline) const
{
  configure (spline).fit (cloud_src, cloud_tgt);
}

template <typename PointSource, typename PointTarget, typename Scalar>
void
TransformationEstimationTPS<PointSource, PointTarget, Scalar>::estimateTransformation (
    const PointCloudSource& cloud_src, const pcl::Indices& indices_src, const PointCloudTarget& cloud_tgt,
    Spline& spline) const
{
  detail::requireIndices (indices_src, "indices_src");
  configure (spline).fit (cloudCoordinates<Scalar, 3> (cloud_src, indices_src),
                          cloudCoordinates<Scalar, 3> (cloud_tgt));
}

template <typename PointSource, typename PointTarget, typename Scalar>
void
TransformationEstimationTPS<PointSource, PointTarget, Scalar>::estimateTransformation (
    const PointCloudSource& cloud_src, const pcl::Indices& indices_src, const PointCloudTarget& cloud_tgt,
    const pcl::Indices& indices_tgt, Spline& spline) const
{
  detail::requireIndices (indices_src, "indices_src");
  detail::requireIndices (indices_tgt, "indices_tgt");
  configure (spline).fit (cloudCoordinates<Scalar, 3> (cloud_src, indices_src),
                          cloudCoordinates<Scalar, 3> (cloud_tgt, indices_tgt));
}

template <typename PointSource, typename PointTarget, typename Scalar>
void
TransformationEstimationTPS<PointSource, PointTarget, Scalar>::estimateTransformation (
    const PointCloudSource& cloud_src, const PointCloudTarget& cloud_tgt, const pcl::Correspondences& correspondences,
    Spline& spline) const
{
  configure (spline).fit (cloud_src, cloud_tgt, correspondences);
}

} // namespace morphreg

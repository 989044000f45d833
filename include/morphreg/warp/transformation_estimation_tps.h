// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file transformation_estimation_tps.h
 *  \brief PCL-style estimation of a thin plate spline warp from corresponding points, next to PCL's
 *  pcl::registration::TransformationEstimation* classes (which estimate rigid/affine matrices instead).
 */
#include <morphreg/warp/thin_plate_spline.h>

#include <pcl/correspondence.h>
#include <pcl/point_cloud.h>
#include <pcl/types.h>

#include <memory>

namespace morphreg
{
/** \brief Estimates the ThinPlateSpline that carries source points onto their target points, from whole clouds
 *  (point i to point i), index lists or pcl::Correspondences, like pcl::registration::TransformationEstimation
 *  does for rigid transforms. Coincident pairs are merged; degenerate input throws (see ThinPlateSpline).
 *
 *  \code
 *  morphreg::TransformationEstimationTPS<pcl::PointXYZ, pcl::PointXYZ> estimation;
 *  morphreg::ThinPlateSpline<double, 3> warp;
 *  estimation.estimateTransformation (*scan_landmarks, *model_landmarks, *correspondences, warp);
 *  warp.transformCloud (*scan, *warped_scan);
 *  \endcode
 */
template <typename PointSource, typename PointTarget, typename Scalar = double>
class TransformationEstimationTPS
{
public:
  using Ptr = std::shared_ptr<TransformationEstimationTPS>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const TransformationEstimationTPS>; ///< shared pointer to const
  using PointCloudSource = pcl::PointCloud<PointSource>;               ///< the source cloud type
  using PointCloudTarget = pcl::PointCloud<PointTarget>;               ///< the target cloud type
  using Spline = ThinPlateSpline<Scalar, 3>;                           ///< the estimated warp

  /** \brief Regularisation lambda of the estimated splines (see ThinPlateSpline::setRegularization).
   *  \param[in] lambda the smoothing weight, >= 0
   */
  void
  setRegularization (double lambda)
  {
    settings_.setRegularization (lambda);
  }

  /** \brief Regularisation lambda of the estimated splines.
   *  \return lambda
   */
  double
  getRegularization () const
  {
    return settings_.getRegularization ();
  }

  /** \brief Condition limit of the estimated splines (see ThinPlateSpline::setMaxConditionNumber).
   *  \param[in] limit the largest accepted condition estimate
   */
  void
  setMaxConditionNumber (double limit)
  {
    settings_.setMaxConditionNumber (limit);
  }

  /** \brief Condition limit of the estimated splines.
   *  \return the limit
   */
  double
  getMaxConditionNumber () const
  {
    return settings_.getMaxConditionNumber ();
  }

  /** \brief Source point i goes to target point i; the clouds must have the same size.
   *  \param[in] cloud_src the source points
   *  \param[in] cloud_tgt the target points
   *  \param[out] spline the fitted warp
   */
  void
  estimateTransformation (const PointCloudSource& cloud_src, const PointCloudTarget& cloud_tgt, Spline& spline) const;

  /** \brief Source point indices_src[i] goes to target point i.
   *  \param[in] cloud_src the source cloud
   *  \param[in] indices_src the source points used, one per target point
   *  \param[in] cloud_tgt the target points
   *  \param[out] spline the fitted warp
   */
  void
  estimateTransformation (const PointCloudSource& cloud_src, const pcl::Indices& indices_src,
                          const PointCloudTarget& cloud_tgt, Spline& spline) const;

  /** \brief Source point indices_src[i] goes to target point indices_tgt[i].
   *  \param[in] cloud_src the source cloud
   *  \param[in] indices_src the source points used
   *  \param[in] cloud_tgt the target cloud
   *  \param[in] indices_tgt the target points, as many as \a indices_src
   *  \param[out] spline the fitted warp
   */
  void
  estimateTransformation (const PointCloudSource& cloud_src, const pcl::Indices& indices_src,
                          const PointCloudTarget& cloud_tgt, const pcl::Indices& indices_tgt, Spline& spline) const;

  /** \brief Each correspondence maps source point index_query to target point index_match.
   *  \param[in] cloud_src the source cloud
   *  \param[in] cloud_tgt the target cloud
   *  \param[in] correspondences the point pairs
   *  \param[out] spline the fitted warp
   */
  void
  estimateTransformation (const PointCloudSource& cloud_src, const PointCloudTarget& cloud_tgt,
                          const pcl::Correspondences& correspondences, Spline& spline) const;

private:
  /** Copies the settings into \a spline. */
  Spline&
  configure (Spline& spline) const;

  Spline settings_; ///< holds (and validates) the settings; never fitted
};

} // namespace morphreg

/// \cond
#define MORPHREG_DECLARE_TPS_ESTIMATION(T)                                                                             \
  extern template class morphreg::TransformationEstimationTPS<T, T, double>;                                           \
  extern template class morphreg::TransformationEstimationTPS<T, T, float>;
MORPHREG_DECLARE_TPS_ESTIMATION (pcl::PointXYZ)
MORPHREG_DECLARE_TPS_ESTIMATION (pcl::PointNormal)
MORPHREG_DECLARE_TPS_ESTIMATION (pcl::PointXYZRGBNormal)
#undef MORPHREG_DECLARE_TPS_ESTIMATION
/// \endcond

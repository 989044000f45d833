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
  using Ptr = std::shared_ptr<TransformationEstimationTPS>;
  using ConstPtr = std::shared_ptr<const TransformationEstimationTPS>;
  using PointCloudSource = pcl::PointCloud<PointSource>;
  using PointCloudTarget = pcl::PointCloud<PointTarget>;
  using Spline = ThinPlateSpline<Scalar, 3>;

  /** \brief Regularisation lambda of the estimated splines (see ThinPlateSpline::setRegularization). */
  void
  setRegularization (double lambda)
  {
    settings_.setRegularization (lambda);
  }

  double
  getRegularization () const
  {
    return settings_.getRegularization ();
  }

  /** \brief Condition limit of the estimated splines (see ThinPlateSpline::setMaxConditionNumber). */
  void
  setMaxConditionNumber (double limit)
  {
    settings_.setMaxConditionNumber (limit);
  }

  double
  getMaxConditionNumber () const
  {
    return settings_.getMaxConditionNumber ();
  }

  /** \brief Source point i goes to target point i; the clouds must have the same size. */
  void
  estimateTransformation (const PointCloudSource& cloud_src, const PointCloudTarget& cloud_tgt, Spline& spline) const;

  /** \brief Source point indices_src[i] goes to target point i. */
  void
  estimateTransformation (const PointCloudSource& cloud_src, const pcl::Indices& indices_src,
                          const PointCloudTarget& cloud_tgt, Spline& spline) const;

  /** \brief Source point indices_src[i] goes to target point indices_tgt[i]. */
  void
  estimateTransformation (const PointCloudSource& cloud_src, const pcl::Indices& indices_src,
                          const PointCloudTarget& cloud_tgt, const pcl::Indices& indices_tgt, Spline& spline) const;

  /** \brief Each correspondence maps source point index_query to target point index_match. */
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

#define MORPHREG_DECLARE_TPS_ESTIMATION(T)                                                                         \
  extern template class morphreg::TransformationEstimationTPS<T, T, double>;                                      \
  extern template class morphreg::TransformationEstimationTPS<T, T, float>;
MORPHREG_DECLARE_TPS_ESTIMATION (pcl::PointXYZ)
MORPHREG_DECLARE_TPS_ESTIMATION (pcl::PointNormal)
MORPHREG_DECLARE_TPS_ESTIMATION (pcl::PointXYZRGBNormal)
#undef MORPHREG_DECLARE_TPS_ESTIMATION

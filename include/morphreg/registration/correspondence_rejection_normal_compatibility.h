// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file correspondence_rejection_normal_compatibility.h
 *  \brief Rejects correspondences whose source normal and target normal disagree.
 */
#include <morphreg/registration/target_surface.h>

#include <pcl/PCLPointCloud2.h>
#include <pcl/registration/correspondence_rejection.h>

#include <Eigen/Core>

namespace morphreg
{
/** \brief A pcl::registration::CorrespondenceRejector that drops every correspondence whose source normal (the posed
 *  model's vertex normal, from setSourceNormals) and target normal (the TargetSurface's, oriented: given by the scan,
 *  or estimated and turned towards the sensor or away from the scan's centre) differ by more than a maximum angle
 *  (default 60 degrees). The far side of a model fitted to one view of a head would otherwise pull onto the near
 *  side's surface and shrink the fit, and a thin part (an ear) would pull across to its other face. MorphableICP puts
 *  one, on its own target surface, in its default chain (see MorphableICP::getNormalCompatibilityRejector).
 */
class CorrespondenceRejectorNormalCompatibility : public pcl::registration::CorrespondenceRejector
{
public:
  using Ptr = std::shared_ptr<CorrespondenceRejectorNormalCompatibility>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const CorrespondenceRejectorNormalCompatibility>; ///< shared pointer to const

  /** \param[in] surface the target surface whose normals decide (may be set later) */
  explicit CorrespondenceRejectorNormalCompatibility (TargetSurface::Ptr surface = nullptr);

  /** \brief Sets the surface whose normals decide.
   *  \param[in] surface the target surface, holding the same points as the correspondences' target cloud
   */
  void
  setTargetSurface (TargetSurface::Ptr surface)
  {
    surface_ = std::move (surface);
  }

  /** \brief The largest angle between a kept correspondence's normals (degrees, 0 to 180; default 60). Throws
   *  InvalidInputError outside that range.
   *  \param[in] degrees the angle
   */
  void
  setMaximumAngle (double degrees);

  /** \brief The largest angle kept.
   *  \return degrees
   */
  double
  getMaximumAngle () const
  {
    return max_angle_deg_;
  }

  /** \brief The source normals come from the source points' cloud (normal_x, normal_y, normal_z).
   *  \return true
   */
  bool
  requiresSourceNormals () const override
  {
    return true;
  }

  /** \brief Takes the source's normals (a cloud with normal_x, normal_y, normal_z fields).
   *  \param[in] cloud the source points with their normals
   */
  void
  setSourceNormals (pcl::PCLPointCloud2::ConstPtr cloud) override;

  /** \brief The correspondences of \a original whose normals agree (or that have no target normal). Throws
   *  InvalidInputError without a target surface or source normals.
   *  \param[in] original the correspondences
   *  \param[out] remaining those kept
   */
  void
  getRemainingCorrespondences (const pcl::Correspondences& original, pcl::Correspondences& remaining) override;

protected:
  /** \brief PCL's rejection hook: getRemainingCorrespondences applied to the input correspondences.
   *  \param[out] correspondences the input correspondences whose normals agree
   */
  void
  applyRejection (pcl::Correspondences& correspondences) override;

private:
  TargetSurface::Ptr surface_;      ///< the surface whose normals decide
  Eigen::Matrix3Xd source_normals_; ///< per source point
  double max_angle_deg_ = 60.0;     ///< largest angle kept
};
} // namespace morphreg

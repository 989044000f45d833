// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file correspondence_rejection_target_boundary.h
 *  \brief Rejects correspondences whose target point lies on the target surface's boundary.
 */
#include <morphreg/registration/target_surface.h>

#include <pcl/registration/correspondence_rejection.h>

namespace morphreg
{
/** \brief A pcl::registration::CorrespondenceRejector that drops every correspondence whose target point is a
 *  boundary point of a TargetSurface (hole borders, scan edges, isolated outliers): there the nearest point is not
 *  the model's counterpart, and its pull drags the fit across the hole. The surface's points are computed on first
 *  use, so only points that become correspondences pay for their neighbourhood. MorphableICP puts one, on its own
 *  target surface, in its default chain (see MorphableICP::getTargetBoundaryRejector).
 *
 *  \code
 *  auto surface = std::make_shared<morphreg::TargetSurface> ();
 *  surface->setInputTarget (points, normals, search);
 *  morphreg::CorrespondenceRejectorTargetBoundary rejector (surface);
 *  rejector.getRemainingCorrespondences (all, inside);
 *  \endcode
 */
class CorrespondenceRejectorTargetBoundary : public pcl::registration::CorrespondenceRejector
{
public:
  using Ptr = std::shared_ptr<CorrespondenceRejectorTargetBoundary>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const CorrespondenceRejectorTargetBoundary>; ///< shared pointer to const

  /** \param[in] surface the target surface whose boundary flags decide (may be set later) */
  explicit CorrespondenceRejectorTargetBoundary (TargetSurface::Ptr surface = nullptr);

  /** \brief Sets the surface whose boundary flags decide which correspondences are dropped.
   *  \param[in] surface the target surface, holding the same points as the correspondences' target cloud
   */
  void
  setTargetSurface (TargetSurface::Ptr surface)
  {
    surface_ = std::move (surface);
  }

  /** \brief The surface whose boundary flags decide.
   *  \return the target surface, or nullptr if none is set
   */
  TargetSurface::Ptr
  getTargetSurface () const
  {
    return surface_;
  }

  /** \brief The correspondences of \a original whose target point is not a boundary point. Throws
   *  InvalidInputError without a target surface.
   *  \param[in] original the correspondences
   *  \param[out] remaining those kept
   */
  void
  getRemainingCorrespondences (const pcl::Correspondences& original, pcl::Correspondences& remaining) override;

protected:
  /** \brief PCL's rejection hook: getRemainingCorrespondences applied to the input correspondences.
   *  \param[out] correspondences the input correspondences whose target point is not a boundary point
   */
  void
  applyRejection (pcl::Correspondences& correspondences) override;

private:
  TargetSurface::Ptr surface_; ///< the surface whose boundary flags decide
};
} // namespace morphreg

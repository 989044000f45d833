// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/registration/correspondence_rejection_target_boundary.h>

namespace morphreg
{
CorrespondenceRejectorTargetBoundary::CorrespondenceRejectorTargetBoundary (TargetSurface::Ptr surface)
  : surface_ (std::move (surface))
{
  rejection_name_ = "CorrespondenceRejectorTargetBoundary";
}

void
CorrespondenceRejectorTargetBoundary::getRemainingCorrespondences (const pcl::Correspondences& original,
                                                                   pcl::Correspondences& remaining)
{
  if (!surface_)
    throw InvalidInputError ("CorrespondenceRejectorTargetBoundary: no target surface (call setTargetSurface)");
  surface_->compute (original);
  pcl::Correspondences kept;
  kept.reserve (original.size ());
  for (const pcl::Correspondence& c : original)
    if (!surface_->isBoundary (c.index_match))
      kept.push_back (c);
  remaining.swap (kept);
}

void
CorrespondenceRejectorTargetBoundary::applyRejection (pcl::Correspondences& correspondences)
{
  getRemainingCorrespondences (*input_correspondences_, correspondences);
}
} // namespace morphreg

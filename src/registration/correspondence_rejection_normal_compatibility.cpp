// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/registration/correspondence_rejection_normal_compatibility.h>

#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <cmath>

namespace morphreg
{
CorrespondenceRejectorNormalCompatibility::CorrespondenceRejectorNormalCompatibility (TargetSurface::Ptr surface)
  : surface_ (std::move (surface))
{
  rejection_name_ = "CorrespondenceRejectorNormalCompatibility";
}

void
CorrespondenceRejectorNormalCompatibility::setMaximumAngle (double degrees)
{
  if (!(degrees >= 0.0 && degrees <= 180.0))
    throw InvalidInputError ("CorrespondenceRejectorNormalCompatibility::setMaximumAngle: " + std::to_string (degrees) +
                             " degrees is not 0 to 180");
  max_angle_deg_ = degrees;
}

void
CorrespondenceRejectorNormalCompatibility::setSourceNormals (pcl::PCLPointCloud2::ConstPtr cloud)
{
  pcl::PointCloud<pcl::Normal> normals;
  pcl::fromPCLPointCloud2 (*cloud, normals);
  source_normals_.resize (3, static_cast<Eigen::Index> (normals.size ()));
  for (std::size_t i = 0; i < normals.size (); ++i)
    source_normals_.col (static_cast<Eigen::Index> (i)) = normals[i].getNormalVector3fMap ().cast<double> ();
}

void
CorrespondenceRejectorNormalCompatibility::getRemainingCorrespondences (const pcl::Correspondences& original,
                                                                        pcl::Correspondences& remaining)
{
  if (!surface_)
    throw InvalidInputError ("CorrespondenceRejectorNormalCompatibility: no target surface (call setTargetSurface)");
  surface_->compute (original);
  const double min_cosine = std::cos (max_angle_deg_ * M_PI / 180.0);
  pcl::Correspondences kept;
  kept.reserve (original.size ());
  for (const pcl::Correspondence& c : original) {
    if (c.index_query < 0 || c.index_query >= source_normals_.cols ())
      throw InvalidInputError ("CorrespondenceRejectorNormalCompatibility: no source normal for point " +
                               std::to_string (c.index_query) + " (call setSourceNormals)");
    const Eigen::Vector3d source = source_normals_.col (c.index_query);
    const bool judged = surface_->hasNormal (c.index_match) && source.allFinite () && source.squaredNorm () > 0.0;
    if (!judged || source.normalized ().dot (surface_->normal (c.index_match)) >= min_cosine)
      kept.push_back (c);
  }
  remaining.swap (kept);
}

void
CorrespondenceRejectorNormalCompatibility::applyRejection (pcl::Correspondences& correspondences)
{
  getRemainingCorrespondences (*input_correspondences_, correspondences);
}
} // namespace morphreg

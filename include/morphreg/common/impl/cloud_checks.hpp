// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/common/cloud_checks.h>
#include <morphreg/common/error.h>

#include <cmath>
#include <sstream>

namespace morphreg
{
template <typename PointT>
void
requireFiniteNonEmpty (const pcl::PointCloud<PointT>& cloud, const std::string& name)
{
  if (cloud.empty ())
    throw InvalidInputError (name + ": the cloud is empty");
  for (std::size_t i = 0; i < cloud.size (); ++i)
    if (!std::isfinite (cloud[i].x) || !std::isfinite (cloud[i].y) || !std::isfinite (cloud[i].z)) {
      std::ostringstream msg;
      msg << name << ": point " << i << " is not finite (NaN or Inf); remove invalid points first "
          << "(pcl::removeNaNFromPointCloud)";
      throw InvalidInputError (msg.str ());
    }
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/model/model_radius.h>

#include <cmath>

namespace morphreg
{
double
modelRadius (const MorphableModel& model)
{
  const Eigen::Map<const Eigen::Matrix3Xd> mean (model.mean ().data (), 3, model.numVertices ());
  const Eigen::Vector3d centroid = mean.rowwise ().mean ();
  return std::sqrt ((mean.colwise () - centroid).colwise ().squaredNorm ().mean ());
}
} // namespace morphreg

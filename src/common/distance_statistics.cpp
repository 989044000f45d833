// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/distance_statistics.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace morphreg
{
std::vector<double>
sortedFinite (const Eigen::VectorXd& values)
{
  std::vector<double> finite;
  for (double v : values)
    if (std::isfinite (v))
      finite.push_back (v);
  std::sort (finite.begin (), finite.end ());
  return finite;
}

nlohmann::json
distanceStatistics (const Eigen::VectorXd& values)
{
  const std::vector<double> finite = sortedFinite (values);
  if (finite.empty ())
    return {{"count", 0}};
  double sum = 0.0, squares = 0.0;
  for (double v : finite) {
    sum += v;
    squares += v * v;
  }
  const double n = static_cast<double> (finite.size ());
  return {{"count", finite.size ()},
          {"mean", sum / n},
          {"median", finite[finite.size () / 2]},
          {"rms", std::sqrt (squares / n)},
          {"max", finite.back ()}};
}

} // namespace morphreg

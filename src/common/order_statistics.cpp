// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/common/order_statistics.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace morphreg
{
namespace
{
void
requireValues (const std::vector<double>& values, const char* what)
{
  if (values.empty ())
    throw InvalidInputError (std::string (what) + ": no values");
}

size_t
keptCount (size_t size, double fraction)
{
  return std::max<size_t> (1, std::min (size, static_cast<size_t> (fraction * static_cast<double> (size))));
}

/** The upper median of \a values (not empty, reordered). A few values are ranked by counting, without branches:
 *  twice as fast as std::nth_element at 24 values, where a resampler's ray takes several medians. */
double
medianOf (std::vector<double>& values)
{
  constexpr std::size_t kRankedAtMost = 64;
  const std::size_t n = values.size (), middle = n / 2;
  if (n <= kRankedAtMost)
    for (std::size_t i = 0; i < n; ++i) {
      std::size_t rank = 0; // ties are ranked by position: exactly one value has rank n / 2
      for (std::size_t j = 0; j < i; ++j)
        rank += values[j] <= values[i];
      for (std::size_t j = i + 1; j < n; ++j)
        rank += values[j] < values[i];
      if (rank == middle)
        return values[i];
    }
  std::nth_element (values.begin (), values.begin () + static_cast<long> (middle), values.end ());
  return values[middle];
}
} // namespace

double
median (std::vector<double> values)
{
  requireValues (values, "median");
  return medianOf (values);
}

double
median (const Eigen::Ref<const Eigen::VectorXd>& values)
{
  thread_local std::vector<double> copy;
  copy.assign (values.data (), values.data () + values.size ());
  requireValues (copy, "median");
  return medianOf (copy);
}

double
percentile (std::vector<double> values, double fraction)
{
  requireValues (values, "percentile");
  if (!(fraction >= 0.0 && fraction <= 1.0))
    throw InvalidInputError ("percentile: the fraction must lie in [0, 1], got " + std::to_string (fraction));
  std::sort (values.begin (), values.end ());
  const double position = fraction * static_cast<double> (values.size () - 1);
  const auto below = static_cast<size_t> (std::floor (position));
  const size_t above = std::min (below + 1, values.size () - 1);
  return values[below] + (position - static_cast<double> (below)) * (values[above] - values[below]);
}

double
trimmedLimit (std::vector<double> values, double fraction)
{
  requireValues (values, "trimmedLimit");
  const size_t keep = keptCount (values.size (), fraction);
  std::nth_element (values.begin (), values.begin () + static_cast<long> (keep - 1), values.end ());
  return values[keep - 1];
}

double
trimmedMean (const std::vector<double>& values, double fraction)
{
  const double limit = trimmedLimit (values, fraction);
  double sum = 0.0, count = 0.0;
  for (double v : values)
    if (v <= limit) {
      sum += v;
      count += 1.0;
    }
  return sum / count;
}

Eigen::Vector3d
coordinateMedian (const Eigen::Matrix3Xd& points)
{
  Eigen::Vector3d centre;
  for (int d = 0; d < 3; ++d) {
    const Eigen::RowVectorXd row = points.row (d);
    centre[d] = median (std::vector<double> (row.data (), row.data () + row.size ()));
  }
  return centre;
}

Eigen::Matrix3Xd
pointsNearMedian (const Eigen::Matrix3Xd& points, double fraction, Eigen::Index minimum)
{
  const Eigen::Vector3d centre = coordinateMedian (points);
  std::vector<std::pair<double, Eigen::Index>> by_distance;
  by_distance.reserve (static_cast<size_t> (points.cols ()));
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    by_distance.emplace_back ((points.col (i) - centre).squaredNorm (), i);
  const auto keep = std::min (by_distance.size (),
                              std::max (static_cast<size_t> (minimum), keptCount (by_distance.size (), fraction)));
  std::nth_element (by_distance.begin (), by_distance.begin () + static_cast<long> (keep - 1), by_distance.end ());
  Eigen::Matrix3Xd kept (3, static_cast<Eigen::Index> (keep));
  for (size_t k = 0; k < keep; ++k)
    kept.col (static_cast<Eigen::Index> (k)) = points.col (by_distance[k].second);
  return kept;
}
} // namespace morphreg

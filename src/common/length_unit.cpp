#include <morphreg/common/error.h>
#include <morphreg/common/length_unit.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

namespace morphreg
{
namespace
{
constexpr LengthUnit kUnits[] = {LengthUnit::millimetre, LengthUnit::centimetre, LengthUnit::metre, LengthUnit::inch};

/** RMS distance from the centroid of the 90 % of \a points nearest to their coordinate-wise median. */
double
robustRadius (const Eigen::Matrix3Xd& points)
{
  Eigen::Vector3d median;
  for (int d = 0; d < 3; ++d) {
    std::vector<double> row (static_cast<size_t> (points.cols ()));
    for (Eigen::Index i = 0; i < points.cols (); ++i)
      row[static_cast<size_t> (i)] = points (d, i);
    std::nth_element (row.begin (), row.begin () + static_cast<long> (row.size () / 2), row.end ());
    median[d] = row[row.size () / 2];
  }
  std::vector<std::pair<double, Eigen::Index>> by_distance;
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    by_distance.emplace_back ((points.col (i) - median).squaredNorm (), i);
  const auto keep = std::max<size_t> (4, static_cast<size_t> (0.9 * static_cast<double> (by_distance.size ())));
  std::nth_element (by_distance.begin (), by_distance.begin () + static_cast<long> (keep - 1), by_distance.end ());
  Eigen::Matrix3Xd kept (3, static_cast<Eigen::Index> (keep));
  for (size_t k = 0; k < keep; ++k)
    kept.col (static_cast<Eigen::Index> (k)) = points.col (by_distance[k].second);
  const Eigen::Vector3d centroid = kept.rowwise ().mean ();
  return std::sqrt ((kept.colwise () - centroid).colwise ().squaredNorm ().mean ());
}
} // namespace

double
millimetresPer (LengthUnit unit)
{
  switch (unit) {
  case LengthUnit::centimetre:
    return 10.0;
  case LengthUnit::metre:
    return 1000.0;
  case LengthUnit::inch:
    return 25.4;
  case LengthUnit::millimetre:
    break;
  }
  return 1.0;
}

std::string
toString (LengthUnit unit)
{
  switch (unit) {
  case LengthUnit::centimetre:
    return "cm";
  case LengthUnit::metre:
    return "m";
  case LengthUnit::inch:
    return "in";
  case LengthUnit::millimetre:
    break;
  }
  return "mm";
}

LengthUnit
parseLengthUnit (const std::string& name)
{
  for (LengthUnit unit : kUnits)
    if (toString (unit) == name)
      return unit;
  throw InvalidInputError ("unknown length unit '" + name + "': choose mm, cm, m or in");
}

LengthUnitGuess
guessLengthUnit (const Eigen::Matrix3Xd& points, double model_radius_mm)
{
  if (points.cols () < 4 || !points.allFinite ())
    throw InvalidInputError ("guessLengthUnit: need at least 4 finite points, got " + std::to_string (points.cols ()) +
                             (points.allFinite () ? "" : " with non-finite coordinates"));
  if (!(model_radius_mm > 0.0) || !std::isfinite (model_radius_mm))
    throw InvalidInputError ("guessLengthUnit: the model radius must be positive and finite");
  const double radius = robustRadius (points);
  LengthUnitGuess guess;
  guess.size_ratio = radius / model_radius_mm;
  double best = std::numeric_limits<double>::infinity ();
  for (LengthUnit unit : kUnits) {
    const double distance = std::abs (std::log10 (guess.size_ratio * millimetresPer (unit))) +
                            (unit == LengthUnit::inch ? 0.15 : 0.0);
    if (distance < best) {
      best = distance;
      guess.unit = unit;
    }
  }
  const double relative = guess.size_ratio * millimetresPer (guess.unit);
  std::ostringstream reason;
  reason.precision (3);
  reason << "the scan's RMS radius is " << radius << " against the model's " << model_radius_mm << " mm: ";
  if (!(relative >= 0.3 && relative <= 10.0)) {
    guess.unit = LengthUnit::millimetre;
    reason << "it is not head-sized in any unit, so it is taken as mm";
  }
  else
    reason << "in " << toString (guess.unit) << " (x" << millimetresPer (guess.unit) << ") it is " << relative
           << " times the model";
  guess.reason = reason.str ();
  return guess;
}

} // namespace morphreg

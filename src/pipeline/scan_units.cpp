// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/cloud_matrix.h>
#include <morphreg/common/error.h>
#include <morphreg/pipeline/scan_units.h>

#include <cmath>
#include <iomanip>
#include <sstream>

namespace morphreg
{
namespace
{
/** Throws when the scan's size, against the model's, is beyond a head's in every unit by orders of magnitude (a
 *  kilometre-sized or micrometre-sized "head"): the file is corrupt or not a scan. */
void
requireHeadScale (const LengthUnitGuess& unit, const std::string& scan_name)
{
  constexpr double kLargest = 1e4, kSmallest = 1e-5; // a metre scan of a head is about 1e-3 of the model's size
  if (unit.size_ratio <= kLargest && unit.size_ratio >= kSmallest)
    return;
  std::ostringstream message;
  message << std::setprecision (3) << scan_name << ": the scan is " << unit.size_ratio
          << " times the model's size, which is no head in any unit (mm, cm, m, in); is the file corrupt? ("
          << unit.reason << ")";
  throw InvalidInputError (message.str ());
}

} // namespace

LengthUnitGuess
scanUnit (const pcl::PointCloud<pcl::PointNormal>& scan, const std::string& units, const MorphableModel& model,
          const std::string& scan_name, bool one_view)
{
  LengthUnitGuess unit;
  if (units == "auto") {
    unit = guessLengthUnit (pointsOf (scan), modelRadius (model), one_view || scan.isOrganized ());
    requireHeadScale (unit, scan_name);
  }
  else {
    unit.unit = parseLengthUnit (units);
    unit.scale_to_mm = millimetresPer (unit.unit);
    unit.reason = "given: " + units;
  }
  return unit;
}

LengthUnitGuess
convertScanToMillimetres (pcl::PointCloud<pcl::PointNormal>& scan, const std::string& units,
                          const MorphableModel& model, const std::string& scan_name, bool one_view)
{
  const LengthUnitGuess unit = scanUnit (scan, units, model, scan_name, one_view);
  const auto to_mm = static_cast<float> (unit.scale_to_mm);
  if (to_mm != 1.0f)
    for (auto& point : scan)
      point.getVector3fMap () *= to_mm;
  return unit;
}

LengthUnitGuess
scanInputUnit (const ScanInput& scan, const std::string& units, const MorphableModel& model)
{
  if (!scan.cloud)
    throw InvalidInputError (scan.name + ": no points (a null cloud)");
  return scanUnit (*scan.cloud, scan.unit ? toString (*scan.unit) : units, model, scan.name,
                   scan.viewpoint.has_value ());
}

ScanInput
scaledScan (const ScanInput& scan, double factor)
{
  ScanInput scaled = scan;
  scaled.cloud = pcl::make_shared<pcl::PointCloud<pcl::PointNormal>> (*scan.cloud);
  const auto to_mm = static_cast<float> (factor);
  if (to_mm != 1.0f)
    for (auto& point : *scaled.cloud)
      point.getVector3fMap () *= to_mm;
  if (scaled.viewpoint)
    *scaled.viewpoint *= factor;
  return scaled;
}

std::string
unitConversionMessage (const LengthUnitGuess& unit)
{
  if (unit.unit == LengthUnit::millimetre)
    return "";
  return "units: the scan's unit is " + toString (unit.unit) + " (" + unit.reason + "); rescaled to mm";
}

} // namespace morphreg

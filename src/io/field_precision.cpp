// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/field_precision.h>

#include <pcl/PCLPointField.h>
#include <pcl/common/io.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <vector>

namespace morphreg
{
namespace
{
bool
hasDoubleField (const pcl::PCLPointCloud2& cloud)
{
  for (const pcl::PCLPointField& field : cloud.fields)
    if (field.datatype == pcl::PCLPointField::FLOAT64)
      return true;
  return false;
}

/** The fields with each FLOAT64 turned into FLOAT32 and the offsets packed again; returns the new point step. */
std::uint32_t
narrowedLayout (const std::vector<pcl::PCLPointField>& fields, std::vector<pcl::PCLPointField>& narrowed)
{
  narrowed = fields;
  std::uint32_t offset = 0;
  for (pcl::PCLPointField& field : narrowed) {
    if (field.datatype == pcl::PCLPointField::FLOAT64)
      field.datatype = pcl::PCLPointField::FLOAT32;
    field.offset = offset;
    offset +=
        static_cast<std::uint32_t> (pcl::getFieldSize (field.datatype)) * std::max<std::uint32_t> (field.count, 1);
  }
  return offset;
}

float
narrowValue (double value, const pcl::PCLPointField& field, std::size_t point, const std::string& path)
{
  if (std::isfinite (value) && std::abs (value) > static_cast<double> (std::numeric_limits<float>::max ()))
    throw FormatError (path + ": property '" + field.name + "' of point " + std::to_string (point) + " is " +
                       std::to_string (value) + ", beyond the range of a float (3.4e38)");
  return static_cast<float> (value);
}

void
copyField (const std::uint8_t* from, const pcl::PCLPointField& field, std::uint8_t* to,
           const pcl::PCLPointField& target, std::size_t point, const std::string& path)
{
  const std::uint32_t count = std::max<std::uint32_t> (field.count, 1);
  if (field.datatype != pcl::PCLPointField::FLOAT64) {
    std::memcpy (to + target.offset, from + field.offset, pcl::getFieldSize (field.datatype) * count);
    return;
  }
  for (std::uint32_t k = 0; k < count; ++k) {
    double value = 0.0;
    std::memcpy (&value, from + field.offset + k * sizeof (double), sizeof (double));
    const float narrowed = narrowValue (value, field, point, path);
    std::memcpy (to + target.offset + k * sizeof (float), &narrowed, sizeof (float));
  }
}
} // namespace

void
narrowDoubleFields (pcl::PCLPointCloud2& cloud, const std::string& path)
{
  if (!hasDoubleField (cloud))
    return;
  std::vector<pcl::PCLPointField> narrowed;
  const std::uint32_t point_step = narrowedLayout (cloud.fields, narrowed);
  const std::size_t points = static_cast<std::size_t> (cloud.width) * cloud.height;
  std::vector<std::uint8_t> data (points * point_step);
  for (std::size_t p = 0; p < points; ++p) {
    const std::uint8_t* from = cloud.data.data () + p * cloud.point_step;
    for (std::size_t f = 0; f < narrowed.size (); ++f)
      copyField (from, cloud.fields[f], data.data () + p * point_step, narrowed[f], p, path);
  }
  cloud.fields = std::move (narrowed);
  cloud.point_step = point_step;
  cloud.row_step = point_step * cloud.width;
  cloud.data = std::move (data);
}

} // namespace morphreg

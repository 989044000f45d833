// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/cloud_matrix.h>
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/depth_image_io.h>
#include <morphreg/pipeline/scan_input.h>
#include <morphreg/registration/scan_checks.h>

#include <pcl/common/io.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace morphreg
{
namespace
{
/** \a scan without its missing points (PCL marks them NaN). An infinite coordinate is no such mark but a broken
 *  file: those points stay for requireRegistrableScan to reject. */
void
dropMissingPoints (pcl::PointCloud<pcl::PointNormal>& scan)
{
  const auto missing = [] (const pcl::PointNormal& p) {
    return std::isnan (p.x) || std::isnan (p.y) || std::isnan (p.z);
  };
  scan.erase (std::remove_if (scan.begin (), scan.end (), missing), scan.end ());
}
} // namespace

ScanInput
makeScanInput (const pcl::PointCloud<pcl::PointNormal>& cloud, const std::string& name)
{
  ScanInput scan{pcl::make_shared<pcl::PointCloud<pcl::PointNormal>> (cloud), std::nullopt, name, std::nullopt};
  if (cloud.isOrganized ())
    scan.viewpoint = cloud.sensor_origin_.head<3> ().cast<double> ();
  dropMissingPoints (*scan.cloud);
  if (scan.cloud->empty ())
    throw FormatError (name + ": the scan has no valid (finite) points");
  requireRegistrableScan (pointsOf (*scan.cloud), name);
  requireUnitNormals (normalsOf (*scan.cloud), name);
  scan.cloud->is_dense = true;
  return scan;
}

ScanInput
readScanFile (const std::string& path)
{
  return makeScanInput (*loadCloud<pcl::PointNormal> (path), path);
}

ScanInput
readDepthImageScan (const std::string& depth_png, const std::string& intrinsics_json)
{
  const DepthImage image = loadDepthPng (depth_png);
  const DepthIntrinsics camera = loadDepthIntrinsics (intrinsics_json);
  if (camera.width != image.width || camera.height != image.height)
    throw InvalidInputError (depth_png + ": the depth image is " + std::to_string (image.width) + " x " +
                             std::to_string (image.height) + " pixels, the camera of " + intrinsics_json + " " +
                             std::to_string (camera.width) + " x " + std::to_string (camera.height));
  pcl::PointCloud<pcl::PointNormal> cloud;
  pcl::copyPointCloud (*depthImageToCloud (image.depth, camera), cloud);
  for (auto& point : cloud) // a depth image has no normals: estimated in the fit
    point.normal_x = point.normal_y = point.normal_z = std::numeric_limits<float>::quiet_NaN ();
  ScanInput scan = makeScanInput (cloud, depth_png);
  scan.unit = LengthUnit::millimetre;
  return scan;
}

ScanInput
readScanOrDepthImage (const std::string& path, const std::string& intrinsics, const std::string& colours,
                      const std::string& units)
{
  if (intrinsics.empty ())
    return readScanFile (path);
  if (colours == "scan")
    throw InvalidInputError ("the depth image " + path + " has no colours to give the fitted mesh (colours scan)");
  if (units != "auto" && units != "mm")
    throw InvalidInputError ("the depth image " + path + " holds mm, not " + units + " (units " + units + ")");
  return readDepthImageScan (path, intrinsics);
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file scan_input.h
 *  \brief A scan as the registration pipeline takes it (scan_registration.h): points with normals and nothing
 *  missing, checked to be registrable, read from a file, a depth image or a cloud already in memory.
 */
#include <morphreg/common/length_unit.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <optional>
#include <string>

namespace morphreg
{
/** \brief A scan to register: its points (any unit, see ScanRegistration) and what the source tells about them. */
struct ScanInput
{
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud; ///< finite points; NaN normals where the source has none
  /** For one sensor's view (an organised cloud, a depth image): where the sensor stood, in the cloud's frame and
   *  unit; the fit turns estimated normals towards it and expects to see one side of the head. */
  std::optional<Eigen::Vector3d> viewpoint;
  std::string name;               ///< what messages and reports call it (its file)
  std::optional<LengthUnit> unit; ///< the unit the source fixes (a depth image holds mm); else the settings' units
};

/** \brief \a cloud as a scan: its missing (NaN) points dropped, a viewpoint if it is organised (its sensor origin),
 *  checked to be registrable (at least 100 finite points spread in 3D, normals of unit length or none). Throws
 *  FormatError or InvalidInputError naming \a name otherwise.
 *  \param[in] cloud the points, copied
 *  \param[in] name the scan's name for messages
 *  \return the scan
 */
ScanInput
makeScanInput (const pcl::PointCloud<pcl::PointNormal>& cloud, const std::string& name);

/** \brief A scan file (.pcd .ply .obj .stl .off .vtk .gltf .glb, see loadCloud) as a scan (makeScanInput).
 *  \param[in] path the file
 *  \return the scan, named \a path
 */
ScanInput
readScanFile (const std::string& path);

/** \brief A depth camera's image (16-bit PNG, mm) as a scan: its points in the camera frame (mm), the camera the
 *  viewpoint. Throws InvalidInputError naming both files when the image and the camera differ in size.
 *  \param[in] depth_png the depth image (see depth_image_io.h)
 *  \param[in] intrinsics_json its camera (width, height, fx, fy, cx, cy)
 *  \return the scan, named \a depth_png, unit mm
 */
ScanInput
readDepthImageScan (const std::string& depth_png, const std::string& intrinsics_json);

/** \brief The scan of a registration: the scan file \a path (readScanFile), or with \a intrinsics a depth image
 *  (readDepthImageScan). A depth image has no colours and holds mm: InvalidInputError naming it when \a colours is
 *  "scan" or \a units neither "auto" nor "mm".
 *  \param[in] path the scan file, or the depth image (16-bit PNG, mm)
 *  \param[in] intrinsics the depth image's camera (JSON), or empty for a scan file
 *  \param[in] colours the fitted mesh's colours asked for ("scan", "residual", "auto")
 *  \param[in] units the scan's unit asked for
 *  \return the scan */
ScanInput
readScanOrDepthImage (const std::string& path, const std::string& intrinsics, const std::string& colours,
                      const std::string& units);

} // namespace morphreg

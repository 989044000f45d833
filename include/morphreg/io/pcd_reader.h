// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file pcd_reader.h
 *  \brief morphreg's own reader of PCL's PCD files (DATA ascii, binary and binary_compressed), used by loadCloud()
 *  instead of pcl::PCDReader, which crashes or allocates without bound on some malformed files.
 *
 *  What a file must satisfy: a header of VERSION, FIELDS (or COLUMNS), SIZE, TYPE, COUNT (optional, 1 each),
 *  WIDTH, HEIGHT, VIEWPOINT (optional, 7 finite numbers), POINTS and DATA lines, each at most once, comments (#)
 *  and blank lines allowed; FIELDS, SIZE, TYPE and COUNT of one length; TYPE and SIZE pairs F 4|8 or I, U 1|2|4|8;
 *  no field named twice (but the padding "_"); fields x, y and z of one 4-byte float each (PCL converts positions
 *  only from those); WIDTH * HEIGHT = POINTS, at least 1 and at most 2^31 - 1, a row (WIDTH points) under 4 GB (PCL's
 *  limits). The data must fit in the file before anything is allocated for it: binary holds POINTS * the point's
 *  bytes; binary_compressed holds the compressed and unpacked sizes (32-bit little endian), then that many LZF bytes
 *  unpacking to exactly POINTS * the point's bytes, field by field; ascii holds one line a point with one number of
 *  its field's type and range per value ("nan" and "inf" for F). Whatever follows the data is ignored.
 */
#include <pcl/PCLPointCloud2.h>

#include <Eigen/Geometry>

#include <string>

namespace morphreg
{
/** \brief What a PCD file holds: its points as PCL's reader gives them, and its acquisition viewpoint. */
struct PcdCloud
{
  /** the fields in header order (padding fields "_" included) packed without gaps, width and height as in the
   *  header, is_dense false if a float value is NaN or infinite */
  pcl::PCLPointCloud2 cloud;
  Eigen::Vector4f origin = Eigen::Vector4f::Zero ();                ///< the VIEWPOINT's translation (w 0)
  Eigen::Quaternionf orientation = Eigen::Quaternionf::Identity (); ///< the VIEWPOINT's rotation
};

/** \brief Reads a PCD file, checking it as it reads (see the file's description). Throws IoError if the file cannot
 *  be read, FormatError naming the file (and the line of a header or ASCII line) and the problem otherwise:
 *  "scan.pcd:3: SIZE value '16' is not a whole number in [1, 8]", "scan.pcd: header claims 2000000000 points (at
 *  least 24 GB) but the file holds 212 bytes after its header".
 *  \param[in] path the PCD file
 *  \return its points and viewpoint
 */
PcdCloud
readPcdFile (const std::string& path);

} // namespace morphreg

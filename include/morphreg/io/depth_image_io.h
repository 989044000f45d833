// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file depth_image_io.h
 *  \brief Depth images as depth cameras save them: a 16-bit greyscale PNG of depths in mm (0 = no depth), and the
 *  camera's intrinsics as JSON ({"width", "height", "fx", "fy", "cx", "cy"}, pixels).
 */
#include <morphreg/common/depth_intrinsics.h>

#include <cstdint>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief A depth image: width x height depths in mm, row by row, 0 where the camera saw nothing. */
struct DepthImage
{
  int width = 0;                    ///< columns
  int height = 0;                   ///< rows
  std::vector<std::uint16_t> depth; ///< mm per pixel, row by row
};

/** \brief Reads a 16-bit greyscale PNG of depths in mm. The header is checked before any pixel is decoded: a PNG
 *  signature, 16-bit greyscale without alpha, at most 16384 pixels a side, and a file large enough for a compressed
 *  image of that size. Throws IoError for a missing file, FormatError naming the file and the problem otherwise.
 *  \param[in] path the PNG file
 *  \return the depths
 */
DepthImage
loadDepthPng (const std::string& path);

/** \brief Writes \a image as a 16-bit greyscale PNG, atomically; IoError naming the file if it cannot be written.
 *  \param[in] path the PNG file
 *  \param[in] image the depths (mm)
 */
void
saveDepthPng (const std::string& path, const DepthImage& image);

/** \brief Reads a depth camera's intrinsics: a JSON object with "width" and "height" (whole numbers) and "fx", "fy",
 *  "cx", "cy" (pixels). Throws FormatError naming the file and the field that is missing or invalid.
 *  \param[in] path the JSON file
 *  \return the intrinsics, validated (requireValidIntrinsics)
 */
DepthIntrinsics
loadDepthIntrinsics (const std::string& path);

} // namespace morphreg

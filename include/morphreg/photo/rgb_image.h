// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file rgb_image.h
 *  \brief An 8-bit RGB photo in memory, read from PNG or JPEG (checked and decoded by loadPhotoFile(), photo_file.h)
 *  and written to PNG with VTK.
 */
#include <morphreg/common/colour_map.h>

#include <string>
#include <vector>

namespace morphreg
{
/** \brief An 8-bit RGB image, rows top to bottom (pixel (0, 0) is the top-left corner, as in photo annotations). */
struct RgbImage
{
  int width = 0;                   ///< pixels per row
  int height = 0;                  ///< rows
  std::vector<unsigned char> data; ///< 3 bytes per pixel, row by row

  /** \brief The colour of column \a x, row \a y (no range check).
   *  \param[in] x the column, 0 at the left
   *  \param[in] y the row, 0 at the top
   *  \return the pixel's colour
   */
  Rgb8
  pixel (int x, int y) const
  {
    const auto i = 3 * (static_cast<size_t> (y) * static_cast<size_t> (width) + static_cast<size_t> (x));
    return {data[i], data[i + 1], data[i + 2]};
  }
};

/** \brief Reads a PNG or JPEG photo (grey and RGBA images become RGB) with loadPhotoFile(): IoError if the file is
 *  missing or not a regular file, FormatError naming it if it is not a complete, valid PNG or JPEG of a plausible
 *  size, InvalidInputError if it would not fit in memory.
 *  \param[in] path the image file
 *  \return the image as RGB
 */
RgbImage
loadRgbImage (const std::string& path);

/** \brief Writes \a image as PNG. Throws InvalidInputError for an empty or inconsistent image, IoError if the file
 *  cannot be written.
 *  \param[in] path the PNG file
 *  \param[in] image the image
 */

void
saveRgbImage (const std::string& path, const RgbImage& image);
} // namespace morphreg

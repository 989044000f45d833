// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file rgb_image.h
 *  \brief An 8-bit RGB image in memory (a photo, a scan's texture); io/rgb_image_io.h reads and writes them.
 */
#include <morphreg/common/colour_map.h>

#include <cstddef>
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

} // namespace morphreg

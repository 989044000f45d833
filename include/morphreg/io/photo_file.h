// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file photo_file.h
 *  \brief Photos (PNG, JPEG) read safely: the header checked from the file's bytes (signature, size 1 to
 *  kMaxPhotoSide a side, a size the file can hold, memory for the pixels) before a decoder allocates anything, then
 *  decoded whole, so that a corrupt or truncated photo is a FormatError naming it before any work that needs it.
 */
#include <string>
#include <vector>

namespace morphreg
{
/** \brief The longest side of a photo accepted, in pixels. */
constexpr int kMaxPhotoSide = 16384;

/** \brief An 8-bit RGB photo as decoded: rows top to bottom, 3 bytes a pixel (grey, palette and alpha images are
 *  converted, 16-bit samples reduced to 8 bits). */
struct PhotoPixels
{
  int width = 0;
  int height = 0;
  std::vector<unsigned char> rgb;
};

/** \brief Reads the PNG or JPEG photo \a path (recognised by its content). Throws IoError if it is missing or not a
 *  regular file; FormatError naming it if it is neither PNG nor JPEG, declares a size outside 1 to kMaxPhotoSide or
 *  more pixels than the file can hold, or is corrupt or truncated (a JPEG decoder warning counts as corruption);
 *  InvalidInputError if its pixels would not fit in memory.
 *  \param[in] path the photo
 *  \return its pixels
 */
PhotoPixels
loadPhotoFile (const std::string& path);

} // namespace morphreg

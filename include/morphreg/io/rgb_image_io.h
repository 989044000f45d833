// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file rgb_image_io.h
 *  \brief RGB images (a photo, a scan's texture) read from PNG or JPEG (libpng, libjpeg) and written to PNG.
 */
#include <morphreg/common/rgb_image.h>

#include <string>
#include <vector>

namespace morphreg
{
/** \brief Reads a PNG or JPEG photo (grey, palette, 16-bit and RGBA images become 8-bit RGB) with loadPhotoFile()
 *  (photo_file.h): IoError if the file is missing or not a regular file, FormatError naming it if it is not a
 *  complete, valid PNG or JPEG of a plausible size, InvalidInputError if it would not fit in memory.
 *  \param[in] path the image file
 *  \return the image as RGB
 */
RgbImage
loadRgbImage (const std::string& path);

/** \brief Decodes a PNG or JPEG image held in memory (a texture embedded in a glTF file), recognised by its first
 *  bytes. FormatError naming \a name if it is neither, cannot be decoded, or declares more than \a max_pixels pixels
 *  (checked before anything is decoded).
 *  \param[in] bytes the encoded image
 *  \param[in] name what the image is (e.g. "scan.glb: image 0"), for the messages
 *  \param[in] max_pixels the largest width x height accepted
 *  \return the image as RGB
 */
RgbImage
decodeRgbImage (const std::vector<unsigned char>& bytes, const std::string& name, double max_pixels);

/** \brief Writes \a image as PNG. Throws InvalidInputError for an empty or inconsistent image, IoError if the file
 *  cannot be written.
 *  \param[in] path the PNG file
 *  \param[in] image the image
 */

void
saveRgbImage (const std::string& path, const RgbImage& image);
} // namespace morphreg

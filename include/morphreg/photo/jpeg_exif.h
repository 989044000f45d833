// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file jpeg_exif.h
 *  \brief The one EXIF fact a photo fit uses: the lens's focal length in 35 mm film terms (tag 0xA405), which with
 *  the image size gives the focal length in pixels of a camera that was not calibrated.
 */
#include <optional>
#include <string>

namespace morphreg
{
/** \brief The 35 mm equivalent focal length (mm) of the JPEG \a path from its EXIF block, if it has one. A file
 *  that is no JPEG, has no EXIF block, a malformed one or no such tag gives none (the fit then searches the focal
 *  length within a range and says so); IoError if the file cannot be read.
 *  \param[in] path the photo
 *  \return the focal length in 35 mm terms, or none
 */
std::optional<double>
jpegFocalLength35mm (const std::string& path);

/** \brief The same from the bytes of a JPEG file.
 *  \param[in] bytes the file's content
 *  \return the focal length in 35 mm terms, or none
 */
std::optional<double>
jpegFocalLength35mmFromBytes (const std::string& bytes);

/** \brief The focal length in pixels of a camera whose 35 mm equivalent focal length is \a millimetres, for an
 *  image of \a width x \a height pixels: the 35 mm frame's diagonal (43.27 mm) spans the image's diagonal.
 *  \param[in] millimetres the 35 mm equivalent focal length
 *  \param[in] width the image width (px)
 *  \param[in] height the image height (px)
 *  \return the focal length in pixels
 */
double
focalPixelsFrom35mm (double millimetres, int width, int height);
} // namespace morphreg

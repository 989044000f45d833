// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file photo_camera_io.h
 *  \brief Camera files of `fit-photos --camera` (layout in README.md, "Cameras"): one camera as {"K": 3 x 3,
 *  "R": 3 x 3, "t": [3]} or {"P": 3 x 4} (pixels from the top-left corner, x ~ K [R | t] X), optionally with
 *  "width" and "height"; or several as {"cameras": {"name": {..., "image": "file.jpg"}, ...}}, the one for a photo
 *  found by its "image" (the photo's file name).
 */
#include <morphreg/photo/photo_camera.h>

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace morphreg
{
/** \brief Reads the camera of the photo \a image (\a width x \a height pixels) from \a path. Throws IoError for a
 *  missing file, FormatError naming the file and member for a malformed camera, a camera list without one for
 *  \a image, or an image size that differs from the photo's; InvalidInputError for values that are no camera
 *  (PhotoCamera's checks).
 *  \param[in] path the camera JSON file
 *  \param[in] image the photo's path (its file name selects a camera of a list)
 *  \param[in] width the photo's width in pixels
 *  \param[in] height the photo's height in pixels
 *  \return the camera
 */
PhotoCamera
loadPhotoCamera (const std::string& path, const std::string& image, int width, int height);

/** \brief The camera as {"projection": "perspective" | "orthographic", "K", "R", "t"} (the file layout above).
 *  \param[in] camera the camera
 *  \return the JSON object
 */
nlohmann::json
photoCameraJson (const PhotoCamera& camera);
} // namespace morphreg

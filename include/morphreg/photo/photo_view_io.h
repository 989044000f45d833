// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file photo_view_io.h
 *  \brief JSON files of the annotated photos of the two-view fit (layouts in README.md, "Photo annotations").
 *
 *  Profile: {"view": "profile", "image": {"width": W, "height": H}, "nose_tip": [x, y],
 *            "silhouette": [[x, y], ...]}
 *  Frontal: {"view": "frontal", "image": {"width": W, "height": H}, "units": "px",
 *            "landmarks": [{"id": "nose_tip", "position": [x, y]}, ...]} (the 2D landmark file layout plus "image")
 *  Pixels: x right, y down, origin at the image's top-left corner.
 *
 *  Readers throw IoError for a missing file, FormatError naming the file and element for malformed content, and
 *  InvalidInputError naming the file for invalid values (image size, non-finite or missing nose tip, unknown ids).
 */
#include <morphreg/photo/frontal_view.h>
#include <morphreg/photo/profile_view.h>

#include <string>

namespace morphreg
{
/** \brief Reads a profile annotation (the layout above).
 *  \param[in] path the JSON file
 *  \return the silhouette and nose tip
 */
ProfileView
loadProfileView (const std::string& path);

/** \brief Reads a frontal annotation (the layout above).
 *  \param[in] path the JSON file
 *  \return the landmarks
 */
FrontalView
loadFrontalView (const std::string& path);

/** \brief Writes \a view as a profile JSON file; IoError if it cannot be written.
 *  \param[in] path the JSON file
 *  \param[in] view the profile annotation
 */
void
saveProfileView (const std::string& path, const ProfileView& view);

/** \brief Writes \a view as a frontal JSON file; IoError if it cannot be written.
 *  \param[in] path the JSON file
 *  \param[in] view the frontal annotation
 */

void
saveFrontalView (const std::string& path, const FrontalView& view);
} // namespace morphreg

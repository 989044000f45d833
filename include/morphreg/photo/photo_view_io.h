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
 *  Outline: {"outline": [[x, y], ...], "hairline": [x, y]} (the hairline optional: where the hair begins).
 *
 *  Readers throw IoError for a missing file, FormatError naming the file and element for malformed content, and
 *  InvalidInputError naming the file for invalid values (image size, non-finite or missing nose tip, unknown ids).
 */
#include <morphreg/photo/frontal_view.h>
#include <morphreg/photo/photo_view.h>
#include <morphreg/photo/profile_view.h>
#include <morphreg/io/rgb_image_io.h>

#include <optional>
#include <string>
#include <vector>

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

/** \brief A traced outline and the optional mark where the hair begins on it (pixels). */
struct OutlineAnnotation
{
  std::vector<Eigen::Vector2d> points;     ///< the outline, in order along it
  std::optional<Eigen::Vector2d> hairline; ///< where the hair begins, if marked
};

/** \brief Reads an outline file (the layout above).
 *  \param[in] path the JSON file
 *  \return the outline and hairline
 */
OutlineAnnotation
loadOutline (const std::string& path);

/** \brief Writes an outline file (the layout above); IoError if it cannot be written.
 *  \param[in] path the JSON file
 *  \param[in] outline the outline and hairline
 */
void
saveOutline (const std::string& path, const OutlineAnnotation& outline);

/** \brief The files of one photo of `fit-photos --view`: the image, and optionally its landmarks (.json, .csv or
 *  .pts, ids of docs/landmarks.md or iBUG-68), camera (photo_camera_io.h) and outline (the layout above). */
struct PhotoViewFiles
{
  std::string image;     ///< PNG or JPEG
  std::string landmarks; ///< landmark file, or empty
  std::string camera;    ///< camera file, or empty (the camera is estimated)
  std::string outline;   ///< outline file, or empty
};

/** \brief A photo read for a fit: its view and its pixels (for the texture). */
struct LoadedPhotoView
{
  PhotoView view; ///< the landmarks, outline and camera
  RgbImage image; ///< the photo's pixels
};

/** \brief Reads a photo and its annotations: the image's size, a JPEG's EXIF focal length, the landmarks, camera and
 *  outline. Throws as the readers do, InvalidInputError naming the landmark file for a landmark farther than a tenth
 *  of the image outside it (the landmarks of another photo), and for a photo with neither landmarks nor outline.
 *  \param[in] files the photo's files
 *  \return the view and the image
 */
LoadedPhotoView
loadPhotoView (const PhotoViewFiles& files);
} // namespace morphreg

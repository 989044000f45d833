// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file profile_view.h
 *  \brief A profile (side) photo annotated for the two-view fit: the head's silhouette as a polyline and the nose
 *  tip, in pixels.
 */
#include <morphreg/photo/photo_normalisation.h>

#include <Eigen/Core>

#include <string>
#include <vector>

namespace morphreg
{
/** \brief The silhouette of a head in a profile photo. The face must look to the right of the image (+x): a photo
 *  of the face looking left is mirrored before annotation. The polyline follows the whole mid-sagittal profile
 *  (front of the neck, face, crown, back of the neck, in either direction), or the part of it the photo shows:
 *  profile-line vertices beyond its ends get no correspondence, and the fit does not take its scale from the
 *  polyline's height.

 */
class ProfileView
{
public:
  /** \brief Throws InvalidInputError naming \a source for a non-positive image size, a non-finite nose tip or
   *  silhouette point, a silhouette of fewer than kMinimumSilhouettePoints points or of coincident ones, or a face
   *  looking left (the nose tip left of the silhouette's mean x).
   *  \param[in] width the image width in pixels
   *  \param[in] height the image height in pixels
   *  \param[in] silhouette the traced outline in pixels, in order along it
   *  \param[in] nose_tip the marked nose tip in pixels
   *  \param[in] source the annotation's file or origin, for messages
   */
  ProfileView (int width, int height, std::vector<Eigen::Vector2d> silhouette, const Eigen::Vector2d& nose_tip,
               const std::string& source = "ProfileView");

  /** \brief The photo's normalisation.
   *  \return the map from pixels to the normalised frame
   */
  const PhotoNormalisation&
  normalisation () const
  {
    return normalisation_;
  }

  /** \brief The silhouette polyline in pixels.
   *  \return the points in order
   */
  const std::vector<Eigen::Vector2d>&
  silhouette () const
  {
    return silhouette_;
  }

  /** \brief The silhouette in the normalised frame (2 x K): u towards the face (the model's +Z), v up (+Y).
   *  \return the points in order, one per column
   */

  Eigen::Matrix2Xd
  normalisedSilhouette () const;

  /** \brief The fewest silhouette points a profile needs (a traced outline has many more). */
  static constexpr std::size_t kMinimumSilhouettePoints = 10;

private:
  /** Throws unless the nose tip lies right of the silhouette's mean x (the face looks to +x). */
  void
  requireFacingRight (const Eigen::Vector2d& nose_tip, const std::string& source) const;

  PhotoNormalisation normalisation_;
  std::vector<Eigen::Vector2d> silhouette_;
};
} // namespace morphreg

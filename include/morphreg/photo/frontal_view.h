// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file frontal_view.h
 *  \brief A frontal photo annotated for the two-view fit: named landmarks (ids of docs/landmarks.md) in pixels.
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/photo/photo_normalisation.h>

#include <map>
#include <string>

namespace morphreg
{
/** \brief Named landmarks of a frontal photo, nose_tip (or iBUG-68's point 30, ibug68_30) among them (it centres the
 *  normalised frame). The subject's right appears on the left of the image, as in any photo of a face.
 */
class FrontalView
{
public:
  /** \brief Throws InvalidInputError naming \a source for a non-positive image size, a landmark id that is not in
   *  docs/landmarks.md, a non-finite pixel or a missing nose tip.
   *  \param[in] width the image width in pixels
   *  \param[in] height the image height in pixels
   *  \param[in] landmarks the marked landmarks in pixels
   *  \param[in] source the annotation's file or origin, for messages
   */
  FrontalView (int width, int height, LandmarkPixels landmarks, const std::string& source = "FrontalView");

  /** \brief The photo's normalisation.
   *  \return the map from pixels to the normalised frame
   */
  const PhotoNormalisation&
  normalisation () const
  {
    return normalisation_;
  }

  /** \brief The landmarks in pixels.
   *  \return id -> pixel
   */
  const LandmarkPixels&
  landmarks () const
  {
    return landmarks_;
  }

  /** \brief The landmarks in the normalised frame: u to the image's right (the model's +X), v up (+Y).
   *  \return id -> normalised position
   */

  std::map<std::string, Eigen::Vector2d>
  normalisedLandmarks () const;

private:
  /** The nose tip of \a landmarks (nose_tip, else ibug68_30); InvalidInputError naming \a source if both are absent. */
  static Eigen::Vector2d
  noseTip (const LandmarkPixels& landmarks, const std::string& source);

  PhotoNormalisation normalisation_;
  LandmarkPixels landmarks_;
};
} // namespace morphreg

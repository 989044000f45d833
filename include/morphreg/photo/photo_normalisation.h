// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file photo_normalisation.h
 *  \brief The normalised photo frame of docs/method.md ("Fitting to two orthogonal
 *  photographs"): pixels divided by the longer image side, centred on
 *  the nose tip, with the image's y axis flipped so that +Y is up. Both photos of a two-view fit use it, so one
 *  similarity maps the model into both.
 */
#include <Eigen/Core>

#include <string>

namespace morphreg
{
/** \brief Throws InvalidInputError "<what> (x, y) is not finite" if \a pixel has a NaN or infinite coordinate.
 *  \param[in] pixel the pixel to check
 *  \param[in] what what the pixel is, for the message
 */
void
requireFinitePixel (const Eigen::Vector2d& pixel, const std::string& what);

/** \brief Maps the pixels of one photo (x right, y down, origin at the top-left corner) to the normalised frame
 *  (u right, v up, origin at the nose tip, the longer image side has length 1) and back.
 */
class PhotoNormalisation
{
public:
  /** \brief Throws InvalidInputError naming \a source if \a width or \a height is not positive or \a nose_tip is
   *  not finite.
   *  \param[in] width the image width in pixels
   *  \param[in] height the image height in pixels
   *  \param[in] nose_tip the marked nose tip in pixels
   *  \param[in] source the annotation's file or origin, for messages
   */
  PhotoNormalisation (int width, int height, const Eigen::Vector2d& nose_tip, const std::string& source);

  /** \brief (x - nose_x, nose_y - y) / longer side.
   *  \param[in] pixel a position in pixels
   *  \return the position in the normalised frame
   */
  Eigen::Vector2d
  normalise (const Eigen::Vector2d& pixel) const;

  /** \brief The inverse of normalise().
   *  \param[in] normalised a position in the normalised frame
   *  \return the position in pixels
   */
  Eigen::Vector2d
  toPixel (const Eigen::Vector2d& normalised) const;

  /** \brief The image width.
   *  \return pixels
   */
  int
  width () const
  {
    return width_;
  }

  /** \brief The image height.
   *  \return pixels
   */
  int
  height () const
  {
    return height_;
  }

  /** \brief The nose tip in pixels.
   *  \return the origin of the normalised frame, in pixels
   */
  const Eigen::Vector2d&
  noseTip () const
  {
    return nose_tip_;
  }

  /** \brief max(width, height) in pixels: the length of one normalised unit.
   *  \return pixels per normalised unit
   */

  double
  longerSide () const
  {
    return static_cast<double> (width_ > height_ ? width_ : height_);
  }

private:
  int width_;
  int height_;
  Eigen::Vector2d nose_tip_;
};
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/photo/photo_normalisation.h>

namespace morphreg
{
void
requireFinitePixel (const Eigen::Vector2d& pixel, const std::string& what)
{
  if (!pixel.allFinite ())
    throw InvalidInputError (what + " (" + std::to_string (pixel.x ()) + ", " + std::to_string (pixel.y ()) +
                             ") is not finite");
}

PhotoNormalisation::PhotoNormalisation (int width, int height, const Eigen::Vector2d& nose_tip,
                                        const std::string& source)
  : width_ (width), height_ (height), nose_tip_ (nose_tip)
{
  if (width <= 0 || height <= 0)
    throw InvalidInputError (source + ": the image size " + std::to_string (width) + " x " + std::to_string (height) +
                             " px must be positive");
  requireFinitePixel (nose_tip, source + ": the nose tip");
}

Eigen::Vector2d
PhotoNormalisation::normalise (const Eigen::Vector2d& pixel) const
{
  return Eigen::Vector2d (pixel.x () - nose_tip_.x (), nose_tip_.y () - pixel.y ()) / longerSide ();
}

Eigen::Vector2d
PhotoNormalisation::toPixel (const Eigen::Vector2d& normalised) const
{
  return nose_tip_ + longerSide () * Eigen::Vector2d (normalised.x (), -normalised.y ());
}
} // namespace morphreg

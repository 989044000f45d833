// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/common/colour_map.h>
#include <morphreg/common/distance_statistics.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace morphreg
{
namespace
{
/** \brief Viridis sampled at t = 0, 1/9, ..., 1 (its usual ten-colour palette). */
constexpr std::array<std::array<int, 3>, 10> kViridisStops = {{{0x44, 0x01, 0x54},
                                                               {0x48, 0x28, 0x78},
                                                               {0x3e, 0x4a, 0x89},
                                                               {0x31, 0x68, 0x8e},
                                                               {0x26, 0x82, 0x8e},
                                                               {0x1f, 0x9e, 0x89},
                                                               {0x35, 0xb7, 0x79},
                                                               {0x6d, 0xcd, 0x59},
                                                               {0xb4, 0xde, 0x2c},
                                                               {0xfd, 0xe7, 0x25}}};

const Rgb8 kNoValueGrey (150, 150, 150);
} // namespace

Rgb8
viridis (double t)
{
  if (std::isnan (t))
    return kNoValueGrey;
  const double position = std::clamp (t, 0.0, 1.0) * (kViridisStops.size () - 1);
  const std::size_t lower = std::min (static_cast<std::size_t> (position), kViridisStops.size () - 2);
  const double fraction = position - static_cast<double> (lower);
  Rgb8 colour;
  for (int c = 0; c < 3; ++c)
    colour[c] = static_cast<unsigned char> (
        std::lround ((1.0 - fraction) * kViridisStops[lower][c] + fraction * kViridisStops[lower + 1][c]));
  return colour;
}

VertexColours
residualColours (const Eigen::VectorXd& values, double max_value)
{
  if (!(max_value > 0.0) || !std::isfinite (max_value))
    throw InvalidInputError ("residual colours: the scale maximum must be positive and finite, got " +
                             std::to_string (max_value));
  VertexColours colours (3, values.size ());
  for (Eigen::Index i = 0; i < values.size (); ++i) {
    if (values[i] < 0.0 || std::isinf (values[i]))
      throw InvalidInputError ("residual colours: value " + std::to_string (i) + " is " + std::to_string (values[i]) +
                               "; residuals must be non-negative and finite (or NaN)");
    colours.col (i) = viridis (values[i] / max_value);
  }
  return colours;
}

double
residualColourScale (const Eigen::VectorXd& residuals, double requested)
{
  if (requested > 0.0)
    return requested;
  const std::vector<double> finite = sortedFinite (residuals);
  const double percentile = finite.empty () ? 0.0 : finite[(finite.size () * 95) / 100];
  return std::max (percentile, 1e-3);
}

} // namespace morphreg

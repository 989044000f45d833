// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file colour_map.h
 *  \brief The residual colour map: viridis (dark blue-violet = low, yellow = high), perceptually uniform and
 *  readable in greyscale, unlike PCL's LUT_JET, which maps low values to red.
 */
#include <Eigen/Core>

namespace morphreg
{
/** \brief An 8-bit RGB colour. */
using Rgb8 = Eigen::Matrix<unsigned char, 3, 1>;

/** \brief Per-vertex 8-bit RGB colours (3 x N), the layout toPolygonMesh() takes. */
using VertexColours = Eigen::Matrix<unsigned char, 3, Eigen::Dynamic>;

/** \brief The viridis colour of \a t in [0, 1] (clamped; NaN gives neutral grey), piecewise linear between ten
 *  stops of the published map.
 *  \param[in] t the value to colour, 0 the low end and 1 the high end of the scale
 *  \return the colour
 */
Rgb8
viridis (double t);

/** \brief Colours of non-negative \a values on the scale [0, \a max_value] (larger values saturate at the top);
 *  NaN entries (no residual) are grey. Throws InvalidInputError if \a max_value is not positive and finite or a
 *  value is negative or infinite.
 *  \param[in] values one non-negative value (e.g. a residual in mm) per vertex, NaN for none
 *  \param[in] max_value the value that maps to the top of the scale
 *  \return one colour per value
 */
VertexColours

residualColours (const Eigen::VectorXd& values, double max_value);

/** \brief The colour scale of a residual map: \a requested if positive, else the 95th percentile of the residuals
 *  (at least 0.001 mm, so that a perfect fit still has a scale).
 *  \param[in] residuals one residual (mm) per vertex, NaN for none
 *  \param[in] requested the scale asked for, mm; 0: the percentile
 *  \return the scale's maximum, mm
 */
double
residualColourScale (const Eigen::VectorXd& residuals, double requested);

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file order_statistics.h
 *  \brief Medians, percentiles and trimmed means of samples: the robust statistics the estimators and reports use.
 */
#include <Eigen/Core>

#include <vector>

namespace morphreg
{
/** \brief The median of \a values (the upper one of the two middle values for an even count).
 *  \param[in] values the sample (taken by value: it is partially reordered)
 *  \return the median; InvalidInputError if \a values is empty
 */
double
median (std::vector<double> values);

/** \brief The median of \a values without copying them into a vector first (a column, an array's matrix view).
 *  \param[in] values the sample
 *  \return the median; InvalidInputError if \a values is empty
 */
double
median (const Eigen::Ref<const Eigen::VectorXd>& values);

/** \brief The \a fraction quantile of \a values, linearly interpolated between order statistics.
 *  \param[in] values the sample, not empty
 *  \param[in] fraction in [0, 1]: 0 the minimum, 0.5 the median, 1 the maximum
 *  \return the quantile; InvalidInputError for an empty sample or a fraction outside [0, 1]
 */
double
percentile (std::vector<double> values, double fraction);

/** \brief The value below which the \a fraction smallest of \a values lie (at least one value is kept).
 *  \param[in] values the sample, not empty
 *  \param[in] fraction in (0, 1]
 *  \return the largest kept value; InvalidInputError for an empty sample
 */
double
trimmedLimit (std::vector<double> values, double fraction);

/** \brief The mean of the \a fraction smallest of \a values.
 *  \param[in] values the sample, not empty
 *  \param[in] fraction in (0, 1]
 *  \return the trimmed mean; InvalidInputError for an empty sample
 */
double
trimmedMean (const std::vector<double>& values, double fraction);

/** \brief The coordinate-wise median of the columns of \a points.
 *  \param[in] points 3 x N, N >= 1
 *  \return the median of each row
 */
Eigen::Vector3d
coordinateMedian (const Eigen::Matrix3Xd& points);

/** \brief The columns of \a points nearest to their coordinate-wise median: the \a fraction closest, but at least
 *  \a minimum (or all when there are fewer), in no particular order. Trims outliers before moments are taken.
 *  \param[in] points 3 x N, N >= 1
 *  \param[in] fraction share of the points kept, in (0, 1]
 *  \param[in] minimum the least number of points kept
 *  \return the kept columns
 */
Eigen::Matrix3Xd
pointsNearMedian (const Eigen::Matrix3Xd& points, double fraction, Eigen::Index minimum);
} // namespace morphreg

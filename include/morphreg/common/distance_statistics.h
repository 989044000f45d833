// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file distance_statistics.h
 *  \brief Summary statistics of per-vertex distances (mm) for reports, NaN marking a vertex without a value.
 */
#include <Eigen/Core>

#include <nlohmann/json_fwd.hpp>

#include <vector>

namespace morphreg
{
/** \brief The finite entries of \a values (NaN = a vertex without a value), sorted.
 *  \param[in] values per-vertex values, NaN where a vertex has none
 *  \return the finite ones in ascending order
 */
std::vector<double>
sortedFinite (const Eigen::VectorXd& values);

/** \brief Count, mean, median, RMS and maximum of the finite \a values ({"count": 0} alone without any).
 *  \param[in] values per-vertex distances (mm), NaN where a vertex has none
 *  \return the JSON object
 */
nlohmann::json
distanceStatistics (const Eigen::VectorXd& values);
} // namespace morphreg

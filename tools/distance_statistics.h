#pragma once
// Summary statistics of per-vertex distances (mm) for the reports of register and fit-photos.
#include <Eigen/Core>

#include <nlohmann/json.hpp>

#include <vector>

namespace morphreg
{
namespace tools
{
/** The finite entries of \a values (NaN = a vertex without a value), sorted. */
std::vector<double>
sortedFinite (const Eigen::VectorXd& values);

/** Count, mean, median, RMS and maximum (mm) of the finite \a values. */
nlohmann::json
distanceStatistics (const Eigen::VectorXd& values);
} // namespace tools
} // namespace morphreg

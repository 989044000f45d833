// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file registration_result_json.h
 *  \brief A finished MorphableICP fit as JSON: its verdict, similarity, coefficients per region, residuals,
 *  iterations and termination; the body of `morphreg register`'s report and of the Python result's report.
 */
#include <morphreg/model/morphable_model.h>
#include <morphreg/registration/fit_plausibility.h>
#include <morphreg/registration/morphable_icp.h>

#include <pcl/point_types.h>

#include <nlohmann/json_fwd.hpp>

#include <Eigen/Core>

namespace morphreg
{
/** \brief The measures (measureFit) of \a icp's finished fit of \a model against its target (mm); of the shape
 *  coefficients, each region's FitPlausibilitySettings::leading_components are held to the sigma limit.
 *  \param[in] icp a registration after align()
 *  \param[in] model the model it fitted
 *  \return the measures
 */
FitMeasures
measureRegistration (MorphableICP<pcl::PointNormal>& icp, const MorphableModel& model);

/** \brief The plausibility checks (checkFitPlausibility) of measureRegistration's measures.
 *  \param[in] icp a registration after align()
 *  \param[in] model the model it fitted
 *  \return the verdict
 */
FitPlausibility
checkRegistration (MorphableICP<pcl::PointNormal>& icp, const MorphableModel& model);

/** \brief A similarity as JSON: the 4 x 4 matrix (row-major), its scale, rotation (row-major) and translation.
 *  \param[in] transform a similarity (scale times rotation, then translation)
 *  \return the JSON object
 */
nlohmann::json
similarityJson (const Eigen::Matrix4d& transform);

/** \brief The JSON of \a icp's finished fit of \a model: "status" ("ok" or "failed") and "checks"
 *  (checkRegistration, with the measures), "initialisation", "similarity", "initial_similarity", "coefficients" (per region name, in prior
 *  standard deviations; "coefficients_unit" says so) and "coefficients_mm" (the same as lengths),
 *  "residuals_mm" (scan to model over the correspondences; "per_vertex" statistics), "iterations" and
 *  "termination". Callers add what they know of the scan, the model file and the outputs.
 *  \param[in] icp a registration after align()
 *  \param[in] model the model it fitted
 *  \return the JSON object
 */
nlohmann::json
registrationResultJson (MorphableICP<pcl::PointNormal>& icp, const MorphableModel& model);

} // namespace morphreg

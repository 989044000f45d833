// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/cloud_matrix.h>
#include <morphreg/common/distance_statistics.h>
#include <morphreg/model/coefficient_units.h>
#include <morphreg/registration/registration_result_json.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <vector>

namespace morphreg
{
namespace
{
nlohmann::json
iterationsJson (const IcpReport& report)
{
  nlohmann::json history = nlohmann::json::array ();
  for (const IcpIteration& it : report.history)
    history.push_back ({{"stage", toString (it.stage)},
                        {"mean_squared_error_mm2", it.error},
                        {"correspondences", it.correspondences},
                        {"kept", it.kept},
                        {"seconds", it.seconds}});
  return {{"similarity", report.similarity_iterations},
          {"shape", report.shape_iterations},
          {"total", report.history.size ()},
          {"history", history}};
}

nlohmann::json
coefficientsJson (const MorphableModel& model, const ComponentSelection& selection, const Eigen::VectorXd& m)
{
  nlohmann::json coefficients = nlohmann::json::object ();
  for (int j = 0; j < model.numRegions (); ++j) {
    const Eigen::VectorXd part = m.segment (selection.offset (j), selection.count (j));
    coefficients[model.region (j).name] = std::vector<double> (part.data (), part.data () + part.size ());
  }
  return coefficients;
}

/** Residual statistics: scan to model over the correspondences (with PCL's fitness score, the mean squared distance
 *  that getFitnessScore() returns), and per model vertex. */
nlohmann::json
residualsJson (const IcpReport& report, const Eigen::VectorXd& vertex_residuals)
{
  return {{"scan_to_model",
           {{"correspondences", report.correspondences},
            {"mean", report.fitness_mean},
            {"median", report.fitness_median},
            {"rms", report.fitness_rms},
            {"fitness_score_mm2", report.fitness_rms * report.fitness_rms}}},
          {"per_vertex", distanceStatistics (vertex_residuals)}};
}
} // namespace

FitMeasures
measureRegistration (MorphableICP<pcl::PointNormal>& icp, const MorphableModel& model)
{
  const Eigen::Matrix4d similarity = icp.getFinalTransformation ().cast<double> ();
  return measureFit (model, icp.getComponentSelection (), icp.getShapeCoefficientsMm (), similarity,
                     icp.getFittedVertices (), icp.getVertexResiduals (), pointsOf (*icp.getInputTarget ()),
                     icp.getRegistrationReport (), FitPlausibilitySettings ().leading_components);
}

FitPlausibility
checkRegistration (MorphableICP<pcl::PointNormal>& icp, const MorphableModel& model)
{
  return checkFitPlausibility (measureRegistration (icp, model));
}

nlohmann::json
similarityJson (const Eigen::Matrix4d& transform)
{
  const Eigen::Matrix3d linear = transform.topLeftCorner<3, 3> ();
  const double scale = std::cbrt (linear.determinant ());
  const Eigen::Matrix4d rows = transform.transpose (); // row-major order in the file
  const Eigen::Matrix3d rotation_rows = (linear / scale).transpose ();
  return {{"matrix_row_major", std::vector<double> (rows.data (), rows.data () + 16)},
          {"scale", scale},
          {"rotation_row_major", std::vector<double> (rotation_rows.data (), rotation_rows.data () + 9)},
          {"translation", {transform (0, 3), transform (1, 3), transform (2, 3)}}};
}

/** FitMeasures::region_coverage as an object: region name -> share. */
nlohmann::json
regionCoverageJson (const FitMeasures& measures)
{
  nlohmann::json coverage = nlohmann::json::object ();
  for (const auto& [name, share] : measures.region_coverage)
    coverage[name] = share;
  return coverage;
}

/** The measures as the report's "checks" object holds them, with the verdict. */
nlohmann::json
checksJson (const FitMeasures& measures, const FitPlausibility& checks)
{
  return {{"passed", checks.plausible},
          {"failures", checks.failures},
          {"measures",
           {{"scale", measures.scale},
            {"correspondence_share", measures.correspondence_share},
            {"largest_leading_sigma", measures.largest_sigma},
            {"thickness_ratio", measures.thickness_ratio},
            {"median_residual_mm", measures.median_residual},
            {"explained_share", measures.explained_share},
            {"explained_within_mm", kExplainedDistance},
            {"scored_scan_points", measures.scored_points},
            {"folded_share", measures.folded_share},
            {"region_coverage", regionCoverageJson (measures)}}}};
}

nlohmann::json
registrationResultJson (MorphableICP<pcl::PointNormal>& icp, const MorphableModel& model)
{
  const IcpReport& report = icp.getRegistrationReport ();
  const FitMeasures measures = measureRegistration (icp, model);
  const FitPlausibility checks = checkFitPlausibility (measures);
  return {{"status", checks.plausible ? "ok" : "failed"},
          {"checks", checksJson (measures, checks)},
          {"units", "mm"},
          {"initialisation",
           {{"method", report.initialisation},
            {"detail", report.initialisation_detail},
            {"confidence", report.initialisation_confidence},
            {"head_points", report.head_points}}},
          {"similarity", similarityJson (icp.getFinalTransformation ().cast<double> ())},
          {"initial_similarity", similarityJson (report.initial_transformation)},
          {"coefficients", coefficientsJson (model, icp.getComponentSelection (), icp.getShapeCoefficients ())},
          {"coefficients_unit", kCoefficientsUnit},
          {"coefficients_mm", coefficientsJson (model, icp.getComponentSelection (), icp.getShapeCoefficientsMm ())},
          {"residuals_mm", residualsJson (report, icp.getVertexResiduals ())},
          {"iterations", iterationsJson (report)},
          {"termination", {{"reason", toString (report.termination)}, {"message", report.message}}},
          {"target_surface",
           {{"smoothing", report.target_smoothing},
            {"noise_ratio", std::isfinite (report.target_noise_ratio) ? nlohmann::json (report.target_noise_ratio)
                                                                      : nlohmann::json (nullptr)}}}};
}

} // namespace morphreg

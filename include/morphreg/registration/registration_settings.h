// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file registration_settings.h
 *  \brief The settings of a scan registration by their command-line names (`morphreg register --iterations ...`),
 *  applied to a MorphableICP in one place for the command line and the Python module.
 */
#include <morphreg/model/morphable_model.h>
#include <morphreg/registration/morphable_icp.h>

#include <pcl/point_types.h>

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief MorphableICP's settings as `morphreg register` names them (each field is the option without "--", with
 *  '_' for '-'); the defaults are the command line's, which are MorphableICP's own (MorphableIcpDefaults). */
struct RegistrationSettings
{
  /** ICP iterations, similarity and shape stages together (>= 1) */
  int iterations = MorphableIcpDefaults::iterations;
  /** at most this many fit the similarity alone (>= 1) */
  int similarity_iterations = MorphableIcpDefaults::similarity_iterations;
  double max_distance = 0.0; ///< max correspondence distance (mm, 0 = no limit)
  /** Components per region: one count for all, or one per region; empty (the default): every component the model
   *  has, at most kMaxDefaultComponents per region. */
  std::vector<int> components;
  bool point_to_plane = MorphableIcpDefaults::point_to_plane; ///< point-to-plane rows (false: point-to-point)
  /** point-to-point share kept along the tangent plane (0-1) */
  double tangential_weight = MorphableIcpDefaults::tangential_weight;
  double shape_prior = MorphableIcpDefaults::shape_prior; ///< lambda_2, the shape regulariser (>= 0)
  /** lambda_2 (>= 0) of a refinement over all `components` (with lambda_1 = refinement_smoothness), after a first
   *  shape phase over at most kCoarseComponents per region at shape_prior; unset: two phases over all at
   *  shape_prior. A weak prior once the correspondences have settled lets many components follow the scan (models
   *  built from scans). */
  std::optional<double> refinement_prior;
  /** lambda_1 (>= 0) of that refinement: under a weak prior the overlapping regions need a firmer pull to agree
   *  (synthetic scans: vertex error 0.165 mm at 0.1, 0.138 mm at 1 to 10); a model whose regions cannot agree on the
   *  scan fits closer with less (ICT-FaceKit on the real Lee Perry-Smith scan: RMS 1.56 mm at 0.1, 1.71 mm at 1). */
  double refinement_smoothness = 1.0;
  /** One landmark counts as this many correspondences (>= 0). 0, the default: landmarks only place the start; the
   *  surface fits the shape (hand-placed landmarks lie millimetres off the model's points, and contour ones such as
   *  the jaw line mean other points on a scan than on the model). */
  double landmark_weight = MorphableIcpDefaults::landmark_weight;
  bool area_weighting = false;    ///< weigh model vertices by their surface area
  std::string loss = "tukey";     ///< robust loss: none, huber or tukey
  double loss_scale = 0.0;        ///< robust loss width (mm, 0 = from the residuals' MAD)
  double reject_distance = 0.0;   ///< reject correspondences beyond this distance (mm, 0 = off)
  double reject_median = 0.0;     ///< reject beyond this factor of the median distance (0 = off)
  bool reject_one_to_one = false; ///< keep the nearest of several model points sharing a scan point
  double reject_trimmed = 0.0;    ///< keep this share of the correspondences, the nearest (0 = off, else 0-1]
  /** Fit to the scan points projected onto their neighbourhood's plane: "on", "off" or "auto" (on for noisy scans,
   *  see TargetSmoothing). */
  std::string target_smoothing = "auto";
  std::string units = "auto"; ///< the scan's unit: auto (guessed from its size), mm, cm, m or in
  std::string start = "auto"; ///< where the fit starts: a registered InitialAlignmentStrategy (starts/)
};

/** \brief The components per region of the first shape phase when RegistrationSettings::refinement_prior is set. */
constexpr int kCoarseComponents = 10;

/** \brief The most components per region that RegistrationSettings' default (every component) fits, as
 *  MorphableICP::setModel selects. */
constexpr int kMaxDefaultComponents = MorphableIcpDefaults::components_per_region;

/** \brief The components per region that \a settings select in \a model: their counts, or the default.
 *  Throws InvalidInputError if the counts are neither one nor one per region.
 *  \param[in] settings the settings
 *  \param[in] model the model to fit
 *  \return one count per region (at most what each region has)
 */
std::vector<int>
componentsPerRegion (const RegistrationSettings& settings, const MorphableModel& model);

/** \brief Throws InvalidInputError naming the first setting out of its range (see the fields) or the unknown loss or
 *  unit name.
 *  \param[in] settings the settings to check
 */
void
requireValidSettings (const RegistrationSettings& settings);

/** \brief Configures \a icp for a fit of \a model with \a settings (checked first): components, iterations, rows,
 *  priors, robust loss and the rejector chain (the target-boundary rejector first, then the ones the settings turn
 *  on). The target must be in mm (convert the scan first, see pipeline/scan_units.h: MorphableICP refuses one that is not).
 *  \param[in,out] icp the registration to configure
 *  \param[in] settings the settings
 *  \param[in] model the model to fit
 */
void
configureRegistration (MorphableICP<pcl::PointNormal>& icp, const RegistrationSettings& settings,
                       const MorphableModel::ConstPtr& model);

/** \brief The settings as the JSON object of registration reports (keys with their units, e.g.
 *  "max_correspondence_distance_mm").
 *  \param[in] settings the settings
 *  \return the JSON object
 */
nlohmann::json
toJson (const RegistrationSettings& settings);

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/common/length_unit.h>
#include <morphreg/registration/registration_options.h>
#include <morphreg/registration/robust_kernel.h>
#include <morphreg/registration/registration_settings.h>

#include <pcl/registration/correspondence_rejection_distance.h>
#include <pcl/registration/correspondence_rejection_median_distance.h>
#include <pcl/registration/correspondence_rejection_one_to_one.h>
#include <pcl/registration/correspondence_rejection_trimmed.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

namespace morphreg
{
namespace
{
TargetSmoothing
parseTargetSmoothing (const std::string& name)
{
  if (name == "auto")
    return TargetSmoothing::automatic;
  if (name == "on")
    return TargetSmoothing::on;
  if (name == "off")
    return TargetSmoothing::off;
  throw InvalidInputError ("registration setting target_smoothing = \"" + name + "\" is none of auto, on, off");
}

/** Two shape phases: over at most kCoarseComponents per region at \a settings' shape prior (and \a icp's
 *  first-phase lambda_1) while the correspondences settle, then over all \a counts at its refinement weights. */
std::vector<ShapePhase>
coarseToFine (const MorphableICP<pcl::PointNormal>& icp, const MorphableModel& model, const std::vector<int>& counts,
              const RegistrationSettings& settings)
{
  std::vector<int> coarse = counts;
  for (int& count : coarse)
    count = std::min (count, kCoarseComponents);
  return {{model.firstComponents (coarse), icp.getSmoothnessWeight (), settings.shape_prior},
          {model.firstComponents (counts), settings.refinement_smoothness, settings.refinement_prior}};
}

/** The rejectors \a settings turn on, after the target-boundary and normal-compatibility rejectors (a chain replaces
 *  MorphableICP's default one, which is those two, so they stay first). */
void
addRejectors (MorphableICP<pcl::PointNormal>& icp, const RegistrationSettings& settings)
{
  icp.addCorrespondenceRejector (icp.getTargetBoundaryRejector ());
  icp.addCorrespondenceRejector (icp.getNormalCompatibilityRejector ());
  if (settings.reject_distance > 0.0) {
    auto rejector = std::make_shared<pcl::registration::CorrespondenceRejectorDistance> ();
    rejector->setMaximumDistance (static_cast<float> (settings.reject_distance));
    icp.addCorrespondenceRejector (rejector);
  }
  if (settings.reject_median > 0.0) {
    auto rejector = std::make_shared<pcl::registration::CorrespondenceRejectorMedianDistance> ();
    rejector->setMedianFactor (settings.reject_median);
    icp.addCorrespondenceRejector (rejector);
  }
  if (settings.reject_one_to_one)
    icp.addCorrespondenceRejector (std::make_shared<pcl::registration::CorrespondenceRejectorOneToOne> ());
  if (settings.reject_trimmed > 0.0) {
    auto rejector = std::make_shared<pcl::registration::CorrespondenceRejectorTrimmed> ();
    rejector->setOverlapRatio (static_cast<float> (settings.reject_trimmed));
    icp.addCorrespondenceRejector (rejector);
  }
}
} // namespace

void
requireValidSettings (const RegistrationSettings& settings)
{
  requireValidOptions (registrationOptions (), settings, "registration setting");
  parseTargetSmoothing (settings.target_smoothing);
}

void
configureRegistration (MorphableICP<pcl::PointNormal>& icp, const RegistrationSettings& settings,
                       const MorphableModel::ConstPtr& model)
{
  requireValidSettings (settings);
  icp.setModel (model);
  const std::vector<int> per_region = componentsPerRegion (settings, *model);
  icp.setComponentSelection (model->firstComponents (per_region));
  if (settings.refinement_prior)
    icp.setShapeSchedule (coarseToFine (icp, *model, per_region, settings));
  icp.setMaximumIterations (settings.iterations);
  icp.setSimilarityIterations (settings.similarity_iterations);
  if (settings.max_distance > 0.0)
    icp.setMaxCorrespondenceDistance (settings.max_distance);
  icp.setPointToPlane (settings.point_to_plane, settings.tangential_weight);
  icp.setShapePriorWeight (settings.shape_prior);
  icp.setAreaWeighting (settings.area_weighting);
  icp.setRobustKernel (makeRobustKernel (settings.loss, settings.loss_scale));
  icp.setInitialAlignment (makeInitialAlignment (settings.start));
  icp.setTargetSmoothing (parseTargetSmoothing (settings.target_smoothing));
  addRejectors (icp, settings);
}

std::vector<int>
componentsPerRegion (const RegistrationSettings& settings, const MorphableModel& model)
{
  const std::vector<int>& counts = settings.components;
  const auto regions = static_cast<std::size_t> (model.numRegions ());
  if (counts.size () > 1 && counts.size () != regions)
    throw InvalidInputError ("registration setting components has " + std::to_string (counts.size ()) +
                             " counts for a model with " + std::to_string (regions) +
                             " regions: give one count for all regions, or one per region");
  std::vector<int> per_region (regions);
  for (std::size_t j = 0; j < regions; ++j) {
    const auto available = static_cast<int> (model.region (static_cast<int> (j)).variances.size ());
    per_region[j] = counts.empty () ? std::min (available, kMaxDefaultComponents)
                                    : std::min (available, counts.size () == 1 ? counts.front () : counts[j]);
  }
  return per_region;
}

nlohmann::json
toJson (const RegistrationSettings& settings)
{
  return {
      {"iterations", settings.iterations},
      {"similarity_iterations", settings.similarity_iterations},
      {"max_correspondence_distance_mm", settings.max_distance},
      {"components", settings.components},
      {"point_to_plane", settings.point_to_plane},
      {"tangential_weight", settings.tangential_weight},
      {"shape_prior_weight", settings.shape_prior},
      {"refinement_prior_weight", settings.refinement_prior ? nlohmann::json (*settings.refinement_prior) : nullptr},
      {"refinement_smoothness_weight", settings.refinement_smoothness},
      {"area_weighting", settings.area_weighting},
      {"landmark_weight", settings.landmark_weight},
      {"robust_loss", settings.loss},
      {"robust_scale_mm", settings.loss_scale},
      {"reject_distance_mm", settings.reject_distance},
      {"reject_median_factor", settings.reject_median},
      {"reject_one_to_one", settings.reject_one_to_one},
      {"reject_trimmed_ratio", settings.reject_trimmed},
      {"units", settings.units},
      {"start", settings.start},
      {"target_smoothing", settings.target_smoothing}};
}

} // namespace morphreg

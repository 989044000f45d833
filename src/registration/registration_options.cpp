// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/registration/registration_options.h>
#include <morphreg/registration/initial_alignment_strategy.h>
#include <morphreg/registration/robust_kernel.h>

#include <string>

namespace morphreg
{
namespace
{
using S = RegistrationSettings;

/** \a names as "a, b, c". */
std::string
nameList (const std::vector<std::string>& names)
{
  std::string listed;
  for (const std::string& name : names)
    listed += (listed.empty () ? "" : ", ") + name;
  return listed;
}

/** The fit's iterations, correspondences, components, rows and priors. */
std::vector<RegistrationOption>
fitOptions ()
{
  constexpr double kNoBound = kUnboundedSetting;
  return {
      {"iterations", "ICP iterations, similarity and shape stages together", &S::iterations, 1, 10000, {}},
      {"similarity_iterations",
       "at most this many iterations fit the similarity alone before the shape joins",
       &S::similarity_iterations,
       1,
       10000,
       {}},
      {"max_distance", "max correspondence distance (mm, 0 = no limit)", &S::max_distance, 0, kNoBound, {}},
      {"components",
       "shape components per region: one count for all, or one per region (default: every component the model has, "
       "at most 60 per region)",
       &S::components,
       0,
       10000,
       {}},
      {"point_to_plane",
       "point-to-plane residuals along the scan normals (default) or point-to-point",
       &S::point_to_plane,
       0,
       0,
       {"point_to_point"}},
      {"tangential_weight",
       "share of the point-to-point term kept along the tangent plane (point-to-plane)",
       &S::tangential_weight,
       0,
       1,
       {}},
      {"shape_prior",
       "weight of the shape prior (coefficients in prior standard deviations)",
       &S::shape_prior,
       0,
       kNoBound,
       {}},
      {"refinement_prior",
       "refine over all components at this shape prior, after a first phase over at most 10 per region at the "
       "shape prior (e.g. 0.5 with many components: fits that follow the scan closely)",
       &S::refinement_prior,
       0,
       kNoBound,
       {}},
      {"refinement_smoothness",
       "lambda_1 of the refinement at the refinement prior (less for models whose regions cannot agree on the scan, "
       "e.g. 0.1 with ICT-FaceKit)",
       &S::refinement_smoothness,
       0,
       kNoBound,
       {}},
      {"landmark_weight",
       "one landmark counts as this many correspondences in the fit (0: the landmarks only place the start)",
       &S::landmark_weight,
       0,
       kNoBound,
       {}},
  };
}

/** How the scan is taken: its surface, its unit, the weight of the model's vertices. */
std::vector<RegistrationOption>
scanOptions ()
{
  return {
      {"start",
       "where the fit starts: " + nameList (initialAlignmentNames ()) +
           " (auto: the landmarks when at least 3 are given, else the search for the head in any pose; guess: the "
           "scan as it lies, already in the model's frame; coarse: about the scan's principal axes)",
       &S::start, 0, 0, initialAlignmentNames ()},
      {"target_smoothing",
       "fit to each scan point projected onto its neighbours' plane: on, off or auto (on for noisy scans such as "
       "depth-camera frames; the report's target_surface says what was done)",
       &S::target_smoothing,
       0,
       0,
       {"auto", "on", "off"}},
      {"units",
       "the scan's length unit: auto (from its size; a scan in no unit: its scale estimated from the head), mm, cm, "
       "m or in (glTF/GLB scans: the unit after reading, which converts glTF's metres to mm)",
       &S::units,
       0,
       0,
       {"auto", "mm", "cm", "m", "in"}},
      {"area_weighting",
       "weigh model vertices by their surface area (models with uneven vertex density, e.g. ICT)",
       &S::area_weighting,
       0,
       0,
       {}},
  };
}

/** The robust kernel and PCL's rejectors. */
std::vector<RegistrationOption>
robustnessOptions ()
{
  constexpr double kNoBound = kUnboundedSetting;
  return {
      {"loss", "robust loss (IRLS kernel): " + nameList (robustKernelNames ()), &S::loss, 0, 0, robustKernelNames ()},
      {"loss_scale", "robust loss width (mm, 0 = from the residuals' MAD)", &S::loss_scale, 0, kNoBound, {}},
      {"reject_distance",
       "reject correspondences farther than this (mm, 0 = off; pcl CorrespondenceRejectorDistance)",
       &S::reject_distance,
       0,
       kNoBound,
       {}},
      {"reject_median",
       "reject beyond FACTOR x the median distance (0 = off; CorrespondenceRejectorMedianDistance)",
       &S::reject_median,
       0,
       kNoBound,
       {}},
      {"reject_one_to_one",
       "keep one correspondence per scan point (CorrespondenceRejectorOneToOne)",
       &S::reject_one_to_one,
       0,
       0,
       {}},
      {"reject_trimmed",
       "keep this fraction of the closest correspondences (0 = off; CorrespondenceRejectorTrimmed)",
       &S::reject_trimmed,
       0,
       1,
       {}},
  };
}

} // namespace

const std::vector<RegistrationOption>&
registrationOptions ()
{
  static const std::vector<RegistrationOption> options =
      joinedOptions ({fitOptions (), scanOptions (), robustnessOptions ()});
  return options;
}

const RegistrationOption*
findRegistrationOption (const std::string& name)
{
  return findSettingOption (registrationOptions (), name);
}

} // namespace morphreg

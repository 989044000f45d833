// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/resampling/resampling_settings.h>

#include <nlohmann/json.hpp>

namespace morphreg
{
namespace
{
using S = ResamplingSettings;

std::vector<ResamplingOption>
makeOptions ()
{
  constexpr double kNoBound = kUnboundedSetting;
  return {
      {"ray_distance",
       "farthest a vertex moves along its normal onto the scan (mm); beyond it the vertex is filled",
       &S::ray_distance,
       0.01,
       kNoBound,
       {}},
      {"normal_agreement",
       "largest angle between a vertex normal and the scan's at the hit (degrees)",
       &S::normal_agreement,
       1,
       180,
       {}},
      {"ring_width", "rings of observed vertices around a hole that fill it", &S::ring_width, 1, 20, {}},
      {"max_hole_fraction",
       "largest share of the model's surface one hole may cover (else the scan is refused)",
       &S::max_hole_fraction,
       0.01,
       1,
       {}},
      {"fill_smoothing", "thin plate spline smoothing of the fills (mm)", &S::fill_smoothing, 0, kNoBound, {}},
      {"passes",
       "resampling passes; each after the first casts again from the previous one's fills",
       &S::passes,
       1,
       10,
       {}},
      {"neighbours",
       "scan points a point cloud's local plane is weighted over (clouds only)",
       &S::neighbours,
       4,
       1000,
       {}},
      {"max_jump",
       "largest difference (mm) between a hit's displacement and its neighbours' median; beyond it the hit is "
       "dropped as a jump onto another surface",
       &S::max_jump,
       0.01,
       kNoBound,
       {}},
  };
}
} // namespace

const std::vector<ResamplingOption>&
resamplingOptions ()
{
  static const std::vector<ResamplingOption> options = makeOptions ();
  return options;
}

void
requireValidSettings (const ResamplingSettings& settings)
{
  requireValidOptions (resamplingOptions (), settings, "resampling setting");
}

nlohmann::json
toJson (const ResamplingSettings& settings)
{
  return {{"ray_distance_mm", settings.ray_distance},  {"normal_agreement_deg", settings.normal_agreement},
          {"ring_width", settings.ring_width},         {"max_hole_fraction", settings.max_hole_fraction},
          {"fill_smoothing", settings.fill_smoothing}, {"passes", settings.passes},
          {"neighbours", settings.neighbours},         {"max_jump_mm", settings.max_jump}};
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/model/model_builder_options.h>

namespace morphreg
{
const std::vector<ModelBuilderOption>&
modelBuilderOptions ()
{
  using S = ModelBuilderSettings;
  static const std::vector<ModelBuilderOption> options = {
      {"components", "at most this many components per region (0 = no limit)", &S::max_components, 0, 100000, {}},
      {"variance",
       "keep the fewest components explaining this fraction of each region's variance",
       &S::explained_variance,
       kAboveZeroSetting,
       1.0,
       {}},
      {"blend_rings", "rings of blending around each region (0 = hard)", &S::blend_rings, 0, 1000, {}},
      {"procrustes",
       "rigid Procrustes alignment of the meshes before the PCA (on by default; --no-procrustes or procrustes=False "
       "skips it)",
       &S::align,
       0,
       0,
       {"no_procrustes"}},
  };
  return options;
}
} // namespace morphreg

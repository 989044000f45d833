// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target photo_json: the profile and frontal photo annotation loaders.
#include "fuzz_target.h"

#include <morphreg/photo/photo_view_io.h>

namespace
{
const bool registered =
    morphreg::fuzz::registerTarget ({"photo_json",
                                     ".json",
                                     {[] (const std::string& path) { morphreg::loadProfileView (path); },
                                      [] (const std::string& path) { morphreg::loadFrontalView (path); }}});
} // namespace

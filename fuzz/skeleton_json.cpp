// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target skeleton_json: the skeleton file loader of the articulated warp.
#include "fuzz_target.h"

#include <morphreg/io/skeleton_io.h>

namespace
{
const bool registered = morphreg::fuzz::registerTarget (
    {"skeleton_json", ".json", {[] (const std::string& path) { morphreg::loadSkeleton (path); }}});
} // namespace

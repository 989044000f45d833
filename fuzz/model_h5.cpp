// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target model_h5: model files, read as loadModel() does (morphreg's layout, statismo's at the root, or the
// Basel Face Model 2017's under "shape/") and as a BFM-2017 file explicitly.
#include "fuzz_target.h"

#include <morphreg/io/model_io.h>

namespace
{
const bool registered =
    morphreg::fuzz::registerTarget ({"model_h5",
                                     ".h5",
                                     {[] (const std::string& path) { morphreg::loadModel (path); },
                                      [] (const std::string& path) { morphreg::loadStatismoModel (path, "shape"); }}});
} // namespace

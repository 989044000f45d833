// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target npy: the validating .npy reader.
#include "fuzz_target.h"

#include <morphreg/io/npy_reader.h>

namespace
{
const bool registered = morphreg::fuzz::registerTarget (
    {"npy", ".npy", {[] (const std::string& path) { morphreg::readNpyFloat32 (path); }}});
} // namespace

// SPDX-License-Identifier: BSD-3-Clause
// The libFuzzer entry point of one fuzz executable: runs the target named by MORPHREG_FUZZ_TARGET (set per
// executable in fuzz/CMakeLists.txt).
#include "fuzz_target.h"

extern "C" int
LLVMFuzzerTestOneInput (const std::uint8_t* data, std::size_t size)
{
  static const morphreg::fuzz::Target& target = morphreg::fuzz::findTarget (MORPHREG_FUZZ_TARGET);
  morphreg::fuzz::runTarget (target, data, size);
  return 0;
}

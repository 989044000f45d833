// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/warp/impl/tps_kernel.hpp>

// x86-64-v4 (AVX-512) and v3 (AVX2, FMA) clones next to the baseline, picked by the loader for the running CPU.
// Builds that already target a CPU (MORPHREG_NATIVE, or any -march with AVX2) compile the loop for it alone.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && !defined(__AVX2__)
#define MORPHREG_ISA_CLONES __attribute__ ((target_clones ("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define MORPHREG_ISA_CLONES
#endif

namespace morphreg
{
namespace detail
{
MORPHREG_ISA_CLONES void
evaluateTpsBlock (const TpsCoefficients<double, 3>& c, const double* points, Eigen::Index count, double* result)
{
  for (Eigen::Index j = 0; j < count; ++j)
    Eigen::Map<Eigen::Vector3d> (result + 3 * j) = evaluateTpsPoint (c, points + 3 * j);
}
} // namespace detail
} // namespace morphreg

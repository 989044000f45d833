// SPDX-License-Identifier: BSD-3-Clause
// Must not compile (CompileFailTest in ../compile_fail.cmake): MorphableICP's second template argument is the scalar,
// and a point type there is refused by a static_assert with a plain message.
#include <morphreg/registration/morphable_icp.h>

int
main ()
{
  morphreg::MorphableICP<pcl::PointXYZ, pcl::PointXYZ> icp;
  return icp.getMaximumIterations () > 0 ? 0 : 1;
}

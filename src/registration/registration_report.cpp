// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/registration/registration_report.h>

namespace morphreg
{
std::string
toString (IcpTermination termination)
{
  switch (termination) {
  case IcpTermination::not_run:
    return "not_run";
  case IcpTermination::transformation_converged:
    return "transformation_converged";
  case IcpTermination::fitness_converged:
    return "fitness_converged";
  case IcpTermination::max_iterations:
    return "max_iterations";
  case IcpTermination::diverged:
    return "diverged";
  }
  return "unknown";
}

std::string
toString (IcpStage stage)
{
  return stage == IcpStage::similarity ? "similarity" : "shape";
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include "scan_resampling.h"

#include "table_options.h"

namespace morphreg
{
namespace tools
{
void
addResamplingOptions (CLI::App* command, ResamplingOptions& options)
{
  for (const ResamplingOption& option : resamplingOptions ())
    addTableOption<ResamplingSettings> (command, options, option);
}

} // namespace tools
} // namespace morphreg

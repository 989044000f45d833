// SPDX-License-Identifier: BSD-3-Clause
#include "number_text.h"

#include <morphreg/common/error.h>
#include <morphreg/common/setting_options.h>

#include <algorithm>
#include <cmath>

namespace morphreg
{
std::string
commandLineName (const std::string& name)
{
  std::string option = "--" + name;
  std::replace (option.begin (), option.end (), '_', '-');
  return option;
}

void
requireSettingInRange (const std::string& kind, const std::string& name, double value, double lowest, double highest)
{
  if (std::isfinite (value) && value >= lowest && value <= highest)
    return;
  using detail::numberText;
  const std::string range = highest == kUnboundedSetting ? "at least " + numberText (lowest)
                                                         : numberText (lowest) + " to " + numberText (highest);
  throw InvalidInputError (kind + " " + name + " = " + numberText (value, 6) + " is out of range (" + range + ")");
}

void
requireSettingChoice (const std::string& kind, const std::string& name, const std::string& value,
                      const std::vector<std::string>& choices)
{
  if (std::find (choices.begin (), choices.end (), value) != choices.end ())
    return;
  std::string listed;
  for (const std::string& choice : choices)
    listed += (listed.empty () ? "" : ", ") + choice;
  throw InvalidInputError (kind + " " + name + " = \"" + value + "\" is none of " + listed);
}

} // namespace morphreg

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

bool
isSettingInRange (double value, double lowest, double highest)
{
  if (std::isinf (value))
    return value > 0 && highest == kInfiniteSetting;
  return value >= lowest && value <= highest; // false for a NaN
}

std::string
settingRangeText (double lowest, double highest)
{
  using detail::numberText;
  const std::string from = lowest == kAboveZeroSetting ? "above 0" : "at least " + numberText (lowest);
  if (highest == kInfiniteSetting)
    return from + ", or inf";
  if (highest == kUnboundedSetting)
    return from;
  return (lowest == kAboveZeroSetting ? "above 0 to " : numberText (lowest) + " to ") + numberText (highest);
}

void
requireSettingInRange (const std::string& kind, const std::string& name, double value, double lowest, double highest)
{
  if (!isSettingInRange (value, lowest, highest))
    throw InvalidInputError (kind + " " + name + " = " + detail::numberText (value, 6) + " is out of range (" +
                             settingRangeText (lowest, highest) + ")");
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

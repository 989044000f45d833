// SPDX-License-Identifier: BSD-3-Clause
// The one table of the simulated scanner's settings (scanner_options.h) that synth, Python's ScanSimulator and the
// scanner's own check read.
#include "support/expect_error.h"

#include <morphreg/common/error.h>
#include <morphreg/synthetic/scanner_options.h>

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>
#include <type_traits>

namespace
{
using morphreg::synthetic::ScannerOption;
using morphreg::synthetic::ScanSimulator;
using morphreg::test::expectErrorContaining;

TEST (ScannerOptionsTest, EverySettingHasOneEntryAndEveryBoundIsTheScannersCheck)
{
  std::set<std::string> names;
  EXPECT_NO_THROW (ScanSimulator (ScanSimulator::Parameters ()));
  for (const ScannerOption& option : morphreg::synthetic::scannerOptions ()) {
    EXPECT_TRUE (names.insert (option.name).second) << option.name << " twice";
    EXPECT_GT (option.help.size (), 20u) << option.name;
    if (std::holds_alternative<bool ScanSimulator::Parameters::*> (option.field))
      continue;
    for (const double outside : {option.lowest == morphreg::kAboveZeroSetting ? 0.0 : option.lowest - 1.0,
                                 option.highest * 2.0, std::nan ("")}) {
      if (std::isinf (outside) || (std::isnan (outside) && option.name == "angular_samples"))
        continue; // no upper bound; a count cannot hold a NaN
      ScanSimulator::Parameters parameters;
      std::visit (
          [&] (auto field) {
            using T = std::decay_t<decltype (parameters.*field)>;
            if constexpr (std::is_same_v<T, int> || std::is_same_v<T, double>)
              parameters.*field = static_cast<T> (outside);
          },
          option.field);
      expectErrorContaining<morphreg::InvalidInputError> ([&] { ScanSimulator scanner (parameters); },
                                                          "scanner setting " + option.name + " = ");
    }
  }
  EXPECT_EQ (names.size (), 11u) << "every field of ScanSimulator::Parameters";
}
} // namespace

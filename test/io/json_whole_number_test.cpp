// SPDX-License-Identifier: BSD-3-Clause
// Integers read from JSON are whole numbers in range: never wrapped (4294967301 as 5) or truncated (12.9 as 12).
#include <morphreg/common/error.h>
#include <morphreg/io/json_file.h>

#include "support/expect_error.h"

#include <gtest/gtest.h>

using morphreg::test::expectErrorContaining;

TEST (JsonWholeNumberTest, WholeNumbersInRangeAreRead)
{
  EXPECT_EQ (morphreg::jsonWholeNumber (nlohmann::json::parse ("12"), 0, 100, "v"), 12);
  EXPECT_EQ (morphreg::jsonWholeNumber (nlohmann::json::parse ("1e2"), 0, 100, "v"), 100);
  EXPECT_EQ (morphreg::jsonWholeNumber (nlohmann::json::parse ("-3.0"), -5, 100, "v"), -3);
  EXPECT_EQ (morphreg::jsonWholeNumbers (nlohmann::json::parse ("[0, 1, 2]"), 0, 2, "labels"),
             (std::vector<int>{0, 1, 2}));
}

TEST (JsonWholeNumberTest, OthersAreNamedWithTheValueAsWritten)
{
  const auto read = [] (const char* text) {
    morphreg::jsonWholeNumber (nlohmann::json::parse (text), 0, 9601, "lv.json: the vertex of landmark 'nose_tip'");
  };
  expectErrorContaining<morphreg::FormatError> ([&] { read ("4294967301"); },
                                                "lv.json: the vertex of landmark 'nose_tip' 4294967301 is not from 0 "
                                                "to 9601");
  expectErrorContaining<morphreg::FormatError> ([&] { read ("12.9"); }, "12.9 is not a whole number");
  expectErrorContaining<morphreg::FormatError> ([&] { read ("-1"); }, "-1 is not from 0 to 9601");
  expectErrorContaining<morphreg::FormatError> ([&] { read ("\"7\""); }, "\"7\" is not a number");
  expectErrorContaining<morphreg::FormatError> ([&] { read ("18446744073709551615"); }, "is not from 0 to 9601");
  expectErrorContaining<morphreg::FormatError> (
      [] { morphreg::jsonWholeNumbers (nlohmann::json::parse ("[0, 2.7]"), 0, 9, "regions.json: labels"); },
      "regions.json: labels element 1 2.7 is not a whole number");
}

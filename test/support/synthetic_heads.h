// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// One shared head generator per resolution for a test executable (building one takes a moment).
#include <morphreg/synthetic/head_generator.h>

#include <map>
#include <memory>

namespace morphreg
{
namespace test
{
inline const synthetic::HeadGenerator&
headGenerator (int resolution = 40)
{
  static std::map<int, std::unique_ptr<synthetic::HeadGenerator>> generators;
  auto& generator = generators[resolution];
  if (!generator)
    generator = std::make_unique<synthetic::HeadGenerator> (resolution);
  return *generator;
}
} // namespace test
} // namespace morphreg

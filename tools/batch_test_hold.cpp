// SPDX-License-Identifier: BSD-3-Clause
#include "batch_test_hold.h"

#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <thread>
#include <unistd.h>

namespace morphreg
{
namespace tools
{
BatchTestHold::BatchTestHold (const std::string& share)
{
  const char* value = std::getenv ("MORPHREG_BATCH_TEST_HOLD");
  if (value == nullptr || *value == '\0')
    return;
  const std::string text (value);
  const std::size_t colon = text.find (':');
  char* end = nullptr;
  const long index = std::strtol (text.c_str (), &end, 10);
  if (colon == std::string::npos || end != text.c_str () + colon || colon == 0 || index < 0 ||
      colon + 1 == text.size ())
    throw InvalidInputError ("MORPHREG_BATCH_TEST_HOLD='" + text + "': expected N:DIR (a test-only hook)");
  index_ = index;
  const std::filesystem::path directory = text.substr (colon + 1);
  held_ = (directory / ("held." + share)).string ();
  release_ = (directory / ("release." + share)).string ();
}

void
BatchTestHold::atScan (std::size_t index, const std::atomic<int>& interrupts) const
{
  if (index_ < 0 || index != static_cast<std::size_t> (index_))
    return;
  writeFileAtomically (held_, std::to_string (getpid ()) + "\n");
  const auto deadline = std::chrono::steady_clock::now () + std::chrono::seconds (600);
  std::error_code ec;
  while (!std::filesystem::exists (release_, ec) && interrupts.load () == 0) {
    if (std::chrono::steady_clock::now () > deadline) {
      std::cerr << "morphreg: MORPHREG_BATCH_TEST_HOLD: " << release_ << " did not appear in 600 s; going on\n";
      return;
    }
    std::this_thread::sleep_for (std::chrono::milliseconds (10));
  }
}
} // namespace tools
} // namespace morphreg

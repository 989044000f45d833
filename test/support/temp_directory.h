// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A fresh directory under the system temp folder, removed with everything in it when the test ends.
#include <filesystem>
#include <random>
#include <string>

namespace morphreg
{
namespace test
{
class TempDirectory
{
public:
  TempDirectory ()
  {
    std::random_device device;
    path_ = std::filesystem::temp_directory_path () / ("morphreg_test_" + std::to_string (device ()));
    std::filesystem::create_directories (path_);
  }
  ~TempDirectory ()
  {
    std::filesystem::remove_all (path_);
  }
  TempDirectory (const TempDirectory&) = delete;
  TempDirectory&
  operator= (const TempDirectory&) = delete;

  /** Path of \a name inside the directory. */
  std::string
  file (const std::string& name) const
  {
    return (path_ / name).string ();
  }

private:
  std::filesystem::path path_;
};
} // namespace test
} // namespace morphreg

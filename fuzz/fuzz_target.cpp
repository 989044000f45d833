// SPDX-License-Identifier: BSD-3-Clause
#include "fuzz_target.h"

#include <morphreg/common/error.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace morphreg
{
namespace fuzz
{
namespace
{
std::vector<Target>&
registry ()
{
  static std::vector<Target> all;
  return all;
}

/** \brief The input file of one run, removed when the run ends however it ends. */
class InputFile
{
public:
  InputFile (const std::string& extension, const std::uint8_t* data, std::size_t size)
    : path_ ((std::filesystem::temp_directory_path () / ("morphreg_fuzz_" + std::to_string (::getpid ()) + extension))
                 .string ())
  {
    std::ofstream stream (path_, std::ios::binary | std::ios::trunc);
    stream.write (reinterpret_cast<const char*> (data), static_cast<std::streamsize> (size));
    stream.close ();
    if (!stream)
      throw std::runtime_error (path_ + ": cannot write the fuzz input");
  }
  InputFile (const InputFile&) = delete;
  InputFile&
  operator= (const InputFile&) = delete;
  ~InputFile ()
  {
    std::error_code ignored;
    std::filesystem::remove (path_, ignored);
  }

  const std::string&
  path () const
  {
    return path_;
  }

private:
  std::string path_;
};
} // namespace

bool
registerTarget (Target target)
{
  registry ().push_back (std::move (target));
  return true;
}

const std::vector<Target>&
targets ()
{
  return registry ();
}

const Target&
findTarget (const std::string& name)
{
  for (const Target& target : registry ())
    if (target.name == name)
      return target;
  throw std::invalid_argument ("no fuzz target named '" + name + "'");
}

void
runTarget (const Target& target, const std::uint8_t* data, std::size_t size)
{
  const InputFile input (target.extension, data, size);
  for (const Loader& load : target.loaders) {
    try {
      load (input.path ());
    }
    catch (const Error&) {
      // A clear error is the expected answer to a bad file.
    }
  }
}
} // namespace fuzz
} // namespace morphreg

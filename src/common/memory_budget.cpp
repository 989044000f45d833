// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/common/memory_budget.h>

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

namespace morphreg
{
namespace
{
/** The memory limit of this process's control group (cgroup v2 memory.max), 0 if there is none. */
std::uint64_t
controlGroupLimit ()
{
  std::ifstream stream ("/sys/fs/cgroup/memory.max");
  std::string text;
  if (!(stream >> text) || text.empty () || text.find_first_not_of ("0123456789") != std::string::npos)
    return 0; // "max", or no cgroup v2 file
  return std::stoull (text);
}
} // namespace

std::uint64_t
usableMemoryBytes ()
{
  const long pages = ::sysconf (_SC_PHYS_PAGES), page_size = ::sysconf (_SC_PAGE_SIZE);
  std::uint64_t physical = pages > 0 && page_size > 0 ? static_cast<std::uint64_t> (pages) * page_size : 0;
  const std::uint64_t limit = controlGroupLimit ();
  if (limit > 0)
    physical = physical > 0 ? std::min (physical, limit) : limit;
  return physical;
}

std::string
memoryText (double bytes)
{
  const char* units[] = {"bytes", "kB", "MB", "GB", "TB", "PB"};
  int unit = 0;
  while (bytes >= 1000.0 && unit < 5) {
    bytes /= 1000.0;
    ++unit;
  }
  char text[64];
  std::snprintf (text, sizeof text, unit == 0 ? "%.0f %s" : "%.1f %s", bytes, units[unit]);
  return text;
}

void
requireMemory (double bytes, const std::string& what)
{
  const std::uint64_t usable = usableMemoryBytes ();
  if (usable > 0 && bytes > static_cast<double> (usable))
    throw InvalidInputError (what + " needs about " + memoryText (bytes) + " of memory; this machine has " +
                             memoryText (static_cast<double> (usable)));
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Content hashes of input files (FNV-1a, 64 bits), so that a batch run can tell whether the scan, the landmarks or
// the model behind an output on disk are still the ones it was made from.
#include <cstdint>
#include <string>

namespace morphreg
{
namespace tools
{
/** FNV-1a over bytes given in any number of pieces: fast, and enough to notice a changed file (not a defence
 *  against a deliberate collision). */
class Fnv1a64
{
public:
  void
  add (const char* bytes, std::size_t count);

  void
  add (const std::string& bytes)
  {
    add (bytes.data (), bytes.size ());
  }

  /** The hash so far as 16 lower-case hex digits. */
  std::string
  hex () const;

private:
  std::uint64_t state_ = 0xcbf29ce484222325ULL; ///< the FNV offset basis
};

/** FNV-1a 64 of the bytes of \a path as 16 hex digits. IoError naming the file if it is missing, not a regular
 *  file (a FIFO or a device would never end) or cannot be read to its end. */
std::string
hashFile (const std::string& path);
} // namespace tools
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file file_fingerprint.h
 *  \brief Content hashes of input files (FNV-1a, 64 bits), so that a batch run can tell whether the scan, the
 *  landmarks or the model behind an output on disk are still the ones it was made from.
 */
#include <cstdint>
#include <string>

namespace morphreg
{
/** \brief FNV-1a over bytes given in any number of pieces: fast, and enough to notice a changed file (not a defence
 *  against a deliberate collision). */
class Fnv1a64
{
public:
  /** \brief Hashes \a count more bytes.
   *  \param[in] bytes the bytes
   *  \param[in] count how many */
  void
  add (const char* bytes, std::size_t count);

  /** \brief Hashes the bytes of a string.
   *  \param[in] bytes the bytes */
  void
  add (const std::string& bytes)
  {
    add (bytes.data (), bytes.size ());
  }

  /** \brief The hash so far.
   *  \return 16 lower-case hex digits */
  std::string
  hex () const;

private:
  std::uint64_t state_ = 0xcbf29ce484222325ULL; ///< the FNV offset basis
};

/** \brief The FNV-1a 64 hash of a file's bytes. IoError naming the file if it is missing, not a regular file (a FIFO
 *  or a device would never end) or cannot be read to its end.
 *  \param[in] path the file
 *  \return 16 hex digits */
std::string
hashFile (const std::string& path);
} // namespace morphreg

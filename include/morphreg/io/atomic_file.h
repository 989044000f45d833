// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file atomic_file.h
 *  \brief Writing a file so that readers see it whole or not at all: written under a temporary name in the same
 *  folder, then renamed (atomic on POSIX file systems). A run killed mid-write leaves only the temporary file,
 *  so a resumed batch can trust every output it finds.
 */
#include <morphreg/io/output_transaction.h>

#include <cstdio>
#include <string>

namespace morphreg
{
/** \brief The temporary name of \a path while it is written: ".partial.<name>" in the same folder (the extension
 *  kept, as writers choose the format by it).
 *  \param[in] path the file to be written
 *  \return the temporary path beside it
 */
std::string
partialPath (const std::string& path);

/** \brief Renames the finished \a partial onto \a path; IoError naming both if that fails.
 *  \param[in] partial the completely written temporary file
 *  \param[in] path its final name
 */
void
commitPartial (const std::string& partial, const std::string& path);

/** \brief Writes \a path atomically: \a write (a callable taking the file name to write) writes partialPath(path),
 *  which is then renamed to \a path, or, when an open OutputTransaction covers \a path, left for its commit; if
 *  \a write throws, the partial file is removed and the error passed on.
 *  \param[in] path the file to write
 *  \param[in] write called with the temporary file name; writes the whole file there
 */

template <typename Write>
void
writeAtomically (const std::string& path, Write write)
{
  const std::string partial = partialPath (path);
  try {
    write (partial);
  }
  catch (...) {
    std::remove (partial.c_str ());
    throw;
  }
  if (!OutputTransaction::stage (path))
    commitPartial (partial, path);
}

/** \brief Throws IoError naming \a path if \a written, a mesh or cloud file that PCL has just written, is incomplete
 *  (its header promises more than the file holds): PCL's writers do not report a full disk or a file size limit.
 *  \param[in] written the file as written (the temporary file of writeAtomically())
 *  \param[in] path the name to report
 */
void
requireCompletelyWritten (const std::string& written, const std::string& path);

/** \brief Writes \a content to \a path atomically (see writeAtomically()), checking every write and the close, so
 *  that a full disk or a file size limit is an IoError naming the file, never a file cut short.
 *  \param[in] path the file to write
 *  \param[in] content its bytes
 */
void
writeFileAtomically (const std::string& path, const std::string& content);

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file file_checks.h
 *  \brief Small checks shared by the readers and writers: clear errors before a library reader fails obscurely.
 */
#include <morphreg/common/error.h>

#include <cstdint>
#include <exception>
#include <limits>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief The largest text file (JSON, CSV, landmarks, manifests, photo annotations) morphreg reads: 256 MiB, far
 *  above any real one, so that a wrong file (a device, a disk image) is refused before it is read into memory. */
constexpr std::uintmax_t kMaxTextFileBytes = std::uintmax_t (256) << 20;

/** \brief Throws IoError naming \a path if it does not exist, is a directory or not a regular file (a FIFO, a device
 *  or a socket, which a reader would wait on or read without end), or cannot be read; FormatError if it is empty
 *  or larger than \a max_bytes. Nothing is opened before the checks, so a FIFO never blocks.
 *  \param[in] path the file to check
 *  \param[in] max_bytes the largest size accepted
 */
void
requireReadableFile (const std::string& path, std::uintmax_t max_bytes = std::numeric_limits<std::uintmax_t>::max ());

/** \brief Throws IoError naming \a path if a file cannot be written there: its folder is missing, is not a folder or
 *  is not writable, or \a path is itself a folder. Run before long work, so that a bad output path fails at once.
 *  \param[in] path the file to be written
 */
void
requireWritableOutput (const std::string& path);

/** \brief Lower-case extension of \a path including the dot (".ply"), or "" if none.
 *  \param[in] path a file name
 *  \return the extension
 */
std::string
fileExtension (const std::string& path);

/** \brief Throws IoError naming \a path if its extension is not one of \a allowed (e.g. ".ply .obj").
 *  \param[in] path the file to check
 *  \param[in] allowed the accepted extensions, space-separated, with their dots
 *  \param[in] what what the file should hold (e.g. "mesh"), for the message
 */
void
requireExtension (const std::string& path, const std::string& allowed, const std::string& what);

/** \brief Runs a PCL reader or writer \a call on \a path; turns the exceptions PCL throws (its own, and standard
 *  ones such as the std::out_of_range its OBJ reader throws on some malformed lines) into IoError naming the file,
 *  and returns the call's status.
 *  \param[in] path the file the call reads or writes, for the message
 *  \param[in] call the PCL reader or writer, returning its status
 *  \return the call's status
 */

template <typename Call>
int
callPclIo (const std::string& path, Call call)
{
  try {
    return call ();
  }
  catch (const Error&) {
    throw;
  }
  catch (const pcl::PCLException& e) {
    throw IoError (path + ": " + e.detailedMessage ());
  }
  catch (const std::exception& e) {
    throw IoError (path + ": the reader failed (" + e.what () + ")");
  }
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file file_checks.h
 *  \brief Small checks shared by the readers and writers: clear errors before a library reader fails obscurely.
 */
#include <morphreg/common/error.h>

#include <exception>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief Throws IoError naming \a path if it does not exist, is a directory, or cannot be opened for reading.
 *  \param[in] path the file to check
 */
void
requireReadableFile (const std::string& path);

/** \brief Throws IoError naming \a path if a file cannot be written there: its folder is missing, is not a folder or
 *  is not writable, or \a path is itself a folder. Run before long work, so that a bad output path fails at once.
 *  \param[in] path the file to be written
 */
void
requireWritableOutput (const std::string& path);

/** \brief Throws InvalidInputError if \a output is the same file as one of \a inputs (by path or hard link): writing
 *  it would destroy that input.
 *  \param[in] output the file to be written
 *  \param[in] inputs the files the run reads (empty names are skipped)
 */
void
requireNotAnInput (const std::string& output, const std::vector<std::string>& inputs);

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

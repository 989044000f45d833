#pragma once
/** \file file_checks.h
 *  \brief Small checks shared by the readers and writers: clear errors before a library reader fails obscurely.
 */
#include <morphreg/common/error.h>

#include <exception>
#include <string>

namespace morphreg
{
/** \brief Throws IoError naming \a path if it does not exist, is a directory, or cannot be opened for reading.
 *  \param[in] path the file to check
 */
void
requireReadableFile (const std::string& path);

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

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file error.h
 *  \brief The morphreg exception hierarchy. Every error names the input and what was wrong with it.
 */
#include <pcl/exceptions.h>

#include <string>

namespace morphreg
{
/** \brief Base of every exception morphreg throws; a pcl::PCLException, so PCL pipelines catch it too. */
class Error : public pcl::PCLException
{
public:
  /** \brief An error whose text is \a message.
   *  \param[in] message what was wrong, naming the input
   */
  explicit Error (const std::string& message) : pcl::PCLException (message), message_ (message) {}

  /** \brief The message alone (PCLException's own text starts with ": " when no source location is given).
   *  \return the message given to the constructor
   */

  const char*
  what () const noexcept override
  {
    return message_.c_str ();
  }

private:
  std::string message_;
};

/** \brief Invalid arguments or data: empty or NaN clouds, mismatched or degenerate landmarks, bad parameters. */
class InvalidInputError : public Error
{
public:
  using Error::Error;
};

/** \brief A registration lost its target: too few correspondences were left to determine the unknowns (a scan in
 *  the wrong unit or far from the start pose, or a max correspondence distance too small). An InvalidInputError,
 *  since it is the input that cannot be registered as given. The one rule for how many are too few, shared by every
 *  fit, is requireEnoughRows in fitting/pose_shape_least_squares.h.
 */
class TooFewCorrespondencesError : public InvalidInputError
{
public:
  using InvalidInputError::InvalidInputError;
};

/** \brief A file is missing, unreadable or cannot be written. */
class IoError : public Error
{
public:
  using Error::Error;
};

/** \brief A file was read but its content is corrupt, truncated or has the wrong shape. */
class FormatError : public IoError
{
public:
  using IoError::IoError;
};

/** \brief A computation cannot give a trustworthy answer (singular or ill-conditioned system, divergence). */
class NumericalError : public Error
{
public:
  using Error::Error;
};

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file npy_reader.h
 *  \brief A validating reader for NumPy .npy files holding little-endian float32 arrays (the shared data's
 *  model bases and eigenvalues), so a truncated or mislabelled file is an error, never garbage.
 */
#include <cstddef>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief An n-dimensional float32 array in C (row-major) order, as stored in a .npy file. */
struct NpyArray
{
  std::vector<std::size_t> shape; ///< the size of each dimension
  std::vector<float> data;        ///< the elements, last index fastest

  /** \brief Number of elements (the product of \a shape; 1 for a 0-d array).
   *  \return data.size ()
   */
  std::size_t
  size () const
  {
    return data.size ();
  }
};

/** \brief Reads a .npy file (format 1.0, 2.0 or 3.0) of dtype '<f4' in C order.
 *  Throws IoError if the file is missing or unreadable, FormatError naming the file and the problem if the
 *  magic, header, dtype or order is wrong, if the data is shorter or longer than the shape says, or if a
 *  value is NaN or infinite.
 *  \param[in] path the .npy file
 *  \return its shape and elements
 */
NpyArray
readNpyFloat32 (const std::string& path);

/** \brief Throws FormatError naming \a path and both shapes unless \a array has exactly \a expected_shape.
 *  \param[in] array the array read
 *  \param[in] expected_shape the shape it must have
 *  \param[in] path the file it was read from, for the message
 */

void
requireNpyShape (const NpyArray& array, const std::vector<std::size_t>& expected_shape, const std::string& path);

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private helpers over HDF5's C++ API for the model files: every failure becomes a morphreg error that names the
// file, the dataset and the problem.
#include <morphreg/common/error.h>

#include <Eigen/Core>
#include <H5Cpp.h>

#include <string>
#include <vector>

namespace morphreg
{
namespace hdf5
{
/** \brief A numeric dataset as read: its dimensions and values in HDF5's row-major order. */
template <typename Scalar>
struct Array
{
  std::vector<hsize_t> dims;
  std::vector<Scalar> values;
};

/** \brief Read access to one HDF5 file with validating accessors. */
class Reader
{
public:
  /** \brief Opens \a path read-only; IoError if missing, FormatError if not a readable HDF5 file. */
  explicit Reader (const std::string& path);

  /** \brief True if every group along \a name exists (a relative path like "shape/model/mean"). */
  bool
  exists (const std::string& name) const;

  /** \brief A floating-point dataset (converted to double), checked to be finite and to have \a rank dims. */
  Array<double>
  readFloats (const std::string& name, int rank) const;

  /** \brief An integer dataset with \a rank dims. */
  Array<long long>
  readIntegers (const std::string& name, int rank) const;

  /** \brief The single value of a scalar (or one-element) numeric dataset. */
  double
  readScalar (const std::string& name) const;

  /** \brief A string dataset (variable or fixed length). */
  std::string
  readString (const std::string& name) const;

  /** \brief FormatError "<file>: dataset '<name>': <problem>". */
  [[noreturn]] void
  fail (const std::string& name, const std::string& problem) const;

  const std::string&
  path () const
  {
    return path_;
  }

private:
  /** \brief Opens dataset \a name of \a type_class (H5T_NO_CLASS: any number). */
  H5::DataSet
  open (const std::string& name, H5T_class_t type_class) const;

  /** \brief FormatError unless the global heap holding the variable-length string of the single-element \a dataset
   *  is intact (HDF5 1.10 hangs or crashes on a corrupt one); contiguous storage only.
   */
  void
  requireIntactStringHeap (const std::string& name, const H5::DataSet& dataset) const;

  template <typename Scalar>
  Array<Scalar>
  readArray (const std::string& name, int rank, H5T_class_t type_class, const H5::PredType& memory_type) const;

  std::string path_;
  H5::H5File file_;
};

/** \brief A new HDF5 file, built in memory and written to \a path, whole or not at all, by close() (a file that is not
 *  closed is not written); IoError naming the file on failure, a full disk included. */
class Writer
{
public:
  explicit Writer (const std::string& path);

  /** \brief Writes the finished file (writeFileAtomically()); IoError if it cannot be written. */
  void
  close ();

  /** \brief Creates the group \a name (parents must exist). */
  void
  group (const std::string& name);

  /** \brief A float32 (or float64 if \a double_precision) dataset of \a dims from row-major \a values. */
  void
  floats (const std::string& name, const std::vector<hsize_t>& dims, const double* values, bool double_precision);

  /** \brief An int32 dataset of \a dims from row-major \a values. */
  void
  integers (const std::string& name, const std::vector<hsize_t>& dims, const int* values);

  /** \brief A scalar int32 or float32 dataset. */
  void
  scalarInt (const std::string& name, int value);

  void
  scalarFloat (const std::string& name, double value);

  /** \brief A variable-length string dataset. */
  void
  string (const std::string& name, const std::string& value);

  /** \brief A variable-length string attribute of the group \a group. */
  void
  attribute (const std::string& group, const std::string& name, const std::string& value);

private:
  template <typename Call>
  void
  guarded (const std::string& name, Call call);

  std::string path_;
  H5::H5File file_;
};

} // namespace hdf5
} // namespace morphreg

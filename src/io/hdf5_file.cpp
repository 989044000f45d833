// SPDX-License-Identifier: BSD-3-Clause
#include "hdf5_file.h"

#include <morphreg/io/atomic_file.h>
#include <morphreg/io/file_checks.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <sstream>

namespace morphreg
{
namespace hdf5
{
namespace
{
std::string
dimsText (const std::vector<hsize_t>& dims)
{
  std::ostringstream text;
  text << '[';
  for (size_t i = 0; i < dims.size (); ++i)
    text << (i ? ", " : "") << dims[i];
  text << ']';
  return text.str ();
}

H5::H5File
openFile (const std::string& path)
{
  requireReadableFile (path);
  H5::Exception::dontPrint ();
  try {
    return H5::H5File (path, H5F_ACC_RDONLY);
  }
  catch (const H5::Exception& e) {
    throw FormatError (path + ": not a readable HDF5 file (corrupt or truncated): " + e.getDetailMsg ());
  }
}

/** A new HDF5 file held in memory (the core driver without a backing store): HDF5 never touches the disk, so a
 *  full disk cannot leave it in a failed state; close() writes the finished image. */
H5::H5File
createFileInMemory (const std::string& path)
{
  H5::Exception::dontPrint ();
  try {
    H5::FileAccPropList access;
    access.setCore (std::size_t (1) << 20, false);
    return H5::H5File (path, H5F_ACC_TRUNC, H5::FileCreatPropList::DEFAULT, access);
  }
  catch (const H5::Exception& e) {
    throw IoError (path + ": cannot create the HDF5 file: " + e.getDetailMsg ());
  }
}
/** \brief The \a size bytes of \a path from \a offset; none if the file ends before. */
std::vector<unsigned char>
readBytes (const std::string& path, std::uint64_t offset, std::uint64_t size)
{
  std::ifstream stream (path, std::ios::binary | std::ios::ate);
  const auto file_size = static_cast<std::uint64_t> (std::max<std::streamoff> (stream.tellg (), 0));
  if (!stream || offset > file_size || size > file_size - offset)
    return {};
  std::vector<unsigned char> bytes (size);
  stream.seekg (static_cast<std::streamoff> (offset));
  stream.read (reinterpret_cast<char*> (bytes.data ()), static_cast<std::streamsize> (size));
  return stream ? bytes : std::vector<unsigned char> ();
}

/** \brief The little-endian unsigned integer of \a size bytes at \a offset of \a bytes (which must hold them). */
std::uint64_t
decodeUnsigned (const std::vector<unsigned char>& bytes, std::size_t offset, std::size_t size)
{
  std::uint64_t value = 0;
  for (std::size_t i = size; i-- > 0;)
    value = (value << 8) | bytes[offset + i];
  return value;
}

/** \brief Where a variable-length string is kept: its length, and the global heap collection and object holding it. */
struct HeapReference
{
  std::uint64_t length = 0;
  std::uint64_t collection = 0;
  std::uint64_t object = 0;
};

/** \brief Walks the global heap collection at \a reference.collection (an address from \a base) as HDF5 will, and
 *  returns a problem if HDF5 would not read it safely ("" if it would): HDF5 1.10 trusts the collection, so an
 *  object size of 0 makes it loop forever and an object index past the collection's reads out of bounds.
 */
std::string
globalHeapProblem (const std::string& path, std::uint64_t base, const HeapReference& reference, std::size_t size_bytes)
{
  const std::size_t header_bytes = 8 + size_bytes;        // "GCOL", version, 3 reserved bytes, collection size
  const std::size_t object_header_bytes = 8 + size_bytes; // index, reference count, 4 reserved bytes, object size
  const std::vector<unsigned char> header = readBytes (path, base + reference.collection, header_bytes);
  if (header.size () < header_bytes || std::string (header.begin (), header.begin () + 4) != "GCOL")
    return "its global heap collection is missing";
  const std::uint64_t collection_bytes = decodeUnsigned (header, 8, size_bytes);
  if (collection_bytes < header_bytes)
    return "its global heap collection has an invalid size " + std::to_string (collection_bytes);
  const std::vector<unsigned char> collection = readBytes (path, base + reference.collection, collection_bytes);
  if (collection.size () != collection_bytes)
    return "its global heap collection runs past the end of the file";
  // The whole collection, as HDF5 reads it all.
  std::uint64_t found_bytes = 0;
  for (std::uint64_t at = header_bytes; at + object_header_bytes <= collection_bytes;) {
    const std::uint64_t index = decodeUnsigned (collection, at, 2);
    const std::uint64_t object_bytes = decodeUnsigned (collection, at + 8, size_bytes);
    // Index 0 is free space, whose size counts its header; an object's data is padded to 8 bytes.
    const std::uint64_t step = index == 0 ? object_bytes : object_header_bytes + (object_bytes + 7) / 8 * 8;
    if (object_bytes > collection_bytes || step < object_header_bytes || step > collection_bytes - at)
      return "its global heap collection is corrupt (object " + std::to_string (index) + " of " +
             std::to_string (object_bytes) + " bytes)";
    if (index != 0 && index == reference.object)
      found_bytes = object_bytes;
    at += step;
  }
  if (found_bytes != reference.length)
    return "its global heap object " + std::to_string (reference.object) +
           (found_bytes ? " does not hold " + std::to_string (reference.length) + " bytes" : " is missing");
  return "";
}
} // namespace

Reader::Reader (const std::string& path) : path_ (path), file_ (openFile (path)) {}

void
Reader::fail (const std::string& name, const std::string& problem) const
{
  throw FormatError (path_ + ": dataset '" + name + "': " + problem);
}

bool
Reader::exists (const std::string& name) const
{
  try {
    std::string prefix;
    std::istringstream parts (name);
    for (std::string part; std::getline (parts, part, '/');) {
      if (part.empty ())
        continue;
      prefix += (prefix.empty () ? "" : "/") + part;
      if (!file_.nameExists (prefix))
        return false;
    }
    return !prefix.empty ();
  }
  catch (const H5::Exception& e) {
    throw FormatError (path_ + ": a corrupt model file: its HDF5 group structure cannot be read at '" + name +
                       "' (HDF5: " + e.getDetailMsg () + ")");
  }
}

H5::DataSet
Reader::open (const std::string& name, H5T_class_t type_class) const
{
  if (!exists (name))
    fail (name, "missing");
  H5::DataSet dataset;
  H5T_class_t actual = H5T_NO_CLASS;
  try {
    dataset = file_.openDataSet (name);
    actual = dataset.getTypeClass ();
  }
  catch (const H5::Exception& e) {
    fail (name, "cannot be opened as a dataset: " + e.getDetailMsg ());
  }
  const bool numeric = actual == H5T_FLOAT || actual == H5T_INTEGER;
  if (actual != type_class && !(type_class == H5T_NO_CLASS && numeric))
    fail (name, type_class == H5T_FLOAT     ? "expected floating-point data"
                : type_class == H5T_INTEGER ? "expected integer data"
                : type_class == H5T_STRING  ? "expected a string"
                                            : "expected a number");
  return dataset;
}

template <typename Scalar>
Array<Scalar>
Reader::readArray (const std::string& name, int rank, H5T_class_t type_class, const H5::PredType& memory_type) const
{
  const H5::DataSet dataset = open (name, type_class);
  Array<Scalar> array;
  try {
    const H5::DataSpace space = dataset.getSpace ();
    const int actual_rank = space.getSimpleExtentNdims ();
    array.dims.resize (actual_rank);
    space.getSimpleExtentDims (array.dims.data ());
    if (actual_rank != rank)
      fail (name, "has " + std::to_string (actual_rank) + " dimensions " + dimsText (array.dims) + ", expected " +
                      std::to_string (rank));
    // The element count, checked before each product so that a huge extent cannot wrap it around to a small one.
    const hsize_t max_count = hsize_t (1) << 32;
    hsize_t count = 1;
    for (const hsize_t d : array.dims) {
      if (d != 0 && count > max_count / d)
        fail (name, "implausibly large " + dimsText (array.dims));
      count *= d;
    }
    array.values.resize (count);
    if (count > 0)
      dataset.read (array.values.data (), memory_type);
  }
  catch (const H5::Exception& e) {
    fail (name, "cannot be read (corrupt or truncated file?): " + e.getDetailMsg ());
  }
  return array;
}

Array<double>
Reader::readFloats (const std::string& name, int rank) const
{
  Array<double> array = readArray<double> (name, rank, H5T_FLOAT, H5::PredType::NATIVE_DOUBLE);
  for (size_t i = 0; i < array.values.size (); ++i)
    if (!std::isfinite (array.values[i]))
      fail (name, "element " + std::to_string (i) + " is not finite (NaN or Inf)");
  return array;
}

Array<long long>
Reader::readIntegers (const std::string& name, int rank) const
{
  return readArray<long long> (name, rank, H5T_INTEGER, H5::PredType::NATIVE_LLONG);
}

double
Reader::readScalar (const std::string& name) const
{
  const H5::DataSet dataset = open (name, H5T_NO_CLASS);
  double value = 0.0;
  try {
    if (dataset.getSpace ().getSimpleExtentNpoints () != 1)
      fail (name, "expected a single value, found " + std::to_string (dataset.getSpace ().getSimpleExtentNpoints ()));
    dataset.read (&value, H5::PredType::NATIVE_DOUBLE);
  }
  catch (const H5::Exception& e) {
    fail (name, "cannot be read: " + e.getDetailMsg ());
  }
  if (!std::isfinite (value))
    fail (name, "is not finite");
  return value;
}

std::string
Reader::readString (const std::string& name) const
{
  const H5::DataSet dataset = open (name, H5T_STRING);
  try {
    if (dataset.getSpace ().getSimpleExtentNpoints () != 1)
      fail (name, "expected a single string, found " + std::to_string (dataset.getSpace ().getSimpleExtentNpoints ()));
    if (dataset.getStrType ().isVariableStr ())
      requireIntactStringHeap (name, dataset);
    std::string value;
    dataset.read (value, dataset.getStrType ());
    return value;
  }
  catch (const H5::Exception& e) {
    fail (name, "cannot be read as a string: " + e.getDetailMsg ());
  }
}

void
Reader::requireIntactStringHeap (const std::string& name, const H5::DataSet& dataset) const
{
  const haddr_t offset = H5Dget_offset (dataset.getId ());
  if (offset == HADDR_UNDEF)
    return; // compact or chunked storage, whose raw data is not at one place in the file: left to HDF5
  std::size_t address_bytes = 0, size_bytes = 0;
  hsize_t user_block = 0;
  const H5::FileCreatPropList properties = file_.getCreatePlist ();
  H5Pget_sizes (properties.getId (), &address_bytes, &size_bytes);
  H5Pget_userblock (properties.getId (), &user_block);
  if (address_bytes > 8 || size_bytes > 8)
    fail (name, "unsupported HDF5 address or length size");
  // The string's raw data: its length (4 bytes), the collection's address and the object's index (4 bytes).
  const std::vector<unsigned char> raw = readBytes (path_, offset, 8 + address_bytes);
  if (raw.size () != 8 + address_bytes)
    fail (name, "its data runs past the end of the file");
  const HeapReference reference{decodeUnsigned (raw, 0, 4), decodeUnsigned (raw, 4, address_bytes),
                                decodeUnsigned (raw, 4 + address_bytes, 4)};
  if (reference.length == 0)
    return; // an empty string is not kept in the heap
  const std::string problem = globalHeapProblem (path_, user_block, reference, size_bytes);
  if (!problem.empty ())
    fail (name, "variable-length string: " + problem);
}

Writer::Writer (const std::string& path) : path_ (path), file_ (createFileInMemory (path)) {}

void
Writer::close ()
{
  std::string image;
  guarded ("the file", [&] {
    file_.flush (H5F_SCOPE_GLOBAL);
    const ssize_t size = H5Fget_file_image (file_.getId (), nullptr, 0);
    if (size < 0)
      throw H5::FileIException ("H5Fget_file_image", "cannot read the file image");
    image.resize (static_cast<std::size_t> (size));
    H5Fget_file_image (file_.getId (), image.data (), image.size ());
    file_.close ();
  });
  writeFileAtomically (path_, image);
}

template <typename Call>
void
Writer::guarded (const std::string& name, Call call)
{
  try {
    call ();
  }
  catch (const H5::Exception& e) {
    throw IoError (path_ + ": cannot write '" + name + "': " + e.getDetailMsg ());
  }
}

void
Writer::group (const std::string& name)
{
  guarded (name, [&] { file_.createGroup (name); });
}

void
Writer::floats (const std::string& name, const std::vector<hsize_t>& dims, const double* values, bool double_precision)
{
  guarded (name, [&] {
    const H5::DataSpace space (static_cast<int> (dims.size ()), dims.data ());
    H5::DataSet dataset =
        file_.createDataSet (name, double_precision ? H5::PredType::IEEE_F64LE : H5::PredType::IEEE_F32LE, space);
    if (space.getSimpleExtentNpoints () > 0)
      dataset.write (values, H5::PredType::NATIVE_DOUBLE);
  });
}

void
Writer::integers (const std::string& name, const std::vector<hsize_t>& dims, const int* values)
{
  guarded (name, [&] {
    const H5::DataSpace space (static_cast<int> (dims.size ()), dims.data ());
    H5::DataSet dataset = file_.createDataSet (name, H5::PredType::STD_I32LE, space);
    if (space.getSimpleExtentNpoints () > 0)
      dataset.write (values, H5::PredType::NATIVE_INT);
  });
}

void
Writer::scalarInt (const std::string& name, int value)
{
  guarded (name, [&] {
    H5::DataSet dataset = file_.createDataSet (name, H5::PredType::STD_I32LE, H5::DataSpace (H5S_SCALAR));
    dataset.write (&value, H5::PredType::NATIVE_INT);
  });
}

void
Writer::scalarFloat (const std::string& name, double value)
{
  guarded (name, [&] {
    H5::DataSet dataset = file_.createDataSet (name, H5::PredType::IEEE_F32LE, H5::DataSpace (H5S_SCALAR));
    dataset.write (&value, H5::PredType::NATIVE_DOUBLE);
  });
}

void
Writer::string (const std::string& name, const std::string& value)
{
  guarded (name, [&] {
    const H5::StrType type (H5::PredType::C_S1, H5T_VARIABLE);
    H5::DataSet dataset = file_.createDataSet (name, type, H5::DataSpace (H5S_SCALAR));
    dataset.write (value, type);
  });
}

void
Writer::attribute (const std::string& group, const std::string& name, const std::string& value)
{
  guarded (group + "@" + name, [&] {
    const H5::StrType type (H5::PredType::C_S1, H5T_VARIABLE);
    H5::Group target = file_.openGroup (group);
    H5::Attribute attribute = target.createAttribute (name, type, H5::DataSpace (H5S_SCALAR));
    attribute.write (type, value);
  });
}

} // namespace hdf5
} // namespace morphreg

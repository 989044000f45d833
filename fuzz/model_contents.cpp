// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target model_contents: a sound model file whose datasets' values come from the input, read by loadModel():
// the layout is always valid, so the fuzzer works on the contents (the mean and its copies, the bases, the
// triangles, the landmarks and regions), which the consistency checks must refuse or accept, never misread.
#include "fuzz_target.h"

#include <morphreg/io/model_io.h>
#include <morphreg/model/morphable_model.h>

#include <H5Cpp.h>

#include <cstdio>
#include <fstream>
#include <iterator>

namespace
{
/** A tetrahedron model of one region and two orthonormal components. */
morphreg::MorphableModel::Ptr
tetrahedron ()
{
  morphreg::TriangleMesh::Triangles triangles (3, 4);
  triangles << 0, 0, 0, 1, 1, 2, 3, 2, 2, 3, 1, 3;
  Eigen::VectorXd mean (12);
  mean << 0, 0, 0, 100, 0, 0, 0, 100, 0, 0, 0, 100;
  Eigen::MatrixXd basis = Eigen::MatrixXd::Zero (12, 2);
  basis (0, 0) = 1.0;
  basis (4, 1) = 1.0;
  return morphreg::MorphableModel::fromGlobalPca (triangles, mean, basis, Eigen::Vector2d (4.0, 1.0));
}

/** The datasets the input may overwrite, as raw bytes in their file type. */
const char* const kDatasets[] = {"model/mean",
                                 "morphreg/mean",
                                 "representer/points",
                                 "representer/cells",
                                 "model/pcaBasis",
                                 "model/pcaVariance",
                                 "morphreg/profileLine",
                                 "morphreg/regions/region_0/vertices",
                                 "morphreg/regions/region_0/weights",
                                 "morphreg/regions/region_0/basis",
                                 "morphreg/regions/region_0/variances"};

/** Overwrites the dataset chosen by the input's first byte with the rest of the input (repeated to its size). */
void
overwrite (const std::string& path, const std::string& input)
{
  if (input.size () < 2)
    return;
  H5::Exception::dontPrint ();
  H5::H5File file (path, H5F_ACC_RDWR);
  H5::DataSet dataset = file.openDataSet (kDatasets[static_cast<unsigned char> (input[0]) % std::size (kDatasets)]);
  const std::size_t bytes = dataset.getStorageSize ();
  std::string values (bytes, '\0');
  for (std::size_t k = 0; k < bytes; ++k)
    values[k] = input[1 + k % (input.size () - 1)];
  dataset.write (values.data (), dataset.getDataType ());
}

void
loadContents (const std::string& path)
{
  std::ifstream stream (path, std::ios::binary);
  const std::string input ((std::istreambuf_iterator<char> (stream)), {});
  const std::string model = path + ".h5";
  morphreg::saveModel (model, *tetrahedron ());
  try {
    overwrite (model, input);
    morphreg::loadModel (model);
  }
  catch (...) {
    std::remove (model.c_str ());
    throw;
  }
  std::remove (model.c_str ());
}

const bool registered = morphreg::fuzz::registerTarget ({"model_contents", ".bin", {loadContents}});
} // namespace

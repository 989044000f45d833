// SPDX-License-Identifier: BSD-3-Clause
// Every writer of the library under a full disk: a file size limit (RLIMIT_FSIZE, with SIGXFSZ ignored, so a write
// past it fails with EFBIG as on a full disk). Each must throw IoError naming the file and leave nothing behind.
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/model_io.h>
#include <morphreg/model/morphable_model.h>

#include "support/expect_error.h"
#include "support/temp_directory.h"
#include "support/test_meshes.h"

#include <gtest/gtest.h>

#include <sys/resource.h>

#include <csignal>
#include <filesystem>
#include <fstream>

using morphreg::test::expectErrorContaining;
using morphreg::test::TempDirectory;

namespace
{
/** Limits the size of files this process writes to \a bytes while it lives, as a full disk would. */
class FileSizeLimit
{
public:
  explicit FileSizeLimit (rlim_t bytes)
  {
    getrlimit (RLIMIT_FSIZE, &saved_);
    previous_handler_ = std::signal (SIGXFSZ, SIG_IGN);
    rlimit limited = saved_;
    limited.rlim_cur = bytes;
    setrlimit (RLIMIT_FSIZE, &limited);
  }
  ~FileSizeLimit ()
  {
    setrlimit (RLIMIT_FSIZE, &saved_);
    std::signal (SIGXFSZ, previous_handler_);
  }
  FileSizeLimit (const FileSizeLimit&) = delete;
  FileSizeLimit&
  operator= (const FileSizeLimit&) = delete;

private:
  rlimit saved_{};
  void (*previous_handler_) (int) = nullptr;
};

/** Runs \a write under a 1000-byte file size limit; expects an IoError naming \a path and an empty \a dir after. */
template <typename Write>
void
expectCleanWriteFailure (const TempDirectory& dir, const std::string& path, Write write)
{
  {
    const FileSizeLimit limit (1000);
    expectErrorContaining<morphreg::IoError> (write, path);
  }
  for (const auto& left : std::filesystem::directory_iterator (dir.file ("")))
    ADD_FAILURE () << "left behind: " << left.path ();
}

morphreg::TriangleMesh
largeMesh ()
{
  return morphreg::test::makeGrid (20); // well over 1000 bytes in every format
}
} // namespace

TEST (WriteFailureTest, JsonReport)
{
  TempDirectory dir;
  nlohmann::json document;
  for (int i = 0; i < 500; ++i)
    document["values"].push_back (i);
  const std::string path = dir.file ("report.json");
  expectCleanWriteFailure (dir, path, [&] { morphreg::writeJsonFile (path, document); });
}

TEST (WriteFailureTest, MeshInEveryFormat)
{
  TempDirectory dir;
  for (const std::string name : {"mesh.ply", "mesh.obj", "mesh.vtk"}) {
    const std::string path = dir.file (name);
    expectCleanWriteFailure (dir, path, [&] { morphreg::saveTriangleMesh (path, largeMesh ()); });
  }
}

TEST (WriteFailureTest, CloudInEveryFormat)
{
  TempDirectory dir;
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < 500; ++i)
    cloud.push_back ({static_cast<float> (i), 1.0f, 2.0f});
  for (const std::string name : {"cloud.pcd", "cloud.ply", "cloud.obj"}) {
    const std::string path = dir.file (name);
    expectCleanWriteFailure (dir, path, [&] { morphreg::saveCloud (path, cloud); });
  }
}

TEST (WriteFailureTest, Landmarks)
{
  TempDirectory dir;
  morphreg::LandmarkPositions landmarks;
  for (const std::string& id : morphreg::knownLandmarkIds ())
    landmarks[id] = Eigen::Vector3d (1234.56789, -2345.67891, 3456.78912); // every format over 1000 bytes
  for (const std::string name : {"landmarks.json", "landmarks.csv", "landmarks.pp"}) {
    const std::string path = dir.file (name);
    expectCleanWriteFailure (dir, path, [&] { morphreg::saveLandmarks (path, landmarks); });
  }
}

TEST (WriteFailureTest, ModelFile)
{
  TempDirectory dir;
  const morphreg::TriangleMesh mesh = largeMesh ();
  const Eigen::VectorXd mean = Eigen::Map<const Eigen::VectorXd> (mesh.vertices.data (), mesh.vertices.size ());
  const auto model = morphreg::MorphableModel::fromGlobalPca (
      mesh.triangles, mean, Eigen::MatrixXd::Identity (mean.size (), 2), Eigen::VectorXd::Ones (2));
  const std::string path = dir.file ("model.h5");
  expectCleanWriteFailure (dir, path, [&] { morphreg::saveModel (path, *model); });
}

TEST (WriteFailureTest, TheSameWritesSucceedWithoutTheLimit)
{
  TempDirectory dir;
  morphreg::saveTriangleMesh (dir.file ("mesh.ply"), largeMesh ());
  EXPECT_EQ (morphreg::loadTriangleMesh (dir.file ("mesh.ply")).numVertices (), largeMesh ().numVertices ());
  morphreg::writeJsonFile (dir.file ("report.json"), {{"a", 1}});
  EXPECT_EQ (morphreg::readJsonFile (dir.file ("report.json"))["a"], 1);
}

// SPDX-License-Identifier: BSD-3-Clause
// morphreg's PCD reader: valid files (morphreg's, PCL's writers', the shared PCL test files) read exactly as PCL's
// reader reads them, and malformed ones are refused with the file, the line where there is one, and the problem.
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/file_validation.h>
#include <morphreg/io/pcd_reader.h>

#include "support/expect_error.h"
#include "support/temp_directory.h"
#include "support/text_file.h"

#include <gtest/gtest.h>
#include <pcl/io/pcd_io.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>

using morphreg::test::expectErrorContaining;
using morphreg::test::readBytes;
using morphreg::test::TempDirectory;
using morphreg::test::writeText;

namespace
{
/** Coloured points with normals in a 4 x 3 grid, one of them NaN, seen from a viewpoint other than the origin. */
pcl::PointCloud<pcl::PointXYZRGBNormal>
makeOrganisedCloud ()
{
  pcl::PointCloud<pcl::PointXYZRGBNormal> cloud (4, 3);
  for (std::size_t i = 0; i < cloud.size (); ++i) {
    auto& p = cloud[i];
    p.getVector3fMap () = Eigen::Vector3f (0.1f * i, -1.0f / (i + 1), 100.0f + 0.3f * i);
    p.getNormalVector3fMap () = Eigen::Vector3f (0.0f, 0.6f, 0.8f);
    p.r = static_cast<std::uint8_t> (20 * i), p.g = 7, p.b = static_cast<std::uint8_t> (255 - i);
    p.curvature = 0.01f * i;
  }
  cloud[5].x = cloud[5].y = cloud[5].z = std::numeric_limits<float>::quiet_NaN ();
  cloud.sensor_origin_ = Eigen::Vector4f (1.5f, -2.0f, 30.0f, 0.0f);
  cloud.sensor_orientation_ = Eigen::Quaternionf (0.6f, 0.0f, 0.8f, 0.0f);
  return cloud;
}

/** Expects readPcdFile to give for \a path what PCL's reader gives: fields, layout, density, bytes and viewpoint. */
void
expectReadAsPclReadsIt (const std::string& path)
{
  SCOPED_TRACE (path);
  pcl::PCLPointCloud2 expected;
  Eigen::Vector4f origin;
  Eigen::Quaternionf orientation;
  ASSERT_EQ (pcl::io::loadPCDFile (path, expected, origin, orientation), 0);
  const morphreg::PcdCloud read = morphreg::readPcdFile (path);
  ASSERT_EQ (read.cloud.fields.size (), expected.fields.size ());
  for (std::size_t f = 0; f < expected.fields.size (); ++f) {
    EXPECT_EQ (read.cloud.fields[f].name, expected.fields[f].name);
    EXPECT_EQ (read.cloud.fields[f].offset, expected.fields[f].offset) << expected.fields[f].name;
    EXPECT_EQ (read.cloud.fields[f].datatype, expected.fields[f].datatype) << expected.fields[f].name;
    EXPECT_EQ (read.cloud.fields[f].count, expected.fields[f].count) << expected.fields[f].name;
  }
  EXPECT_EQ (read.cloud.width, expected.width);
  EXPECT_EQ (read.cloud.height, expected.height);
  EXPECT_EQ (read.cloud.point_step, expected.point_step);
  EXPECT_EQ (read.cloud.row_step, expected.row_step);
  EXPECT_EQ (read.cloud.is_dense, expected.is_dense);
  EXPECT_TRUE (read.cloud.data == expected.data) << "the points' bytes differ";
  EXPECT_EQ (read.origin, origin);
  EXPECT_EQ (read.orientation.coeffs (), orientation.coeffs ());
}

/** Byte for byte equal points (NaN included). */
template <typename PointT>
void
expectSamePoints (const pcl::PointCloud<PointT>& a, const pcl::PointCloud<PointT>& b)
{
  ASSERT_EQ (a.size (), b.size ());
  EXPECT_EQ (a.width, b.width);
  EXPECT_EQ (a.height, b.height);
  EXPECT_EQ (a.is_dense, b.is_dense);
  EXPECT_EQ (a.sensor_origin_, b.sensor_origin_);
  for (std::size_t i = 0; i < a.size (); ++i)
    EXPECT_EQ (std::memcmp (&a[i], &b[i], sizeof (PointT)), 0) << "point " << i;
}

/** Expects reading \a name (written with \a bytes in \a dir) to fail with a FormatError holding \a fragment after
 *  the file's path, both in the loader and in validateGeometryFile. */
void
expectRefused (const TempDirectory& dir, const std::string& name, const std::string& bytes, const std::string& fragment)
{
  const std::string path = dir.file (name);
  writeText (path, bytes);
  SCOPED_TRACE (name);
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadCloud<pcl::PointXYZ> (path); }, path + fragment);
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::validateGeometryFile (path); }, path + fragment);
}

/** \a bytes with the 32-bit little-endian number at \a at set to \a value. */
std::string
withNumber (std::string bytes, std::size_t at, std::uint32_t value)
{
  for (int i = 0; i < 4; ++i)
    bytes[at + i] = static_cast<char> ((value >> (8 * i)) & 0xffu);
  return bytes;
}

const std::string xyz_fields = "VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\n";
const std::string two_points = "WIDTH 2\nHEIGHT 1\nVIEWPOINT 0 0 0 1 0 0 0\nPOINTS 2\n";
} // namespace

TEST (PcdReaderTest, CloudsWrittenByMorphregAndPclReadAsPclReadsThem)
{
  TempDirectory dir;
  const auto cloud = makeOrganisedCloud ();
  morphreg::saveCloud (dir.file ("morphreg.pcd"), cloud);
  pcl::io::savePCDFileASCII (dir.file ("ascii.pcd"), cloud);
  pcl::io::savePCDFileBinary (dir.file ("binary.pcd"), cloud);
  pcl::io::savePCDFileBinaryCompressed (dir.file ("compressed.pcd"), cloud);
  for (const std::string name : {"morphreg.pcd", "ascii.pcd", "binary.pcd", "compressed.pcd"}) {
    const std::string path = dir.file (name);
    expectReadAsPclReadsIt (path);
    pcl::PointCloud<pcl::PointXYZRGBNormal> by_pcl;
    pcl::io::loadPCDFile (path, by_pcl);
    expectSamePoints (*morphreg::loadCloud<pcl::PointXYZRGBNormal> (path), by_pcl);
    pcl::PointCloud<pcl::PointXYZ> xyz_by_pcl;
    pcl::io::loadPCDFile (path, xyz_by_pcl);
    expectSamePoints (*morphreg::loadCloud<pcl::PointXYZ> (path), xyz_by_pcl);
  }
  const auto loaded = morphreg::loadCloud<pcl::PointXYZRGBNormal> (dir.file ("compressed.pcd"));
  EXPECT_EQ (loaded->height, 3u);
  EXPECT_FALSE (loaded->is_dense);
  EXPECT_EQ ((*loaded)[11].b, 244);
  EXPECT_EQ (loaded->sensor_origin_, cloud.sensor_origin_);
}

TEST (PcdReaderTest, EveryTypeSizeAndCountReadsAsPclReadsIt)
{
  TempDirectory dir;
  writeText (dir.file ("types.pcd"), "# every kind of field\nVERSION .7\nFIELDS x y z label weight histogram _\n"
                                     "SIZE 4 4 4 2 1 8 1\nTYPE F F F U I F U\nCOUNT 1 1 1 1 1 3 2\nWIDTH 3\nHEIGHT 1\n"
                                     "POINTS 3\nDATA ascii\n1.5 -2.25 1e-3 65535 -128 0.1 0.2 1e300 0 0\n\n"
                                     "+4 nan 6 0 127 -1e-300 inf 3 0 0\n7 8 9 12 0 0 0 0 0 0\n");
  pcl::PCLPointCloud2 blob;
  ASSERT_EQ (pcl::io::loadPCDFile (dir.file ("types.pcd"), blob), 0);
  pcl::PCDWriter writer;
  writer.writeBinary (dir.file ("types_binary.pcd"), blob);
  writer.writeBinaryCompressed (dir.file ("types_compressed.pcd"), blob);
  for (const std::string name : {"types.pcd", "types_binary.pcd", "types_compressed.pcd"})
    expectReadAsPclReadsIt (dir.file (name));
  const morphreg::PcdCloud read = morphreg::readPcdFile (dir.file ("types.pcd"));
  EXPECT_EQ (read.cloud.point_step, 4u * 3 + 2 + 1 + 8 * 3 + 2);
  EXPECT_FALSE (read.cloud.is_dense);
  std::int8_t weight = 0;
  std::memcpy (&weight, read.cloud.data.data () + read.cloud.point_step + 14, 1);
  EXPECT_EQ (weight, 127);
  double histogram[3];
  std::memcpy (histogram, read.cloud.data.data () + 15, sizeof (histogram));
  EXPECT_DOUBLE_EQ (histogram[2], 1e300);
  // A float too small for 4 bytes reads as 0, as a stream reads it.
  writeText (dir.file ("tiny.pcd"), xyz_fields + "WIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1e-50 -1e-60 1.4e-45\n");
  const auto tiny = morphreg::loadCloud<pcl::PointXYZ> (dir.file ("tiny.pcd"));
  EXPECT_EQ ((*tiny)[0].x, 0.0f);
  EXPECT_GT ((*tiny)[0].z, 0.0f);
}

TEST (PcdReaderTest, BinaryDataThatLooksLikeHeaderLinesIsData)
{
  // PCL's header parser reads on after DATA, so such bytes redefined its fields and points (the fuzzer's crashes).
  TempDirectory dir;
  const std::string data = "\nFIELDS a\nPOINTS 999999\n"; // 2 points of 12 bytes
  ASSERT_EQ (data.size (), 24u);
  writeText (dir.file ("lines.pcd"), xyz_fields + two_points + "DATA binary\n" + data);
  const auto cloud = morphreg::loadCloud<pcl::PointXYZ> (dir.file ("lines.pcd"));
  ASSERT_EQ (cloud->size (), 2u);
  float z = 0.0f;
  std::memcpy (&z, data.data () + 20, 4);
  EXPECT_EQ (std::memcmp (&(*cloud)[1].z, &z, 4), 0);
}

TEST (PcdReaderTest, SharedPclTestFilesReadAsPclReadsThem)
{
  const std::filesystem::path folder = std::filesystem::path (MORPHREG_SHARED_DATA_DIR) / "pcl_test";
  if (!std::filesystem::exists (folder))
    GTEST_SKIP () << "shared data not found at " << folder;
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator (folder))
    if (entry.path ().extension () == ".pcd") {
      expectReadAsPclReadsIt (entry.path ().string ());
      ++files;
    }
  EXPECT_GE (files, 3) << "ascii, binary and binary_compressed files expected";
}

TEST (PcdReaderTest, MalformedHeadersAreRefusedWithTheLine)
{
  TempDirectory dir;
  const std::string ascii = "DATA ascii\n0 0 0\n1 2 3\n";
  expectRefused (dir, "size_count.pcd", "FIELDS x y z\nSIZE 4 4\nTYPE F F F\n" + two_points + ascii,
                 ": the PCD header lists 3 FIELDS but 2 SIZE, 3 TYPE and 3 COUNT values");
  expectRefused (dir, "type_count.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F F\n" + two_points + ascii,
                 ": the PCD header lists 3 FIELDS but 3 SIZE, 4 TYPE and 3 COUNT values");
  expectRefused (dir, "count_count.pcd", xyz_fields + "COUNT 1 1\n" + two_points + ascii,
                 ":6: COUNT appears more than once in the PCD header");
  expectRefused (dir, "count_short.pcd", "FIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1\n" + two_points + ascii,
                 ": the PCD header lists 3 FIELDS but 3 SIZE, 3 TYPE and 1 COUNT values");
  expectRefused (dir, "no_fields.pcd", "VERSION 0.7\n" + two_points + ascii, ": the PCD header has no FIELDS");
  expectRefused (dir, "size_3.pcd", "FIELDS x\nSIZE 3\nTYPE F\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA binary\n123",
                 ": PCD field 'x' has TYPE F and SIZE 3, which is not a valid pair (F 4|8, I or U 1|2|4|8)");
  expectRefused (dir, "size_16.pcd", "FIELDS x\nSIZE 16\n", ":2: SIZE value '16' is not a whole number in [1, 8]");
  expectRefused (dir, "type_word.pcd", "FIELDS x\nSIZE 4\nTYPE Float\nWIDTH 1\nHEIGHT 1\nPOINTS 1\nDATA ascii\n1\n",
                 ": PCD field 'x' has TYPE Float and SIZE 4");
  expectRefused (dir, "twice.pcd", "FIELDS x x z\nSIZE 4 4 4\nTYPE F F F\n" + two_points + ascii,
                 ": PCD field 'x' is listed twice in FIELDS");
  expectRefused (dir, "area.pcd", xyz_fields + "WIDTH 2\nHEIGHT 2\nPOINTS 2\n" + ascii,
                 ": the PCD header's WIDTH 2 times HEIGHT 2 is not its POINTS 2");
  expectRefused (dir, "area_wraps.pcd", xyz_fields + "WIDTH 4294967296\nHEIGHT 4294967296\nPOINTS 0\n" + ascii,
                 ": the PCD header's WIDTH 4294967296 times HEIGHT 4294967296 is not its POINTS 0");
  expectRefused (dir, "no_height.pcd", xyz_fields + "WIDTH 2\nPOINTS 2\n" + ascii,
                 ": the PCD header has no HEIGHT line");
  expectRefused (dir, "no_points.pcd", xyz_fields + "WIDTH 0\nHEIGHT 1\nPOINTS 0\nDATA binary\n",
                 ": the PCD file holds no points (POINTS 0)");
  expectRefused (dir, "data_kind.pcd", xyz_fields + two_points + "DATA binary_lzma\n",
                 ":10: the DATA line must be 'DATA ascii', 'DATA binary' or 'DATA binary_compressed'");
  expectRefused (dir, "viewpoint.pcd", xyz_fields + "VIEWPOINT 0 0 0 1 0 nan 0\n",
                 ":6: VIEWPOINT must be followed by 7 finite numbers");
  expectRefused (dir, "negative.pcd", xyz_fields + "WIDTH -2\n", ":6: WIDTH value '-2' is not a whole number");
  expectRefused (dir, "no_x.pcd", "FIELDS a y z\nSIZE 4 4 4\nTYPE F F F\n" + two_points + ascii,
                 ": the PCD file has no field 'x' of TYPE F, SIZE 4 and COUNT 1, which the points' positions are read "
                 "from");
  expectRefused (dir, "double_z.pcd", "FIELDS x y z\nSIZE 4 4 8\nTYPE F F F\n" + two_points + ascii,
                 ": the PCD file has no field 'z' of TYPE F, SIZE 4 and COUNT 1");
}

TEST (PcdReaderTest, HeadersClaimingMoreThanTheFileHoldsAreRefusedBeforeAllocating)
{
  TempDirectory dir;
  const std::string huge = "WIDTH 4611686018427387904\nHEIGHT 1\nPOINTS 4611686018427387904\n";
  expectRefused (dir, "huge_binary.pcd", xyz_fields + huge + "DATA binary\n0123456789ab",
                 ": header claims 4611686018427387904 points (at least 55.3 EB) but the file holds 12 bytes");
  expectRefused (dir, "huge_ascii.pcd", xyz_fields + huge + "DATA ascii\n1 2 3\n",
                 ": header claims 4611686018427387904 points");
  expectRefused (dir, "huge_compressed.pcd",
                 xyz_fields + huge + "DATA binary_compressed\n" + withNumber (withNumber ("01234567", 0, 4), 4, 12) +
                     "abcd",
                 ": the compressed PCD data unpacks to 12 bytes but POINTS 4611686018427387904 of 12 bytes need");
  // Data that fits in the file but not in a PCL cloud (sparse files: nothing is written or read).
  const std::string bytes_header =
      "FIELDS b\nSIZE 1\nTYPE U\nWIDTH 2147483648\nHEIGHT 1\nPOINTS 2147483648\nDATA binary\n";
  writeText (dir.file ("many.pcd"), bytes_header);
  std::filesystem::resize_file (dir.file ("many.pcd"), bytes_header.size () + (1ull << 31));
  expectErrorContaining<morphreg::FormatError> (
      [&] { morphreg::readPcdFile (dir.file ("many.pcd")); },
      dir.file ("many.pcd") + ": the PCD file holds 2147483648 points, more than the 2147483647 of a PCL cloud");
  const std::string row_header = "FIELDS d\nSIZE 8\nTYPE F\nWIDTH 600000000\nHEIGHT 1\nPOINTS 600000000\nDATA binary\n";
  writeText (dir.file ("wide.pcd"), row_header);
  std::filesystem::resize_file (dir.file ("wide.pcd"), row_header.size () + 4800000000ull);
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::readPcdFile (dir.file ("wide.pcd")); },
                                                dir.file ("wide.pcd") + ": a row of the PCD cloud (WIDTH 600000000 "
                                                                        "points of 8 bytes) takes more than the 4 GB");
}

TEST (PcdReaderTest, CutAndLyingBinaryDataIsRefused)
{
  TempDirectory dir;
  pcl::PointCloud<pcl::PointNormal> cloud (20, 1);
  for (std::size_t i = 0; i < cloud.size (); ++i)
    cloud[i].getVector3fMap () = Eigen::Vector3f (1.0f * i, 2.0f, 3.0f);
  morphreg::saveCloud (dir.file ("cloud.pcd"), cloud);
  const std::string binary = readBytes (dir.file ("cloud.pcd"));
  expectRefused (dir, "cut_binary.pcd", binary.substr (0, binary.size () - 1),
                 ": header claims 20 points (at least 560 bytes) but the file holds 559 bytes after its header");

  pcl::io::savePCDFileBinaryCompressed (dir.file ("compressed.pcd"), cloud);
  const std::string compressed = readBytes (dir.file ("compressed.pcd"));
  const std::size_t sizes = compressed.find ("DATA binary_compressed\n") + 23;
  const std::uint32_t packed = static_cast<std::uint32_t> (compressed.size () - sizes - 8);
  expectRefused (dir, "more_packed.pcd", withNumber (compressed, sizes, packed + 1),
                 ": the compressed PCD data claims " + std::to_string (packed + 1) + " bytes but the file holds " +
                     std::to_string (packed) + " after its header");
  expectRefused (dir, "fewer_packed.pcd", withNumber (compressed, sizes, packed - 5),
                 ": the compressed PCD data is corrupt: it unpacks to ");
  expectRefused (dir, "more_unpacked.pcd", withNumber (compressed, sizes + 4, 564),
                 ": the compressed PCD data unpacks to 564 bytes but POINTS 20 of 28 bytes need 560 bytes");
  expectRefused (dir, "expansion.pcd", withNumber (withNumber (compressed, sizes, 2), sizes + 4, 560),
                 ": the compressed PCD data (2 bytes) cannot unpack to the 560 bytes its header claims");
  std::string back_reference = compressed; // the first LZF instruction refers back before the start
  back_reference[sizes + 8] = static_cast<char> (0x20);
  expectRefused (dir, "corrupt.pcd", back_reference, ": the compressed PCD data is corrupt");
  expectRefused (dir, "no_sizes.pcd", compressed.substr (0, sizes + 7),
                 ": the compressed PCD data has no sizes (the file is cut short)");
}

TEST (PcdReaderTest, MalformedAsciiPointsAreRefusedWithTheLine)
{
  TempDirectory dir;
  const std::string header = "FIELDS x y z label\nSIZE 4 4 4 1\nTYPE F F F U\n" + two_points + "DATA ascii\n";
  const std::string second = "1 1 1 1\n";
  expectRefused (dir, "word.pcd", header + "0 0 0 1\n1 1 1 one\n",
                 ":10: value 'one' of point 1 is not a number of its field's TYPE U and SIZE 1");
  expectRefused (dir, "range.pcd", header + "0 0 0 256\n" + second,
                 ":9: value '256' of point 0 is not a number of its field's TYPE U and SIZE 1");
  expectRefused (dir, "negative.pcd", header + "0 0 0 -1\n" + second, ":9: value '-1' of point 0 is not a number");
  expectRefused (dir, "fraction.pcd", header + "0 0 0 1.5\n" + second, ":9: value '1.5' of point 0 is not a number");
  expectRefused (dir, "float_range.pcd", header + "1e39 0 0 1\n" + second,
                 ":9: value '1e39' of point 0 is not a number of its field's TYPE F and SIZE 4");
  expectRefused (dir, "columns.pcd", header + "0 0 0 1 2\n" + second, ":9: point 0 has 5 values, expected 4");
  expectRefused (dir, "cut.pcd", header + "0.125000 0.5 0.5 1\n",
                 ": the file ends after 1 of its 2 points (the data is cut short)");
}

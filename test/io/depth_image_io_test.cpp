// SPDX-License-Identifier: BSD-3-Clause
// Depth images (16-bit greyscale PNG, mm) and depth-camera intrinsics (JSON): round trips, and every bad file named
// with its problem before a pixel is decoded.
#include <morphreg/common/error.h>
#include <morphreg/io/depth_image_io.h>

#include "support/expect_error.h"
#include "support/temp_directory.h"
#include "support/text_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace
{
using morphreg::test::expectErrorContaining;
using morphreg::test::TempDirectory;

morphreg::DepthImage
gradient (int width, int height)
{
  morphreg::DepthImage image{width, height, {}};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x)
      image.depth.push_back (static_cast<std::uint16_t> ((x * 37 + y * 1009) % 65536));
  return image;
}

TEST (DepthImageIoTest, SixteenBitPngRoundTripsEveryDepth)
{
  TempDirectory dir;
  const morphreg::DepthImage image = gradient (97, 41);
  morphreg::saveDepthPng (dir.file ("depth.png"), image);
  const morphreg::DepthImage read = morphreg::loadDepthPng (dir.file ("depth.png"));
  EXPECT_EQ (read.width, 97);
  EXPECT_EQ (read.height, 41);
  EXPECT_EQ (read.depth, image.depth);
}

TEST (DepthImageIoTest, BadFilesAreNamedWithTheirProblem)
{
  TempDirectory dir;
  morphreg::saveDepthPng (dir.file ("depth.png"), gradient (200, 100));
  const auto size = std::filesystem::file_size (dir.file ("depth.png"));
  std::filesystem::copy_file (dir.file ("depth.png"), dir.file ("cut.png"));
  std::filesystem::resize_file (dir.file ("cut.png"), size / 2);
  morphreg::test::writeText (dir.file ("text.png"), "not an image\n");
  expectErrorContaining<morphreg::IoError> ([&] { morphreg::loadDepthPng (dir.file ("missing.png")); }, "missing.png");
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadDepthPng (dir.file ("text.png")); },
                                                "text.png: not a PNG file");
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadDepthPng (dir.file ("cut.png")); },
                                                "cut.png: a corrupt or truncated PNG");
}

/** A PNG whose header declares \a width x \a height (CRC correct) followed by no image data. */
void
writeHeaderOnlyPng (const std::string& path, std::uint32_t width, std::uint32_t height, int bit_depth, int colour)
{
  unsigned char ihdr[17] = {'I', 'H', 'D', 'R'};
  for (int i = 0; i < 4; ++i) {
    ihdr[4 + i] = static_cast<unsigned char> (width >> (24 - 8 * i));
    ihdr[8 + i] = static_cast<unsigned char> (height >> (24 - 8 * i));
  }
  ihdr[12] = static_cast<unsigned char> (bit_depth);
  ihdr[13] = static_cast<unsigned char> (colour);
  std::uint32_t crc = 0xffffffffu; // the PNG CRC-32 of the chunk type and data
  for (unsigned char byte : ihdr) {
    crc ^= byte;
    for (int k = 0; k < 8; ++k)
      crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
  }
  crc ^= 0xffffffffu;
  std::ofstream out (path, std::ios::binary);
  const unsigned char head[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 0, 0, 0, 13};
  out.write (reinterpret_cast<const char*> (head), sizeof head);
  out.write (reinterpret_cast<const char*> (ihdr), sizeof ihdr);
  for (int i = 0; i < 4; ++i)
    out.put (static_cast<char> (crc >> (24 - 8 * i)));
}

TEST (DepthImageIoTest, HeadersAreCheckedBeforeDecoding)
{
  TempDirectory dir;
  writeHeaderOnlyPng (dir.file ("huge.png"), 100000, 100000, 16, 0);
  writeHeaderOnlyPng (dir.file ("claims_more.png"), 4000, 4000, 16, 0);
  writeHeaderOnlyPng (dir.file ("colour.png"), 64, 64, 8, 2);
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadDepthPng (dir.file ("huge.png")); }, "huge.png");
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadDepthPng (dir.file ("claims_more.png")); },
                                                "bytes cannot hold the 4000 x 4000 image its header declares");
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadDepthPng (dir.file ("colour.png")); },
                                                "must be a 16-bit greyscale PNG");
}

TEST (DepthImageIoTest, IntrinsicsAreReadAndValidated)
{
  TempDirectory dir;
  morphreg::test::writeText (dir.file ("camera.json"),
                             R"({"width": 640, "height": 480, "fx": 575.8, "fy": 576.1, "cx": 314.5, "cy": 235.5})");
  const morphreg::DepthIntrinsics k = morphreg::loadDepthIntrinsics (dir.file ("camera.json"));
  EXPECT_EQ (k.width, 640);
  EXPECT_EQ (k.height, 480);
  EXPECT_DOUBLE_EQ (k.fx, 575.8);
  EXPECT_DOUBLE_EQ (k.cy, 235.5);
  for (const auto& [text, problem] : std::vector<std::pair<std::string, std::string>>{
           {R"({"width": 640, "height": 480, "fx": 575, "fy": 575, "cx": 320})", "\"cy\" is missing"},
           {R"({"width": 640.5, "height": 480, "fx": 575, "fy": 575, "cx": 320, "cy": 240})", "\"width\" must be"},
           {R"({"width": 640, "height": 480, "fx": -1, "fy": 575, "cx": 320, "cy": 240})", "must be positive"},
           {R"([1, 2, 3])", "must be a JSON object"}}) {
    morphreg::test::writeText (dir.file ("bad.json"), text);
    expectErrorContaining<morphreg::Error> ([&] { morphreg::loadDepthIntrinsics (dir.file ("bad.json")); },
                                            "bad.json: ");
    expectErrorContaining<morphreg::Error> ([&] { morphreg::loadDepthIntrinsics (dir.file ("bad.json")); }, problem);
  }
}
} // namespace

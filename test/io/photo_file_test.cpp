// SPDX-License-Identifier: BSD-3-Clause
// Photos (PNG, JPEG) are checked from their header bytes and decoded whole before any work: grey and 16-bit PNGs
// become 8-bit RGB; corrupt, cut, empty, lying or special files are named with their problem.
#include <morphreg/common/error.h>
#include <morphreg/io/depth_image_io.h>
#include <morphreg/io/photo_file.h>

#include "support/expect_error.h"
#include "support/temp_directory.h"
#include "support/text_file.h"

#include <gtest/gtest.h>

#include <jpeglib.h>
#include <sys/stat.h>

#include <cstdio>
#include <filesystem>

namespace
{
using morphreg::test::expectErrorContaining;
using morphreg::test::TempDirectory;

/** Writes a \a width x \a height RGB JPEG of a smooth gradient with libjpeg. */
void
writeJpeg (const std::string& path, int width, int height)
{
  jpeg_compress_struct info;
  jpeg_error_mgr errors;
  info.err = jpeg_std_error (&errors);
  jpeg_create_compress (&info);
  std::FILE* file = std::fopen (path.c_str (), "wb");
  jpeg_stdio_dest (&info, file);
  info.image_width = static_cast<JDIMENSION> (width);
  info.image_height = static_cast<JDIMENSION> (height);
  info.input_components = 3;
  info.in_color_space = JCS_RGB;
  jpeg_set_defaults (&info);
  jpeg_set_quality (&info, 95, TRUE);
  jpeg_start_compress (&info, TRUE);
  std::vector<unsigned char> row (3 * static_cast<std::size_t> (width));
  while (info.next_scanline < info.image_height) {
    for (int x = 0; x < width; ++x)
      for (int c = 0; c < 3; ++c)
        row[3 * x + c] = static_cast<unsigned char> (40 * c + 2 * x + info.next_scanline);
    JSAMPROW pointer = row.data ();
    jpeg_write_scanlines (&info, &pointer, 1);
  }
  jpeg_finish_compress (&info);
  jpeg_destroy_compress (&info);
  std::fclose (file);
}

TEST (PhotoFileTest, SixteenBitGreyPngBecomesEightBitRgb)
{
  TempDirectory dir;
  morphreg::DepthImage image{3, 2, {0x1234, 0xFF00, 0x0001, 0x8080, 0x0000, 0xABCD}};
  morphreg::saveDepthPng (dir.file ("grey.png"), image);
  const morphreg::PhotoPixels photo = morphreg::loadPhotoFile (dir.file ("grey.png"));
  ASSERT_EQ (photo.width, 3);
  ASSERT_EQ (photo.height, 2);
  const std::vector<unsigned char> high = {0x12, 0xFF, 0x00, 0x80, 0x00, 0xAB};
  for (std::size_t k = 0; k < high.size (); ++k)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ (photo.rgb[3 * k + c], high[k]) << "pixel " << k << " channel " << c;
}

TEST (PhotoFileTest, JpegIsDecodedToItsPixels)
{
  TempDirectory dir;
  writeJpeg (dir.file ("photo.jpg"), 40, 24);
  const morphreg::PhotoPixels photo = morphreg::loadPhotoFile (dir.file ("photo.jpg"));
  ASSERT_EQ (photo.width, 40);
  ASSERT_EQ (photo.height, 24);
  ASSERT_EQ (photo.rgb.size (), 3u * 40 * 24);
  // Lossy, but close: pixel (10, 5), channel 2 was 80 + 20 + 5.
  EXPECT_NEAR (photo.rgb[3 * (5 * 40 + 10) + 2], 105, 6);
}

TEST (PhotoFileTest, BadPhotosAreNamedWithTheirProblem)
{
  TempDirectory dir;
  writeJpeg (dir.file ("photo.jpg"), 64, 64);
  std::filesystem::copy_file (dir.file ("photo.jpg"), dir.file ("cut.jpg"));
  std::filesystem::resize_file (dir.file ("cut.jpg"), std::filesystem::file_size (dir.file ("photo.jpg")) / 2);
  morphreg::saveDepthPng (dir.file ("grey.png"), {200, 100, std::vector<std::uint16_t> (20000, 7)});
  std::filesystem::copy_file (dir.file ("grey.png"), dir.file ("cut.png"));
  std::filesystem::resize_file (dir.file ("cut.png"), std::filesystem::file_size (dir.file ("grey.png")) - 20);
  morphreg::test::writeText (dir.file ("text.png"), "not an image\n");
  morphreg::test::writeText (dir.file ("empty.png"), "");
  ASSERT_EQ (::mkfifo (dir.file ("fifo.png").c_str (), 0600), 0);
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadPhotoFile (dir.file ("cut.jpg")); },
                                                "cut.jpg: a corrupt or truncated JPEG");
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadPhotoFile (dir.file ("cut.png")); },
                                                "cut.png: a corrupt or truncated PNG");
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadPhotoFile (dir.file ("text.png")); },
                                                "not a PNG or JPEG image");
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::loadPhotoFile (dir.file ("empty.png")); },
                                                "file is empty");
  expectErrorContaining<morphreg::IoError> ([&] { morphreg::loadPhotoFile (dir.file ("fifo.png")); },
                                            "fifo.png: is not a regular file (a FIFO)");
}
} // namespace

// SPDX-License-Identifier: BSD-3-Clause
#include "jpeg_errors.h"
#include "png_file.h"

#include <morphreg/common/error.h>
#include <morphreg/common/memory_budget.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/photo_file.h>

#include <jpeglib.h>

#include <cmath>
#include <csetjmp>
#include <cstdio>

namespace morphreg
{
namespace
{
/** The frame header of a JPEG file: its size and colour components. */
struct JpegFrame
{
  int width = 0, height = 0, components = 0;
};

/** Reads the JPEG markers of \a file up to the first frame header (SOFn); FormatError naming \a path if there is none
 *  before the image data or the file ends. */
JpegFrame
readJpegFrame (std::FILE* file, const std::string& path)
{
  const auto byte = [&] () {
    const int value = std::fgetc (file);
    if (value == EOF)
      throw FormatError (path + ": a truncated JPEG (it ends before its frame header)");
    return value;
  };
  const auto word = [&] () { return byte () << 8 | byte (); };
  std::fseek (file, 2, SEEK_SET); // after SOI
  for (;;) {
    if (byte () != 0xFF)
      throw FormatError (path + ": a corrupt JPEG (no marker where one must be)");
    int marker = byte ();
    while (marker == 0xFF)
      marker = byte ();
    if (marker == 0x01 || (marker >= 0xD0 && marker <= 0xD7))
      continue; // markers without a length
    if (marker == 0xDA || marker == 0xD9)
      throw FormatError (path + ": a corrupt JPEG (image data before any frame header)");
    const int length = word ();
    const bool frame = marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 && marker != 0xCC;
    if (frame) {
      byte (); // sample precision
      JpegFrame found;
      found.height = word ();
      found.width = word ();
      found.components = byte ();
      return found;
    }
    if (length < 2 || std::fseek (file, length - 2, SEEK_CUR) != 0)
      throw FormatError (path + ": a corrupt JPEG (a segment of length " + std::to_string (length) + ")");
  }
}

/** Throws unless \a frame is a grey or colour photo of 1 to kMaxPhotoSide a side that \a file_size bytes can hold:
 *  every 8 x 8 block of every component takes at least one bit of Huffman code. */
void
requirePlausibleJpeg (const JpegFrame& frame, const std::string& path, long file_size)
{
  if (frame.width < 1 || frame.height < 1 || frame.width > kMaxPhotoSide || frame.height > kMaxPhotoSide)
    throw FormatError (path + ": the image size " + std::to_string (frame.width) + " x " +
                       std::to_string (frame.height) + " is not 1 to " + std::to_string (kMaxPhotoSide) + " a side");
  if (frame.components != 1 && frame.components != 3)
    throw FormatError (path + ": a JPEG of " + std::to_string (frame.components) +
                       " colour components (CMYK?); give a grey or RGB photo");
  const double blocks = std::ceil (frame.width / 8.0) * std::ceil (frame.height / 8.0) * frame.components;
  if (static_cast<double> (file_size) < blocks / 8.0)
    throw FormatError (path + ": " + std::to_string (file_size) + " bytes cannot hold the " +
                       std::to_string (frame.width) + " x " + std::to_string (frame.height) +
                       " image its header declares (truncated or corrupt)");
}

/** Decodes the JPEG \a file into \a rgb (width x height x 3, allocated by the caller); false (the message in
 *  errors.message) if libjpeg fails or the decoded size differs from the frame header's. */
bool
decodeJpeg (jpeg_decompress_struct& info, JpegErrors& errors, std::FILE* file, const JpegFrame& frame,
            unsigned char* rgb)
{
  if (setjmp (errors.jump))
    return false;
  jpeg_stdio_src (&info, file);
  jpeg_read_header (&info, TRUE);
  info.out_color_space = JCS_RGB;
  jpeg_start_decompress (&info);
  if (static_cast<int> (info.output_width) != frame.width || static_cast<int> (info.output_height) != frame.height ||
      info.output_components != 3) {
    std::snprintf (errors.message, sizeof errors.message, "the decoder's size differs from the frame header's");
    return false;
  }
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = rgb + 3 * static_cast<std::size_t> (info.output_scanline) * frame.width;
    jpeg_read_scanlines (&info, &row, 1);
  }
  jpeg_finish_decompress (&info);
  return true;
}

PhotoPixels
loadJpeg (std::FILE* file, const std::string& path, long file_size)
{
  const JpegFrame frame = readJpegFrame (file, path);
  requirePlausibleJpeg (frame, path, file_size);
  requireMemory (3.0 * frame.width * frame.height,
                 path + ": the " + std::to_string (frame.width) + " x " + std::to_string (frame.height) + " photo");
  PhotoPixels pixels{frame.width, frame.height,
                     std::vector<unsigned char> (3 * std::size_t (frame.width) * frame.height)};
  std::rewind (file);
  jpeg_decompress_struct info;
  JpegErrors errors;
  reportJpegErrorsTo (info, errors);
  jpeg_create_decompress (&info);
  const bool decoded = decodeJpeg (info, errors, file, frame, pixels.rgb.data ());
  jpeg_destroy_decompress (&info);
  if (!decoded)
    throw FormatError (path + ": a corrupt or truncated JPEG (" + errors.message + ")");
  return pixels;
}

/** Sets libpng's transforms to 8-bit RGB and applies them; false (the message in read.error) if libpng fails. */
bool
expandToRgb (png::Read& read, const png::Header& header)
{
  if (setjmp (png_jmpbuf (read.png)))
    return false;
  if (header.colour_type == PNG_COLOR_TYPE_PALETTE)
    png_set_palette_to_rgb (read.png);
  if (!(header.colour_type & PNG_COLOR_MASK_COLOR) && header.bit_depth < 8)
    png_set_expand_gray_1_2_4_to_8 (read.png);
  if (header.bit_depth == 16)
    png_set_strip_16 (read.png);
  if (header.colour_type & PNG_COLOR_MASK_ALPHA)
    png_set_strip_alpha (read.png);
  if (!(header.colour_type & PNG_COLOR_MASK_COLOR))
    png_set_gray_to_rgb (read.png);
  png_read_update_info (read.png, read.info);
  return true;
}

PhotoPixels
loadPng (std::FILE* file, const std::string& path)
{
  long file_size = 0;
  const png::Header declared = png::readDeclaredHeader (file, path, file_size);
  const int channels = declared.colour_type == PNG_COLOR_TYPE_RGB          ? 3
                       : declared.colour_type == PNG_COLOR_TYPE_RGB_ALPHA  ? 4
                       : declared.colour_type == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                                                                           : 1;
  png::requirePlausibleSize (declared, path, file_size, declared.bit_depth * channels / 8.0, kMaxPhotoSide);
  requireMemory (3.0 * declared.width * declared.height, path + ": the " + std::to_string (declared.width) + " x " +
                                                             std::to_string (declared.height) + " photo");
  png::Read read;
  png::Header header;
  if (!read.info || !png::readHeader (read, file, header, kMaxPhotoSide) || !expandToRgb (read, header))
    throw FormatError (path + ": a corrupt PNG header (" + read.error + ")");
  if (header.width != declared.width || header.height != declared.height ||
      png_get_rowbytes (read.png, read.info) != 3 * static_cast<std::size_t> (header.width))
    throw FormatError (path + ": a corrupt PNG (its header cannot be decoded to 8-bit RGB)");
  PhotoPixels pixels{static_cast<int> (header.width), static_cast<int> (header.height), {}};
  pixels.rgb.resize (3 * static_cast<std::size_t> (pixels.width) * pixels.height);
  std::vector<png_bytep> rows (static_cast<std::size_t> (pixels.height));
  for (std::size_t y = 0; y < rows.size (); ++y)
    rows[y] = pixels.rgb.data () + 3 * y * static_cast<std::size_t> (pixels.width);
  if (!png::readRows (read, rows.data ()))
    throw FormatError (path + ": a corrupt or truncated PNG (" + read.error + ")");
  return pixels;
}
} // namespace

PhotoPixels
loadPhotoFile (const std::string& path)
{
  requireReadableFile (path);
  png::File file = png::openFile (path, "rb");
  unsigned char start[8] = {};
  const std::size_t read_bytes = std::fread (start, 1, sizeof start, file.get ());
  std::fseek (file.get (), 0, SEEK_END);
  const long file_size = std::ftell (file.get ());
  std::rewind (file.get ());
  if (read_bytes == sizeof start && png_sig_cmp (start, 0, 8) == 0)
    return loadPng (file.get (), path);
  if (read_bytes >= 3 && start[0] == 0xFF && start[1] == 0xD8 && start[2] == 0xFF)
    return loadJpeg (file.get (), path, file_size);
  throw FormatError (path + ": not a PNG or JPEG image (neither signature at its start)");
}

} // namespace morphreg

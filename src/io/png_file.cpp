// SPDX-License-Identifier: BSD-3-Clause
#include "png_file.h"

#include <morphreg/common/error.h>

#include <cstring>

namespace morphreg
{
namespace png
{
File
openFile (const std::string& path, const char* mode)
{
  File file (std::fopen (path.c_str (), mode), &std::fclose);
  if (!file)
    throw IoError (path + ": cannot open the file");
  return file;
}

void
keepError (png_structp png, png_const_charp message)
{
  auto* text = static_cast<std::string*> (png_get_error_ptr (png));
  *text = message;
  png_longjmp (png, 1);
}

void
ignoreWarning (png_structp, png_const_charp)
{}

Read::Read ()
{
  png = png_create_read_struct (PNG_LIBPNG_VER_STRING, &error, keepError, ignoreWarning);
  info = png ? png_create_info_struct (png) : nullptr;
}

Read::~Read ()
{
  png_destroy_read_struct (&png, &info, nullptr);
}

Header
readDeclaredHeader (std::FILE* file, const std::string& path, long& file_size)
{
  png_byte start[33] = {}; // the signature and the IHDR chunk
  const std::size_t read_bytes = std::fread (start, 1, sizeof start, file);
  if (read_bytes < 8 || png_sig_cmp (start, 0, 8) != 0)
    throw FormatError (path + ": not a PNG file (no PNG signature)");
  if (read_bytes < sizeof start || png_get_uint_32 (start + 8) != 13 || std::memcmp (start + 12, "IHDR", 4) != 0)
    throw FormatError (path + ": a corrupt PNG (no image header after the signature)");
  std::fseek (file, 0, SEEK_END);
  file_size = std::ftell (file);
  std::fseek (file, 8, SEEK_SET);
  return {png_get_uint_32 (start + 16), png_get_uint_32 (start + 20), start[24], start[25]};
}

void
requirePlausibleSize (const Header& header, const std::string& path, long file_size, double bytes_per_pixel,
                      int max_side)
{
  if (header.width < 1 || header.height < 1 || header.width > static_cast<png_uint_32> (max_side) ||
      header.height > static_cast<png_uint_32> (max_side))
    throw FormatError (path + ": the image size " + std::to_string (header.width) + " x " +
                       std::to_string (header.height) + " is not 1 to " + std::to_string (max_side) + " a side");
  const double raw = bytes_per_pixel * header.width * header.height;
  if (static_cast<double> (file_size) < raw / 1032.0)
    throw FormatError (path + ": " + std::to_string (file_size) + " bytes cannot hold the " +
                       std::to_string (header.width) + " x " + std::to_string (header.height) +
                       " image its header declares (truncated or corrupt)");
}

bool
readHeader (Read& read, std::FILE* file, Header& header, int max_side)
{
  if (setjmp (png_jmpbuf (read.png)))
    return false;
  png_set_user_limits (read.png, static_cast<png_uint_32> (max_side), static_cast<png_uint_32> (max_side));
  png_init_io (read.png, file);
  png_set_sig_bytes (read.png, 8);
  png_read_info (read.png, read.info);
  header.width = png_get_image_width (read.png, read.info);
  header.height = png_get_image_height (read.png, read.info);
  header.bit_depth = png_get_bit_depth (read.png, read.info);
  header.colour_type = png_get_color_type (read.png, read.info);
  if (png_get_interlace_type (read.png, read.info) != PNG_INTERLACE_NONE)
    png_set_interlace_handling (read.png);
  return true;
}

bool
readRows (Read& read, png_bytep* rows)
{
  if (setjmp (png_jmpbuf (read.png)))
    return false;
  png_read_image (read.png, rows);
  png_read_end (read.png, nullptr);
  return true;
}

} // namespace png
} // namespace morphreg

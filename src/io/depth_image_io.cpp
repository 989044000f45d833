// SPDX-License-Identifier: BSD-3-Clause
#include "png_file.h"

#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>
#include <morphreg/io/depth_image_io.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/json_file.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>

namespace morphreg
{
namespace
{
constexpr int kMaxSide = 16384;

/** Checks that \a header describes a depth image that \a file_size bytes can hold. */
void
requireDepthHeader (const png::Header& header, const std::string& path, long file_size)
{
  if (header.colour_type != PNG_COLOR_TYPE_GRAY || header.bit_depth != 16)
    throw FormatError (path + ": a depth image must be a 16-bit greyscale PNG (mm per pixel), this one is " +
                       std::to_string (header.bit_depth) + "-bit of colour type " +
                       std::to_string (header.colour_type));
  png::requirePlausibleSize (header, path, file_size, 2.0, kMaxSide);
}
} // namespace

DepthImage
loadDepthPng (const std::string& path)
{
  requireReadableFile (path);
  png::File file = png::openFile (path, "rb");
  long size = 0;
  const png::Header declared = png::readDeclaredHeader (file.get (), path, size);
  requireDepthHeader (declared, path, size);
  png::Read read;
  if (!read.info)
    throw IoError (path + ": cannot start the PNG decoder");
  png::Header header;
  if (!png::readHeader (read, file.get (), header, kMaxSide))
    throw FormatError (path + ": a corrupt PNG header (" + read.error + ")");
  png_set_swap (read.png); // PNG stores 16-bit samples big-endian
  DepthImage image{static_cast<int> (header.width), static_cast<int> (header.height), {}};
  image.depth.assign (static_cast<std::size_t> (image.width) * image.height, 0);
  std::vector<png_bytep> rows (static_cast<std::size_t> (image.height));
  for (int y = 0; y < image.height; ++y)
    rows[static_cast<std::size_t> (y)] =
        reinterpret_cast<png_bytep> (image.depth.data () + static_cast<std::size_t> (y) * image.width);
  if (!png::readRows (read, rows.data ()))
    throw FormatError (path + ": a corrupt or truncated PNG (" + read.error + ")");
  return image;
}

namespace
{
/** A libpng write, its structures freed when it goes out of scope. */
struct PngWrite
{
  std::string error;
  png_structp png = nullptr;
  png_infop info = nullptr;

  PngWrite ()
  {
    png = png_create_write_struct (PNG_LIBPNG_VER_STRING, &error, png::keepError, png::ignoreWarning);
    info = png ? png_create_info_struct (png) : nullptr;
  }
  ~PngWrite ()
  {
    png_destroy_write_struct (&png, &info);
  }
};

/** Encodes \a image into \a file; false (the message in write.error) if libpng fails. */
bool
writePngRows (PngWrite& write, std::FILE* file, const DepthImage& image)
{
  if (setjmp (png_jmpbuf (write.png)))
    return false;
  png_init_io (write.png, file);
  png_set_IHDR (write.png, write.info, static_cast<png_uint_32> (image.width), static_cast<png_uint_32> (image.height),
                16, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_write_info (write.png, write.info);
  png_set_swap (write.png);
  for (int y = 0; y < image.height; ++y)
    png_write_row (write.png, reinterpret_cast<png_const_bytep> (image.depth.data () +
                                                                 static_cast<std::size_t> (y) * image.width));
  png_write_end (write.png, nullptr);
  return true;
}
} // namespace

void
saveDepthPng (const std::string& path, const DepthImage& image)
{
  if (image.width < 1 || image.height < 1 || image.width > kMaxSide || image.height > kMaxSide ||
      image.depth.size () != static_cast<std::size_t> (image.width) * image.height)
    throw InvalidInputError (path + ": a depth image of " + std::to_string (image.width) + " x " +
                             std::to_string (image.height) + " pixels with " + std::to_string (image.depth.size ()) +
                             " depths");
  writeAtomically (path, [&image] (const std::string& partial) {
    png::File file = png::openFile (partial, "wb");
    PngWrite write;
    if (!write.info || !writePngRows (write, file.get (), image) || std::fflush (file.get ()) != 0)
      throw IoError (partial + ": cannot write the PNG" + (write.error.empty () ? "" : " (" + write.error + ")"));
  });
}

DepthIntrinsics
loadDepthIntrinsics (const std::string& path)
{
  const nlohmann::json document = readJsonFile (path);
  if (!document.is_object ())
    throw FormatError (path + ": the intrinsics must be a JSON object with width, height, fx, fy, cx, cy");
  const auto number = [&document, &path] (const char* key) {
    const auto found = document.find (key);
    if (found == document.end () || !found->is_number ())
      throw FormatError (path + ": \"" + key + "\" is missing or not a number");
    return found->get<double> ();
  };
  const auto whole = [&document, &path] (const char* key) {
    const auto found = document.find (key);
    if (found == document.end () || !found->is_number_integer () || found->get<long long> () < 1 ||
        found->get<long long> () > kMaxSide)
      throw FormatError (path + ": \"" + key + "\" must be a whole number of pixels, 1 to " +
                         std::to_string (kMaxSide));
    return static_cast<int> (found->get<long long> ());
  };
  DepthIntrinsics intrinsics{whole ("width"), whole ("height"), number ("fx"),
                             number ("fy"),   number ("cx"),    number ("cy")};
  requireValidIntrinsics (intrinsics, path);
  return intrinsics;
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>
#include <morphreg/io/depth_image_io.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/json_file.h>

#include <png.h>

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <memory>

namespace morphreg
{
namespace
{
constexpr int kMaxSide = 16384;

/** A FILE* closed when it goes out of scope. */
using File = std::unique_ptr<std::FILE, int (*) (std::FILE*)>;

File
openFile (const std::string& path, const char* mode)
{
  File file (std::fopen (path.c_str (), mode), &std::fclose);
  if (!file)
    throw IoError (path + ": cannot open the file");
  return file;
}

/** libpng reports errors through longjmp: the message is kept for the FormatError thrown after it. */
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

/** A libpng read, its structures freed when it goes out of scope. */
struct PngRead
{
  std::string error;
  png_structp png = nullptr;
  png_infop info = nullptr;

  PngRead ()
  {
    png = png_create_read_struct (PNG_LIBPNG_VER_STRING, &error, keepError, ignoreWarning);
    info = png ? png_create_info_struct (png) : nullptr;
  }
  ~PngRead ()
  {
    png_destroy_read_struct (&png, &info, nullptr);
  }
};

/** What the header says (plain values: libpng's longjmp must not cross C++ objects). */
struct PngHeader
{
  png_uint_32 width = 0, height = 0;
  int bit_depth = 0, colour_type = 0;
};

/** Reads the header after the signature; false (the message in read.error) if libpng fails. */
bool
readPngHeader (PngRead& read, std::FILE* file, PngHeader& header)
{
  if (setjmp (png_jmpbuf (read.png)))
    return false;
  png_set_user_limits (read.png, kMaxSide, kMaxSide);
  png_init_io (read.png, file);
  png_set_sig_bytes (read.png, 8);
  png_read_info (read.png, read.info);
  header.width = png_get_image_width (read.png, read.info);
  header.height = png_get_image_height (read.png, read.info);
  header.bit_depth = png_get_bit_depth (read.png, read.info);
  header.colour_type = png_get_color_type (read.png, read.info);
  if (png_get_interlace_type (read.png, read.info) != PNG_INTERLACE_NONE)
    png_set_interlace_handling (read.png);
  png_set_swap (read.png); // PNG stores 16-bit samples big-endian
  return true;
}

/** Decodes every row into \a rows (allocated by the caller); false (the message in read.error) if libpng fails. */
bool
readPngRows (PngRead& read, png_bytep* rows)
{
  if (setjmp (png_jmpbuf (read.png)))
    return false;
  png_read_image (read.png, rows);
  return true;
}

/** Checks that \a header describes a depth image that \a file_size bytes can hold. */
void
requireDepthHeader (const PngHeader& header, const std::string& path, long file_size)
{
  if (header.colour_type != PNG_COLOR_TYPE_GRAY || header.bit_depth != 16)
    throw FormatError (path + ": a depth image must be a 16-bit greyscale PNG (mm per pixel), this one is " +
                       std::to_string (header.bit_depth) + "-bit of colour type " +
                       std::to_string (header.colour_type));
  if (header.width < 1 || header.height < 1 || header.width > kMaxSide || header.height > kMaxSide)
    throw FormatError (path + ": the image size " + std::to_string (header.width) + " x " +
                       std::to_string (header.height) + " is not 1 to " + std::to_string (kMaxSide) + " a side");
  // deflate cannot compress below about 1/1032 of its input: a file that small for its size is truncated or lies
  const double raw = 2.0 * header.width * header.height;
  if (static_cast<double> (file_size) < raw / 1032.0)
    throw FormatError (path + ": " + std::to_string (file_size) + " bytes cannot hold a " +
                       std::to_string (header.width) + " x " + std::to_string (header.height) + " 16-bit image");
}
} // namespace

DepthImage
loadDepthPng (const std::string& path)
{
  requireReadableFile (path);
  File file = openFile (path, "rb");
  png_byte start[33] = {}; // the signature and the IHDR chunk, which PNG requires first
  const std::size_t read_bytes = std::fread (start, 1, sizeof start, file.get ());
  if (read_bytes < 8 || png_sig_cmp (start, 0, 8) != 0)
    throw FormatError (path + ": not a PNG file (no PNG signature)");
  if (read_bytes < sizeof start || png_get_uint_32 (start + 8) != 13 || std::memcmp (start + 12, "IHDR", 4) != 0)
    throw FormatError (path + ": a corrupt PNG (no image header after the signature)");
  std::fseek (file.get (), 0, SEEK_END);
  const long size = std::ftell (file.get ());
  std::fseek (file.get (), 8, SEEK_SET);
  const PngHeader declared{png_get_uint_32 (start + 16), png_get_uint_32 (start + 20), start[24], start[25]};
  requireDepthHeader (declared, path, size);
  PngRead read;
  if (!read.info)
    throw IoError (path + ": cannot start the PNG decoder");
  PngHeader header;
  if (!readPngHeader (read, file.get (), header))
    throw FormatError (path + ": a corrupt PNG header (" + read.error + ")");
  DepthImage image{static_cast<int> (header.width), static_cast<int> (header.height), {}};
  image.depth.assign (static_cast<std::size_t> (image.width) * image.height, 0);
  std::vector<png_bytep> rows (static_cast<std::size_t> (image.height));
  for (int y = 0; y < image.height; ++y)
    rows[static_cast<std::size_t> (y)] =
        reinterpret_cast<png_bytep> (image.depth.data () + static_cast<std::size_t> (y) * image.width);
  if (!readPngRows (read, rows.data ()))
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
    png = png_create_write_struct (PNG_LIBPNG_VER_STRING, &error, keepError, ignoreWarning);
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
    File file = openFile (partial, "wb");
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

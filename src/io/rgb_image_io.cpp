// SPDX-License-Identifier: BSD-3-Clause
#include "jpeg_errors.h"

#include <morphreg/common/error.h>
#include <morphreg/io/photo_file.h>
#include <morphreg/io/rgb_image_io.h>

// libpng and libjpeg(-turbo) directly: VTK 9.1's PNG reader crashes on corrupt data (a segmentation fault after
// "libpng error: IDAT: invalid distance too far back", a cut file, or any file read from memory).
#include <jpeglib.h>
#include <png.h>

#include <csetjmp>
#include <filesystem>
#include <utility>

namespace morphreg
{
namespace
{
const unsigned char kPngSignature[] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
const unsigned char kJpegSignature[] = {0xff, 0xd8, 0xff};

bool
startsWith (const std::vector<unsigned char>& bytes, const unsigned char* signature, std::size_t size)
{
  return bytes.size () >= size && std::equal (signature, signature + size, bytes.begin ());
}

void
requireFewerPixels (double width, double height, const std::string& name, double max_pixels)
{
  if (width * height > max_pixels)
    throw FormatError (name + ": the image declares " + std::to_string (static_cast<long long> (width)) + " x " +
                       std::to_string (static_cast<long long> (height)) + " pixels, more than the " +
                       std::to_string (static_cast<long long> (max_pixels)) + " accepted");
}

/** PNG through libpng's simplified API (any bit depth and colour type, read as 8-bit sRGB RGBA, alpha dropped). */
RgbImage
decodePng (const std::vector<unsigned char>& bytes, const std::string& name, double max_pixels)
{
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  if (!png_image_begin_read_from_memory (&image, bytes.data (), bytes.size ()))
    throw FormatError (name + ": cannot be decoded as PNG (" + image.message + ")");
  requireFewerPixels (image.width, image.height, name, max_pixels);
  image.format = PNG_FORMAT_RGBA;
  std::vector<unsigned char> rgba (PNG_IMAGE_SIZE (image));
  if (!png_image_finish_read (&image, nullptr, rgba.data (), 0, nullptr)) {
    const std::string message = image.message;
    png_image_free (&image);
    throw FormatError (name + ": cannot be decoded as PNG (" + message + ")");
  }
  RgbImage result{static_cast<int> (image.width), static_cast<int> (image.height), {}};
  result.data.resize (3 * std::size_t (image.width) * image.height);
  for (std::size_t p = 0; p < result.data.size () / 3; ++p)
    std::copy_n (&rgba[4 * p], 3, &result.data[3 * p]);
  return result;
}

/** JPEG through libjpeg(-turbo), converted to RGB. */
RgbImage
decodeJpeg (const std::vector<unsigned char>& bytes, const std::string& name, double max_pixels)
{
  jpeg_decompress_struct info;
  JpegErrors errors;
  reportJpegErrorsTo (info, errors);
  std::vector<unsigned char> pixels; // before setjmp: still whole when libjpeg jumps back
  jpeg_create_decompress (&info);
  if (setjmp (errors.jump)) {
    jpeg_destroy_decompress (&info);
    throw FormatError (name + ": cannot be decoded as JPEG (" + errors.message + ")");
  }
  jpeg_mem_src (&info, bytes.data (), static_cast<unsigned long> (bytes.size ()));
  jpeg_read_header (&info, TRUE);
  if (double (info.image_width) * info.image_height > max_pixels) {
    jpeg_destroy_decompress (&info);
    requireFewerPixels (info.image_width, info.image_height, name, max_pixels);
  }
  info.out_color_space = JCS_RGB;
  jpeg_start_decompress (&info);
  pixels.resize (3 * std::size_t (info.output_width) * info.output_height);
  while (info.output_scanline < info.output_height) {
    JSAMPROW row = &pixels[3 * std::size_t (info.output_width) * info.output_scanline];
    jpeg_read_scanlines (&info, &row, 1);
  }
  jpeg_finish_decompress (&info);
  RgbImage result{static_cast<int> (info.output_width), static_cast<int> (info.output_height), std::move (pixels)};
  jpeg_destroy_decompress (&info);
  return result;
}
} // namespace

RgbImage
loadRgbImage (const std::string& path)
{
  PhotoPixels pixels = loadPhotoFile (path);
  return {pixels.width, pixels.height, std::move (pixels.rgb)};
}

RgbImage
decodeRgbImage (const std::vector<unsigned char>& bytes, const std::string& name, double max_pixels)
{
  if (startsWith (bytes, kPngSignature, sizeof (kPngSignature)))
    return decodePng (bytes, name, max_pixels);
  if (startsWith (bytes, kJpegSignature, sizeof (kJpegSignature)))
    return decodeJpeg (bytes, name, max_pixels);
  throw FormatError (name + ": not a PNG or JPEG image (its first bytes are neither's signature)");
}

void
saveRgbImage (const std::string& path, const RgbImage& image)
{
  if (image.width <= 0 || image.height <= 0 ||
      image.data.size () != 3 * static_cast<size_t> (image.width) * static_cast<size_t> (image.height))
    throw InvalidInputError ("saveRgbImage: " + path + ": the image is empty or its data does not match " +
                             std::to_string (image.width) + " x " + std::to_string (image.height) + " RGB pixels");
  png_image png{};
  png.version = PNG_IMAGE_VERSION;
  png.width = static_cast<png_uint_32> (image.width);
  png.height = static_cast<png_uint_32> (image.height);
  png.format = PNG_FORMAT_RGB;
  if (!png_image_write_to_file (&png, path.c_str (), 0, image.data.data (), 0, nullptr) ||
      !std::filesystem::exists (path))
    throw IoError (path + ": cannot be written");
}
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/photo/jpeg_exif.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <iterator>

namespace morphreg
{
namespace
{
constexpr std::uint16_t kExifIfdPointer = 0x8769;
constexpr std::uint16_t kFocalLength35mm = 0xA405;
constexpr double kFilmDiagonal = 43.2666; // mm, the 36 x 24 mm frame

/** The TIFF block of an EXIF segment: bounds-checked reads in its byte order. */
class TiffBlock
{
public:
  TiffBlock (const std::string& bytes, size_t begin, size_t end) : bytes_ (bytes), begin_ (begin), end_ (end)
  {
    little_ = end - begin >= 2 && bytes[begin] == 'I' && bytes[begin + 1] == 'I';
  }

  /** The unsigned integer of \a size bytes at \a offset from the block's start, or none beyond its end. */
  std::optional<std::uint32_t>
  read (size_t offset, int size) const
  {
    if (offset + static_cast<size_t> (size) > end_ - begin_)
      return std::nullopt;
    std::uint32_t value = 0;
    for (int k = 0; k < size; ++k) {
      const auto byte = static_cast<unsigned char> (bytes_[begin_ + offset + (little_ ? size - 1 - k : k)]);
      value = (value << 8) | byte;
    }
    return value;
  }

  /** The SHORT or LONG value of \a tag in the IFD at \a ifd, or none. */
  std::optional<std::uint32_t>
  tag (size_t ifd, std::uint16_t tag) const
  {
    const auto count = read (ifd, 2);
    for (std::uint32_t k = 0; count && k < *count; ++k) {
      const size_t entry = ifd + 2 + 12 * static_cast<size_t> (k);
      const auto id = read (entry, 2), type = read (entry + 2, 2);
      if (!id || !type)
        return std::nullopt;
      if (*id == tag && *type == 3)
        return read (entry + 8, 2);
      if (*id == tag && *type == 4)
        return read (entry + 8, 4);
    }
    return std::nullopt;
  }

private:
  const std::string& bytes_;
  size_t begin_, end_;
  bool little_ = false;
};

/** The start and end of the first APP1 EXIF segment's TIFF block, or (0, 0). */
std::pair<size_t, size_t>
exifBlock (const std::string& bytes)
{
  if (bytes.size () < 4 || static_cast<unsigned char> (bytes[0]) != 0xFF ||
      static_cast<unsigned char> (bytes[1]) != 0xD8)
    return {0, 0};
  for (size_t at = 2; at + 4 <= bytes.size ();) {
    const auto marker = static_cast<unsigned char> (bytes[at + 1]);
    const size_t length = static_cast<size_t> (static_cast<unsigned char> (bytes[at + 2])) << 8 |
                          static_cast<unsigned char> (bytes[at + 3]);
    if (static_cast<unsigned char> (bytes[at]) != 0xFF || marker == 0xDA || length < 2 ||
        at + 2 + length > bytes.size ())
      return {0, 0}; // no marker, the image data begins, or a truncated segment
    if (marker == 0xE1 && length >= 8 && bytes.compare (at + 4, 6, std::string ("Exif\0\0", 6)) == 0)
      return {at + 10, at + 2 + length};
    at += 2 + length;
  }
  return {0, 0};
}
} // namespace

std::optional<double>
jpegFocalLength35mmFromBytes (const std::string& bytes)
{
  const auto [begin, end] = exifBlock (bytes);
  if (end <= begin)
    return std::nullopt;
  const TiffBlock tiff (bytes, begin, end);
  const auto ifd0 = tiff.read (4, 4);
  const auto exif = ifd0 ? tiff.tag (*ifd0, kExifIfdPointer) : std::nullopt;
  const auto focal = exif ? tiff.tag (*exif, kFocalLength35mm) : std::nullopt;
  if (!focal || *focal == 0)
    return std::nullopt; // 0 means "unknown" in EXIF
  return static_cast<double> (*focal);
}

std::optional<double>
jpegFocalLength35mm (const std::string& path)
{
  requireReadableFile (path);
  std::ifstream file (path, std::ios::binary);
  const std::string bytes ((std::istreambuf_iterator<char> (file)), std::istreambuf_iterator<char> ());
  if (!file.good () && !file.eof ())
    throw IoError (path + ": cannot be read");
  return jpegFocalLength35mmFromBytes (bytes);
}

double
focalPixelsFrom35mm (double millimetres, int width, int height)
{
  return millimetres / kFilmDiagonal * std::hypot (static_cast<double> (width), static_cast<double> (height));
}
} // namespace morphreg

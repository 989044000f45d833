// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// libpng reading shared by the depth images (depth_image_io.cpp) and the photos (photo_file.cpp): the image header
// checked from the file's bytes before libpng allocates anything, and libpng's errors (reported through longjmp)
// turned into messages.
#include <png.h>

#include <cstdio>
#include <memory>
#include <string>

namespace morphreg
{
namespace png
{
/** A FILE* closed when it goes out of scope. */
using File = std::unique_ptr<std::FILE, int (*) (std::FILE*)>;

/** Opens \a path with \a mode; IoError naming it if that fails. */
File
openFile (const std::string& path, const char* mode);

/** Keeps libpng's error message in the string its error pointer names, and jumps back. */
void
keepError (png_structp png, png_const_charp message);

/** Ignores libpng's warnings. */
void ignoreWarning (png_structp, png_const_charp);

/** A libpng read, its structures freed when it goes out of scope. */
struct Read
{
  std::string error;
  png_structp png = nullptr;
  png_infop info = nullptr;

  Read ();
  ~Read ();
};

/** What a PNG header says (plain values: libpng's longjmp must not cross C++ objects). */
struct Header
{
  png_uint_32 width = 0, height = 0;
  int bit_depth = 0, colour_type = 0;
};

/** The header of the PNG file \a file (\a path, for messages) from its first bytes: the signature and the IHDR chunk
 *  PNG requires first. Leaves \a file after the signature and sets \a file_size. FormatError if it is not a PNG. */
Header
readDeclaredHeader (std::FILE* file, const std::string& path, long& file_size);

/** Throws FormatError naming \a path unless \a header's size is 1 to \a max_side a side and \a file_size bytes can
 *  hold it at \a bytes_per_pixel uncompressed bytes a pixel (deflate cannot compress below about 1/1032). */
void
requirePlausibleSize (const Header& header, const std::string& path, long file_size, double bytes_per_pixel,
                      int max_side);

/** Reads the header through libpng (after the signature) and sets its limits to \a max_side; false (the message in
 *  read.error) if libpng fails. */
bool
readHeader (Read& read, std::FILE* file, Header& header, int max_side);

/** Decodes every row into \a rows (allocated by the caller); false (the message in read.error) if libpng fails. */
bool
readRows (Read& read, png_bytep* rows);

} // namespace png
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
// Fuzz targets photo_png and photo_jpeg: photos (PNG, JPEG) read as fit-photos --photo reads them: the header
// checked from the bytes, then decoded by libpng or libjpeg.
#include "fuzz_target.h"

#include <morphreg/io/photo_file.h>

namespace
{
const bool registered_png = morphreg::fuzz::registerTarget (
    {"photo_png", ".png", {[] (const std::string& path) { morphreg::loadPhotoFile (path); }}});
const bool registered_jpeg = morphreg::fuzz::registerTarget (
    {"photo_jpeg", ".jpg", {[] (const std::string& path) { morphreg::loadPhotoFile (path); }}});
} // namespace

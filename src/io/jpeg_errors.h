// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// libjpeg's error handling for the JPEG decoders of photo_file.cpp and rgb_image_io.cpp: errors and warnings (corrupt
// or cut data) jump back to the decoder's setjmp with libjpeg's message.
#include <jpeglib.h>

#include <csetjmp>

namespace morphreg
{
/** \brief libjpeg's error manager with the jump back and the message. */
struct JpegErrors
{
  jpeg_error_mgr manager;             ///< libjpeg's, its exits replaced
  std::jmp_buf jump;                  ///< set by the decoder before it calls libjpeg
  char message[JMSG_LENGTH_MAX] = {}; ///< libjpeg's message once it has jumped
};

/** \brief Makes \a info report through \a errors: an error or a warning longjmps to errors.jump with the message.
 *  \param[in,out] info the decompressor, before jpeg_create_decompress
 *  \param[in,out] errors the error manager; it must outlive the decompressor
 */
void
reportJpegErrorsTo (jpeg_decompress_struct& info, JpegErrors& errors);
} // namespace morphreg

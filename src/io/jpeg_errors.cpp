// SPDX-License-Identifier: BSD-3-Clause
#include "jpeg_errors.h"

namespace morphreg
{
namespace
{
[[noreturn]] void
jpegFail (j_common_ptr info)
{
  auto* errors = reinterpret_cast<JpegErrors*> (info->err);
  (*info->err->format_message) (info, errors->message);
  std::longjmp (errors->jump, 1);
}

void
jpegMessage (j_common_ptr info, int level)
{
  if (level < 0) // a warning: the data are corrupt or cut short
    jpegFail (info);
}
} // namespace

void
reportJpegErrorsTo (jpeg_decompress_struct& info, JpegErrors& errors)
{
  info.err = jpeg_std_error (&errors.manager);
  errors.manager.error_exit = &jpegFail;
  errors.manager.emit_message = &jpegMessage;
}
} // namespace morphreg

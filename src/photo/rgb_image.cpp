// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/photo_file.h>
#include <morphreg/photo/rgb_image.h>

#include <vtkImageData.h>
#include <vtkPNGWriter.h>
#include <vtkSmartPointer.h>

#include <filesystem>
#include <utility>

namespace morphreg
{
RgbImage
loadRgbImage (const std::string& path)
{
  PhotoPixels pixels = loadPhotoFile (path);
  return {pixels.width, pixels.height, std::move (pixels.rgb)};
}

void
saveRgbImage (const std::string& path, const RgbImage& image)
{
  if (image.width <= 0 || image.height <= 0 ||
      image.data.size () != 3 * static_cast<size_t> (image.width) * static_cast<size_t> (image.height))
    throw InvalidInputError ("saveRgbImage: " + path + ": the image is empty or its data does not match " +
                             std::to_string (image.width) + " x " + std::to_string (image.height) + " RGB pixels");
  auto data = vtkSmartPointer<vtkImageData>::New ();
  data->SetDimensions (image.width, image.height, 1);
  data->AllocateScalars (VTK_UNSIGNED_CHAR, 3);
  auto* scalars = static_cast<unsigned char*> (data->GetScalarPointer ());
  for (int y = 0; y < image.height; ++y)
    std::copy_n (image.data.data () + 3 * static_cast<size_t> (y) * image.width, 3 * image.width,
                 scalars + 3 * static_cast<size_t> (image.height - 1 - y) * image.width);
  auto writer = vtkSmartPointer<vtkPNGWriter>::New ();
  writer->SetFileName (path.c_str ());
  writer->SetInputData (data);
  writer->Write ();
  if (writer->GetErrorCode () != 0 || !std::filesystem::exists (path))
    throw IoError (path + ": cannot be written");
}
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/photo/rgb_image.h>

#include <vtkImageData.h>
#include <vtkImageReader2.h>
#include <vtkImageReader2Factory.h>
#include <vtkPNGWriter.h>
#include <vtkSmartPointer.h>

#include <filesystem>

namespace morphreg
{
RgbImage
loadRgbImage (const std::string& path)
{
  requireReadableFile (path);
  const vtkSmartPointer<vtkImageReader2> reader =
      vtkSmartPointer<vtkImageReader2>::Take (vtkImageReader2Factory::CreateImageReader2 (path.c_str ()));
  if (!reader || (std::string (reader->GetClassName ()) != "vtkPNGReader" &&
                  std::string (reader->GetClassName ()) != "vtkJPEGReader"))
    throw FormatError (path + ": not a PNG or JPEG image");
  reader->SetFileName (path.c_str ());
  reader->Update ();
  vtkImageData* image = reader->GetOutput ();
  int dims[3];
  image->GetDimensions (dims);
  const int components = image->GetNumberOfScalarComponents ();
  if (dims[0] <= 0 || dims[1] <= 0 || image->GetScalarType () != VTK_UNSIGNED_CHAR || components < 1 || components > 4)
    throw FormatError (path + ": cannot be decoded as an 8-bit grey, RGB or RGBA image");
  RgbImage result{dims[0], dims[1], std::vector<unsigned char> (3 * static_cast<size_t> (dims[0]) * dims[1])};
  const auto* scalars = static_cast<const unsigned char*> (image->GetScalarPointer ());
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      // VTK's rows run bottom to top.
      const unsigned char* in = scalars + components * (static_cast<size_t> (dims[1] - 1 - y) * dims[0] + x);
      unsigned char* out = result.data.data () + 3 * (static_cast<size_t> (y) * dims[0] + x);
      for (int c = 0; c < 3; ++c)
        out[c] = in[components >= 3 ? c : 0];
    }
  return result;
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

// SPDX-License-Identifier: BSD-3-Clause
#include "gltf_file.h"

#include "tiny_gltf_hidden.h"

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace morphreg
{
namespace gltf
{
namespace
{
/** The largest external file (buffer or image) the callbacks read. */
constexpr std::uintmax_t kMaxExternalBytes = std::uintmax_t (1) << 31;

/** The extensions a file may require that the reader honours. */
const char* const kSupportedRequired[] = {"KHR_draco_mesh_compression", "KHR_mesh_quantization", "KHR_materials_unlit"};

bool
fileExists (const std::string& path, void*)
{
  std::error_code ec;
  return std::filesystem::is_regular_file (path, ec);
}

std::string
unexpandedPath (const std::string& path, void*)
{
  return path; // a uri is a path relative to the file's folder (checkGltfJson checked it), taken as it is
}

bool
readWholeFile (std::vector<unsigned char>* out, std::string* err, const std::string& path, void*)
{
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size (path, ec);
  std::ifstream stream (path, std::ios::binary);
  if (ec || !stream || size > kMaxExternalBytes) {
    *err += ec || !stream ? "cannot be read" : "larger than 2 GB";
    return false;
  }
  out->resize (size);
  return static_cast<bool> (stream.read (reinterpret_cast<char*> (out->data ()), static_cast<std::streamsize> (size)));
}

bool
refuseWrite (std::string* err, const std::string&, const std::vector<unsigned char>&, void*)
{
  *err += "the glTF reader writes no files";
  return false;
}

/** Keeps an image's bytes as they are (PNG or JPEG): decoded later, and only if a material uses it. */
bool
keepEncodedImage (tinygltf::Image* image, const int, std::string*, std::string*, int, int, const unsigned char* bytes,
                  int size, void*)
{
  if (size < 0)
    return false;
  image->image.assign (bytes, bytes + size);
  image->as_is = true;
  return true;
}

/** tinygltf's error text, at most a few lines of it (some messages quote a whole data URI). */
std::string
shortened (const std::string& text)
{
  std::string first = text.substr (0, text.find ('\n'));
  if (first.size () > 300)
    first = first.substr (0, 300) + "...";
  return first.empty () ? "tinygltf could not read it" : first;
}

void
refuseUnsupportedExtensions (const GltfFile& file, const tinygltf::Model& model)
{
  for (const std::string& extension : model.extensionsRequired)
    if (std::find (std::begin (kSupportedRequired), std::end (kSupportedRequired), extension) ==
        std::end (kSupportedRequired))
      file.fail ("requires the glTF extension " + extension.substr (0, 100) + ", which morphreg does not read");
}
} // namespace

tinygltf::Model
loadGltfModel (const GltfFile& file)
{
  tinygltf::TinyGLTF loader;
  loader.SetImageLoader (&keepEncodedImage, nullptr);
  loader.SetFsCallbacks ({&fileExists, &unexpandedPath, &readWholeFile, &refuseWrite, nullptr});
  loader.SetStoreOriginalJSONForExtrasAndExtensions (false);
  const std::string folder = std::filesystem::path (file.path).parent_path ().string ();
  tinygltf::Model model;
  std::string err, warn;
  bool loaded = false;
  try {
    loaded = file.binary
                 ? loader.LoadBinaryFromMemory (&model, &err, &warn, file.bytes.data (),
                                                static_cast<unsigned int> (file.bytes.size ()), folder)
                 : loader.LoadASCIIFromString (&model, &err, &warn, reinterpret_cast<const char*> (file.bytes.data ()),
                                               static_cast<unsigned int> (file.bytes.size ()), folder);
  }
  catch (const std::exception& e) {
    file.fail (std::string ("tinygltf failed: ") + e.what ());
  }
  if (!loaded)
    file.fail (shortened (err));
  refuseUnsupportedExtensions (file, model);
  return model;
}
} // namespace gltf
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private to the glTF reader (gltf_reader.cpp): the file read whole, its GLB container checked, and the JSON checked
// for what tinygltf would otherwise trust (buffer sizes, buffer view extents, nesting), all before tinygltf sees it.
#include "tiny_gltf_hidden.h"

#include <morphreg/common/error.h>

#include <cstddef>
#include <string>
#include <vector>

namespace morphreg
{
namespace gltf
{
/** A glTF file in memory: for a GLB, where its JSON and BIN chunks lie; for a .gltf, the JSON is the whole file. */
struct GltfFile
{
  std::string path;                 ///< for messages
  std::vector<unsigned char> bytes; ///< the whole file
  bool binary = false;              ///< GLB
  std::size_t json_offset = 0;      ///< where the JSON text starts
  std::size_t json_length = 0;      ///< its length in bytes
  std::size_t bin_offset = 0;       ///< where the BIN chunk's data starts (GLB)
  std::size_t bin_length = 0;       ///< its length, 0 without a BIN chunk

  /** Throws FormatError "path: problem". */
  [[noreturn]] void
  fail (const std::string& problem) const
  {
    throw FormatError (path + ": " + problem);
  }
};

/** Reads \a path whole; for a GLB (it starts with "glTF"), checks the header (version 2, the length the file has) and
 *  the chunks (JSON first, then an optional BIN chunk, each within the file). FormatError naming the file and what is
 *  wrong; IoError if it cannot be read. */
GltfFile
readGltfBytes (const std::string& path);

/** Parses the JSON and checks what tinygltf would trust: nesting depth, an asset of version 2.x, and for every buffer
 *  its byteLength against its source (the BIN chunk, a data URI, or a file next to the glTF file that must exist),
 *  for every buffer view its extent within its buffer. FormatError naming the file and the item. Draco-compressed
 *  primitives lose their indices accessor, which tinygltf 2.7 would refuse (it has no buffer view): \a file's JSON
 *  is rewritten without them. */
void
checkGltfJson (GltfFile& file);

/** Loads the checked file with tinygltf: buffers read (external files through checked callbacks), images kept
 *  encoded (decoded only when a material uses them), extensions the reader cannot honour refused. */
tinygltf::Model
loadGltfModel (const GltfFile& file);
} // namespace gltf
} // namespace morphreg

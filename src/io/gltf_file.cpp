// SPDX-License-Identifier: BSD-3-Clause
#include "gltf_file.h"

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>

namespace morphreg
{
namespace gltf
{
namespace
{
constexpr std::uint32_t kJsonChunk = 0x4E4F534A; // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;  // "BIN\0"

std::uint32_t
readUint32 (const std::vector<unsigned char>& bytes, std::size_t offset)
{
  return static_cast<std::uint32_t> (bytes[offset]) | static_cast<std::uint32_t> (bytes[offset + 1]) << 8 |
         static_cast<std::uint32_t> (bytes[offset + 2]) << 16 | static_cast<std::uint32_t> (bytes[offset + 3]) << 24;
}

/** A chunk type for messages: its four bytes as hexadecimal, least significant first as they lie in the file. */
std::string
chunkTypeText (std::uint32_t type)
{
  static const char digits[] = "0123456789abcdef";
  std::string text = "0x";
  for (int i = 0; i < 4; ++i, type >>= 8)
    text += std::string{digits[(type >> 4) & 0xf], digits[type & 0xf]};
  return text + " (bytes in file order)";
}

std::string
bytesText (std::uint64_t count)
{
  return std::to_string (count) + (count == 1 ? " byte" : " bytes");
}

/** The 12-byte header: magic, version 2, and a length equal to the file's size. */
void
checkGlbHeader (const GltfFile& file)
{
  const std::size_t size = file.bytes.size ();
  if (size < 12)
    file.fail ("cut short: " + bytesText (size) + ", fewer than the 12 of a GLB header");
  if (std::memcmp (file.bytes.data (), "glTF", 4) != 0)
    file.fail ("not a GLB file: it does not start with the magic bytes 'glTF'");
  const std::uint32_t version = readUint32 (file.bytes, 4);
  if (version != 2)
    file.fail ("GLB version " + std::to_string (version) + "; only glTF 2.0 (version 2) is read");
  const std::uint32_t length = readUint32 (file.bytes, 8);
  if (length != size)
    file.fail ("the GLB header gives a length of " + bytesText (length) + " but the file holds " + bytesText (size) +
               (length > size ? " (the file is cut short)" : " (bytes after the end the header gives)"));
}

/** The chunk header at \a offset: its length and type, the chunk checked to lie within the file. */
std::pair<std::uint32_t, std::uint32_t>
readChunkHeader (const GltfFile& file, std::size_t offset, const std::string& what)
{
  const std::size_t size = file.bytes.size ();
  if (size - offset < 8)
    file.fail ("cut short: " + bytesText (size - offset) + " at byte " + std::to_string (offset) + ", where the " +
               what + " chunk's 8-byte header should be");
  const std::uint32_t length = readUint32 (file.bytes, offset), type = readUint32 (file.bytes, offset + 4);
  if (length > size - offset - 8)
    file.fail ("the " + what + " chunk claims " + bytesText (length) + " but only " + bytesText (size - offset - 8) +
               " follow its header (the file is cut short or the chunk length is wrong)");
  return {length, type};
}

void
checkGlbChunks (GltfFile& file)
{
  const auto [json_length, json_type] = readChunkHeader (file, 12, "JSON");
  if (json_type != kJsonChunk)
    file.fail ("the first chunk is not JSON (its type is " + chunkTypeText (json_type) + ")");
  if (json_length == 0)
    file.fail ("the JSON chunk is empty");
  file.json_offset = 20;
  file.json_length = json_length;
  const std::size_t bin_header = 20 + std::size_t (json_length);
  if (bin_header == file.bytes.size ())
    return;
  const auto [bin_length, bin_type] = readChunkHeader (file, bin_header, "BIN");
  if (bin_type != kBinChunk)
    file.fail ("the chunk after the JSON is not BIN (its type is " + chunkTypeText (bin_type) + ")");
  if (bin_length == 0 || bin_length % 4 != 0)
    file.fail ("the BIN chunk's length " + std::to_string (bin_length) + " is not a positive multiple of 4");
  file.bin_offset = bin_header + 8;
  file.bin_length = bin_length;
}
} // namespace

GltfFile
readGltfBytes (const std::string& path)
{
  GltfFile file;
  file.path = path;
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size (path, ec);
  std::ifstream stream (path, std::ios::binary);
  if (ec || !stream)
    throw IoError (path + ": cannot be opened for reading");
  if (size >= std::numeric_limits<std::uint32_t>::max ())
    file.fail ("holds " + bytesText (size) + ", more than the 4 GB a glTF file can have");
  file.bytes.resize (size);
  if (!stream.read (reinterpret_cast<char*> (file.bytes.data ()), static_cast<std::streamsize> (size)))
    throw IoError (path + ": cannot be read");
  file.binary = size >= 4 && std::memcmp (file.bytes.data (), "glTF", 4) == 0;
  if (!file.binary) {
    file.json_length = file.bytes.size ();
    return file;
  }
  checkGlbHeader (file);
  checkGlbChunks (file);
  return file;
}
} // namespace gltf
} // namespace morphreg

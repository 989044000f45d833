// SPDX-License-Identifier: BSD-3-Clause
#include "gltf_file.h"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cstring>
#include <filesystem>
#include <string_view>

namespace morphreg
{
namespace gltf
{
namespace
{
namespace fs = std::filesystem;
using Json = nlohmann::json;

/** tinygltf reads nested extras recursively: deeper JSON is refused before it is parsed. */
constexpr int kMaxDepth = 64;

void
checkNesting (const GltfFile& file, std::string_view text)
{
  int depth = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      escaped = !escaped && c == '\\';
      in_string = escaped || c != '"';
      continue;
    }
    if (c == '"')
      in_string = true;
    else if ((c == '[' || c == '{') && ++depth > kMaxDepth)
      file.fail ("the JSON is nested deeper than " + std::to_string (kMaxDepth) + " levels");
    else if (c == ']' || c == '}')
      --depth;
  }
}

/** The unsigned whole number \a key of \a item; FormatError naming \a what if it is missing or not one. */
std::uint64_t
requireUnsigned (const GltfFile& file, const Json& item, const char* key, const std::string& what)
{
  const auto value = item.find (key);
  if (value == item.end () || !value->is_number_unsigned ())
    file.fail (what + ": '" + key + "' is " + (value == item.end () ? "missing" : "not a whole number >= 0"));
  return value->get<std::uint64_t> ();
}

/** The array \a key of the document's root (empty if absent); FormatError unless it is an array of objects. */
const Json&
objectArray (const GltfFile& file, const Json& root, const char* key)
{
  static const Json empty = Json::array ();
  const auto array = root.find (key);
  if (array == root.end ())
    return empty;
  if (!array->is_array ())
    file.fail (std::string ("'") + key + "' is not an array");
  for (const Json& item : *array)
    if (!item.is_object ())
      file.fail (std::string ("'") + key + "' holds an item that is not an object");
  return *array;
}

/** Bytes a base64 text of \a text decodes to (tinygltf stops at the first character that is not base64). */
std::uint64_t
base64Bytes (std::string_view text)
{
  std::size_t digits = 0;
  while (digits < text.size () &&
         (std::isalnum (static_cast<unsigned char> (text[digits])) || text[digits] == '+' || text[digits] == '/'))
    ++digits;
  return digits / 4 * 3 + (digits % 4 == 0 ? 0 : digits % 4 - 1);
}

/** %XX escapes decoded, as tinygltf decodes a buffer's uri before looking for the file. */
std::string
percentDecoded (const std::string& uri)
{
  std::string decoded;
  for (std::size_t i = 0; i < uri.size (); ++i) {
    if (uri[i] == '%' && i + 2 < uri.size () && std::isxdigit (static_cast<unsigned char> (uri[i + 1])) &&
        std::isxdigit (static_cast<unsigned char> (uri[i + 2]))) {
      decoded += static_cast<char> (std::stoi (uri.substr (i + 1, 2), nullptr, 16));
      i += 2;
    }
    else
      decoded += uri[i];
  }
  return decoded;
}

/** The bytes buffer \a what's uri provides: a data URI's decoded length, or an external file's size. */
std::uint64_t
uriBytes (const GltfFile& file, const std::string& uri, const std::string& what)
{
  static const char* const kDataPrefixes[] = {"data:application/octet-stream;base64,",
                                              "data:application/gltf-buffer;base64,"};
  for (const char* prefix : kDataPrefixes)
    if (uri.rfind (prefix, 0) == 0)
      return base64Bytes (std::string_view (uri).substr (std::strlen (prefix)));
  if (uri.rfind ("data:", 0) == 0)
    file.fail (what + ": a data URI that is not base64 application/octet-stream or application/gltf-buffer");
  const std::string name = percentDecoded (uri);
  if (name.empty () || name.find ("://") != std::string::npos || name.front () == '/')
    file.fail (what + ": its uri '" + uri.substr (0, 200) + "' is not a relative path to a file next to the glTF file");
  const fs::path located = fs::path (file.path).parent_path () / name;
  std::error_code ec;
  if (!fs::is_regular_file (located, ec))
    file.fail (what + ": its file '" + name + "' does not exist (looked for " + located.string () + ")");
  return fs::file_size (located, ec);
}

/** Each buffer's byteLength against the bytes its source holds; returns the byteLengths. */
std::vector<std::uint64_t>
checkBuffers (const GltfFile& file, const Json& root)
{
  std::vector<std::uint64_t> lengths;
  const Json& buffers = objectArray (file, root, "buffers");
  for (std::size_t b = 0; b < buffers.size (); ++b) {
    const std::string what = "buffer " + std::to_string (b);
    const std::uint64_t length = requireUnsigned (file, buffers[b], "byteLength", what);
    if (length == 0)
      file.fail (what + ": byteLength is 0");
    const auto uri = buffers[b].find ("uri");
    if (uri != buffers[b].end () && !uri->is_string ())
      file.fail (what + ": its uri is not a string");
    if (uri == buffers[b].end () && !(file.binary && b == 0 && file.bin_length > 0))
      file.fail (what + " has no uri, and only the first buffer of a GLB with a BIN chunk may have none");
    const std::uint64_t available =
        uri == buffers[b].end () ? file.bin_length : uriBytes (file, uri->get<std::string> (), what);
    if (uri == buffers[b].end () ? length > available : length != available)
      file.fail (what + ": its byteLength is " + std::to_string (length) + " but its " +
                 (uri == buffers[b].end () ? "BIN chunk" : "data") + " holds " + std::to_string (available) + " bytes");
    lengths.push_back (length);
  }
  return lengths;
}

void
checkBufferViews (const GltfFile& file, const Json& root, const std::vector<std::uint64_t>& buffer_lengths)
{
  const Json& views = objectArray (file, root, "bufferViews");
  for (std::size_t v = 0; v < views.size (); ++v) {
    const std::string what = "bufferView " + std::to_string (v);
    const std::uint64_t buffer = requireUnsigned (file, views[v], "buffer", what);
    if (buffer >= buffer_lengths.size ())
      file.fail (what + ": buffer " + std::to_string (buffer) + " does not exist (the file has " +
                 std::to_string (buffer_lengths.size ()) + ")");
    const std::uint64_t length = requireUnsigned (file, views[v], "byteLength", what);
    const std::uint64_t offset =
        views[v].contains ("byteOffset") ? requireUnsigned (file, views[v], "byteOffset", what) : 0;
    if (length == 0 || offset > buffer_lengths[buffer] || length > buffer_lengths[buffer] - offset)
      file.fail (what + ": bytes " + std::to_string (offset) + " to " + std::to_string (offset + length) +
                 " are not within buffer " + std::to_string (buffer) + "'s " + std::to_string (buffer_lengths[buffer]) +
                 " bytes");
  }
}

void
checkAsset (const GltfFile& file, const Json& root)
{
  if (!root.is_object ())
    file.fail ("the JSON is not an object, so not a glTF document");
  const auto asset = root.find ("asset");
  if (asset == root.end () || !asset->is_object () || !asset->contains ("version") || !(*asset)["version"].is_string ())
    file.fail ("not a glTF document: it has no asset.version");
  const std::string version = (*asset)["version"].get<std::string> ();
  if (version.rfind ("2.", 0) != 0)
    file.fail ("glTF version " + version.substr (0, 20) + "; only glTF 2.0 is read");
}
/** Drops the indices accessor of every Draco-compressed primitive (its indices come from the payload; tinygltf 2.7
 *  refuses an indices accessor without a buffer view, which a Draco primitive's is); returns whether there was one. */
bool
dropDracoIndices (Json& root)
{
  bool dropped = false;
  const auto meshes = root.find ("meshes");
  if (meshes == root.end () || !meshes->is_array ())
    return false;
  for (Json& mesh : *meshes) {
    if (!mesh.is_object () || !mesh.contains ("primitives") || !mesh["primitives"].is_array ())
      continue;
    for (Json& primitive : mesh["primitives"])
      if (primitive.is_object () && primitive.contains ("extensions") && primitive["extensions"].is_object () &&
          primitive["extensions"].contains ("KHR_draco_mesh_compression"))
        dropped = primitive.erase ("indices") > 0 || dropped;
  }
  return dropped;
}

/** \a file with its JSON replaced by \a root (the BIN chunk kept). */
void
replaceJson (GltfFile& file, const Json& root)
{
  std::string json = root.dump ();
  if (!file.binary) {
    file.bytes.assign (json.begin (), json.end ());
    file.json_length = file.bytes.size ();
    return;
  }
  json.resize ((json.size () + 3) / 4 * 4, ' ');
  std::vector<unsigned char> bytes (file.bytes.begin (), file.bytes.begin () + 12);
  const auto append32 = [&bytes] (std::size_t value) {
    for (int i = 0; i < 4; ++i)
      bytes.push_back (static_cast<unsigned char> (value >> (8 * i)));
  };
  append32 (json.size ());
  bytes.insert (bytes.end (), {'J', 'S', 'O', 'N'});
  bytes.insert (bytes.end (), json.begin (), json.end ());
  if (file.bin_length > 0)
    bytes.insert (bytes.end (), file.bytes.begin () + file.bin_offset - 8,
                  file.bytes.begin () + file.bin_offset + file.bin_length);
  for (int i = 0; i < 4; ++i) // the header's length
    bytes[8 + i] = static_cast<unsigned char> (bytes.size () >> (8 * i));
  file.bin_offset = file.bin_length > 0 ? 20 + json.size () + 8 : 0;
  file.json_length = json.size ();
  file.bytes = std::move (bytes);
}
} // namespace

void
checkGltfJson (GltfFile& file)
{
  const auto* text = reinterpret_cast<const char*> (file.bytes.data () + file.json_offset);
  checkNesting (file, std::string_view (text, file.json_length));
  Json root;
  try {
    root = Json::parse (text, text + file.json_length);
  }
  catch (const Json::exception& e) {
    file.fail (std::string ("malformed JSON: ") + e.what ());
  }
  checkAsset (file, root);
  checkBufferViews (file, root, checkBuffers (file, root));
  if (dropDracoIndices (root))
    replaceJson (file, root);
}
} // namespace gltf
} // namespace morphreg

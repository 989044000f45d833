// SPDX-License-Identifier: BSD-3-Clause
// Broken glTF files: each is refused by the loaders with a FormatError naming the file and the problem, never a
// crash or an allocation the file cannot back (tinygltf and Draco see nothing unchecked).
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/mesh_io.h>

#include "support/expect_error.h"
#include "support/glb_writer.h"
#include "support/temp_directory.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>

namespace gltf = morphreg::test::gltf;
using morphreg::test::TempDirectory;

namespace
{
/** A tetrahedron in metres, one triangle primitive with indices. */
gltf::Primitive
tetrahedron ()
{
  gltf::Primitive primitive;
  primitive.positions.resize (3, 4);
  primitive.positions << 0, 0.1f, 0, 0, 0, 0, 0.1f, 0, 0, 0, 0, 0.1f;
  primitive.indices = {0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3};
  return primitive;
}

gltf::Parts
tetrahedronParts ()
{
  return gltf::build (gltf::singleNode (tetrahedron ()));
}

/** Expects both loaders to refuse \a path with a FormatError naming it and containing \a problem. */
void
expectRefused (const std::string& path, const std::string& problem)
{
  for (int loader = 0; loader < 2; ++loader)
    morphreg::test::expectErrorContaining<morphreg::FormatError> (
        [&] {
          if (loader == 0)
            morphreg::loadPolygonMesh (path);
          else
            morphreg::loadCloud<pcl::PointXYZ> (path);
        },
        path + ": " + problem);
}

void
writeBytes (const std::string& path, const std::vector<unsigned char>& bytes)
{
  gltf::writeBytes (path, bytes.data (), bytes.size ());
}

void
setUint32 (std::vector<unsigned char>& bytes, std::size_t offset, std::uint32_t value)
{
  for (int i = 0; i < 4; ++i)
    bytes.at (offset + i) = static_cast<unsigned char> (value >> (8 * i));
}
} // namespace

TEST (GltfBadInputTest, BrokenContainers)
{
  TempDirectory dir;
  const std::vector<unsigned char> good = gltf::glbBytes (tetrahedronParts ());
  writeBytes (dir.file ("cut.glb"), {good.begin (), good.begin () + good.size () / 2});
  expectRefused (dir.file ("cut.glb"), "the GLB header gives a length of " + std::to_string (good.size ()) +
                                           " bytes but the file holds " + std::to_string (good.size () / 2) +
                                           " bytes (the file is cut short)");
  writeBytes (dir.file ("header_only.glb"), {good.begin (), good.begin () + 8});
  expectRefused (dir.file ("header_only.glb"), "cut short: 8 bytes, fewer than the 12 of a GLB header");
  std::vector<unsigned char> magic = good;
  magic[3] = 'X';
  writeBytes (dir.file ("magic.glb"), magic);
  expectRefused (dir.file ("magic.glb"), "not a GLB file: it does not start with the magic bytes 'glTF'");
  std::vector<unsigned char> version = good;
  setUint32 (version, 4, 1);
  writeBytes (dir.file ("version.glb"), version);
  expectRefused (dir.file ("version.glb"), "GLB version 1; only glTF 2.0 (version 2) is read");
  std::vector<unsigned char> json_length = good;
  setUint32 (json_length, 12, 0x7ffffff0);
  writeBytes (dir.file ("json_past_end.glb"), json_length);
  expectRefused (dir.file ("json_past_end.glb"), "the JSON chunk claims 2147483632 bytes but only ");
  std::vector<unsigned char> bin_length = good;
  const std::size_t bin_header = 20 + (good[12] | good[13] << 8 | good[14] << 16);
  setUint32 (bin_length, bin_header, static_cast<std::uint32_t> (good.size ()));
  writeBytes (dir.file ("bin_past_end.glb"), bin_length);
  expectRefused (dir.file ("bin_past_end.glb"), "the BIN chunk claims " + std::to_string (good.size ()) + " bytes");
  std::vector<unsigned char> chunk_type = good;
  chunk_type[16] = 'X';
  writeBytes (dir.file ("chunk_type.glb"), chunk_type);
  expectRefused (dir.file ("chunk_type.glb"), "the first chunk is not JSON");
}

TEST (GltfBadInputTest, BrokenJson)
{
  TempDirectory dir;
  gltf::writeBytes (dir.file ("malformed.gltf"), "{\"asset\": {\"version\": \"2.0\"", 27);
  expectRefused (dir.file ("malformed.gltf"), "malformed JSON: ");
  gltf::writeBytes (dir.file ("old.gltf"), "{\"asset\": {\"version\": \"1.0\"}}", 30);
  expectRefused (dir.file ("old.gltf"), "glTF version 1.0; only glTF 2.0 is read");
  gltf::Parts deep = tetrahedronParts ();
  nlohmann::json nested = 1;
  for (int i = 0; i < 200; ++i)
    nested = nlohmann::json::array ({nested});
  deep.json["extras"] = nested;
  gltf::writeGlb (dir.file ("deep.glb"), deep);
  expectRefused (dir.file ("deep.glb"), "the JSON is nested deeper than 64 levels");
  gltf::Parts extension = tetrahedronParts ();
  extension.json["extensionsRequired"] = {"EXT_meshopt_compression"};
  gltf::writeGlb (dir.file ("extension.glb"), extension);
  expectRefused (dir.file ("extension.glb"),
                 "requires the glTF extension EXT_meshopt_compression, which morphreg does not read");
}

TEST (GltfBadInputTest, SizesBeyondTheData)
{
  TempDirectory dir;
  const std::vector<std::pair<std::string, std::function<void (nlohmann::json&)>>> cases = {
      {"buffer 0: its byteLength is 1000000000000 but its BIN chunk holds ",
       [] (nlohmann::json& json) { json["buffers"][0]["byteLength"] = 1000000000000ull; }},
      {"bufferView 0: bytes 0 to 1000000000000000 are not within buffer 0's ",
       [] (nlohmann::json& json) { json["bufferViews"][0]["byteLength"] = 1000000000000000ull; }},
      {"mesh 0 primitive 0 POSITION: the accessor claims 4000000000000 elements",
       [] (nlohmann::json& json) { json["accessors"][0]["count"] = 4000000000000ull; }},
      {"mesh 0 primitive 0 POSITION: accessor 99 does not exist (the file has 2)",
       [] (nlohmann::json& json) { json["meshes"][0]["primitives"][0]["attributes"]["POSITION"] = 99; }},
      {"bufferView 0: buffer 7 does not exist", [] (nlohmann::json& json) { json["bufferViews"][0]["buffer"] = 7; }},
      {"node 0 is reached twice: the node hierarchy has a cycle",
       [] (nlohmann::json& json) { json["nodes"][0]["children"] = {0}; }},
      {"node 0: mesh 3 does not exist", [] (nlohmann::json& json) { json["nodes"][0]["mesh"] = 3; }},
      {"the scene holds neither triangles nor points",
       [] (nlohmann::json& json) { json["scenes"][0]["nodes"] = nlohmann::json::array (); }},
      {"mesh 0 primitive 0: 11 corners, not a multiple of 3",
       [] (nlohmann::json& json) { json["accessors"][1]["count"] = 11; }}};
  for (std::size_t c = 0; c < cases.size (); ++c) {
    gltf::Parts parts = tetrahedronParts ();
    cases[c].second (parts.json);
    const std::string path = dir.file ("case" + std::to_string (c) + ".glb");
    gltf::writeGlb (path, parts);
    expectRefused (path, cases[c].first);
  }
}

TEST (GltfBadInputTest, IndexBeyondTheVertices)
{
  TempDirectory dir;
  gltf::Primitive primitive = tetrahedron ();
  primitive.indices[5] = 1000;
  gltf::writeGlb (dir.file ("index.glb"), gltf::build (gltf::singleNode (primitive)));
  expectRefused (dir.file ("index.glb"), "mesh 0 primitive 0: index 5 is 1000, beyond the primitive's 4 vertices");
}

TEST (GltfBadInputTest, BadDracoPayload)
{
  TempDirectory dir;
  gltf::Primitive primitive = tetrahedron ();
  primitive.draco = true;
  gltf::Parts parts = gltf::build (gltf::singleNode (primitive));
  const int view = parts.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["bufferView"];
  const std::size_t offset = parts.json["bufferViews"][view]["byteOffset"];
  const std::size_t length = parts.json["bufferViews"][view]["byteLength"];
  gltf::Parts garbled = parts;
  for (std::size_t i = offset + 11; i < offset + length; ++i)
    garbled.bin[i] = static_cast<unsigned char> (i * 37);
  gltf::writeGlb (dir.file ("garbled.glb"), garbled);
  expectRefused (dir.file ("garbled.glb"), "mesh 0 primitive 0: bad Draco payload: it cannot be decoded as a mesh");
  gltf::Parts no_header = parts;
  no_header.bin[offset] = 'X';
  gltf::writeGlb (dir.file ("no_header.glb"), no_header);
  expectRefused (dir.file ("no_header.glb"), "mesh 0 primitive 0: bad Draco payload: buffer view " +
                                                 std::to_string (view) +
                                                 " does not start with the Draco header 'DRACO'");
  gltf::Parts missing = parts;
  missing.json["meshes"][0]["primitives"][0]["extensions"]["KHR_draco_mesh_compression"]["attributes"]["POSITION"] = 9;
  gltf::writeGlb (dir.file ("attribute.glb"), missing);
  expectRefused (dir.file ("attribute.glb"),
                 "mesh 0 primitive 0 POSITION: the Draco payload has no attribute with id 9");
}

TEST (GltfBadInputTest, ExternalAndEmbeddedBuffers)
{
  TempDirectory dir;
  const gltf::Parts parts = tetrahedronParts ();
  gltf::writeGltf (dir.file ("missing.gltf"), parts, "missing.bin");
  std::filesystem::remove (dir.file ("missing.bin"));
  expectRefused (dir.file ("missing.gltf"),
                 "buffer 0: its file 'missing.bin' does not exist (looked for " + dir.file ("missing.bin") + ")");
  gltf::writeGltf (dir.file ("short.gltf"), parts, "short.bin");
  std::filesystem::resize_file (dir.file ("short.bin"), 10);
  expectRefused (dir.file ("short.gltf"),
                 "buffer 0: its byteLength is " + std::to_string (parts.bin.size ()) + " but its data holds 10 bytes");
  gltf::Parts uri = parts;
  uri.json["buffers"][0]["byteLength"] = parts.bin.size () + 30;
  gltf::writeGltf (dir.file ("data_uri.gltf"), uri, "");
  expectRefused (dir.file ("data_uri.gltf"), "buffer 0: its byteLength is " + std::to_string (parts.bin.size () + 30));
  gltf::Parts remote = parts;
  remote.json["buffers"][0]["uri"] = "https://example.com/scan.bin";
  const std::string json = remote.json.dump ();
  gltf::writeBytes (dir.file ("remote.gltf"), json.data (), json.size ());
  expectRefused (dir.file ("remote.gltf"), "buffer 0: its uri 'https://example.com/scan.bin' is not a relative path");
}

TEST (GltfBadInputTest, BrokenTexture)
{
  TempDirectory dir;
  gltf::Primitive primitive = tetrahedron ();
  primitive.uv = Eigen::Matrix2Xf::Zero (2, 4);
  primitive.material = 0;
  gltf::Document document = gltf::singleNode (primitive);
  document.images = {{{0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n', 1, 2, 3}, "image/png"}};
  document.materials = {{0, {}}};
  gltf::writeGlb (dir.file ("png.glb"), gltf::build (document));
  expectRefused (dir.file ("png.glb"), "image 0: cannot be decoded");
  document.images[0].bytes = {'G', 'I', 'F', '8'};
  gltf::writeGlb (dir.file ("gif.glb"), gltf::build (document));
  expectRefused (dir.file ("gif.glb"), "image 0: not a PNG or JPEG image");
}

// SPDX-License-Identifier: BSD-3-Clause
// gltf_test_files OUT_DIR [SHARED_DATA_DIR]: writes the glTF files of the command line's tests with the tests' own
// writer (test/support/glb_writer.h): the bad-input catalogue's broken files (test/scripts/cli_catalogue.cmake), and,
// when SHARED_DATA_DIR holds the real head scans, their glTF versions <scan>_<variant>.glb (test/scripts/gltf.cmake).
#include "support/scan_glb_variants.h"

#include <filesystem>
#include <iostream>

namespace gltf = morphreg::test::gltf;

namespace
{
/** A 0.2 m square grid of 11 x 11 vertices, gently curved: a valid triangle primitive to break. */
gltf::Primitive
grid ()
{
  gltf::Primitive primitive;
  primitive.positions.resize (3, 121);
  for (int i = 0; i < 121; ++i)
    primitive.positions.col (i) << 0.02f * (i % 11), 0.02f * (i / 11), 0.001f * ((i % 11) * (i / 11) % 7);
  for (std::uint32_t r = 0; r < 10; ++r)
    for (std::uint32_t c = 0; c < 10; ++c)
      primitive.indices.insert (primitive.indices.end (), {11 * r + c, 11 * r + c + 1, 11 * r + c + 12, 11 * r + c,
                                                           11 * r + c + 12, 11 * r + c + 11});
  return primitive;
}

std::vector<unsigned char>
glbOf (const gltf::Parts& parts)
{
  return gltf::glbBytes (parts);
}

void
write (const std::string& path, const std::vector<unsigned char>& bytes)
{
  gltf::writeBytes (path, bytes.data (), bytes.size ());
}

void
writeBrokenFiles (const std::string& out)
{
  const gltf::Parts parts = gltf::build (gltf::singleNode (grid ()));
  const std::vector<unsigned char> good = glbOf (parts);
  write (out + "/cut.glb", {good.begin (), good.begin () + good.size () / 2});
  std::vector<unsigned char> magic = good;
  magic[3] = 'X';
  write (out + "/magic.glb", magic);
  std::vector<unsigned char> chunk = good;
  chunk[15] = 0x70; // the JSON chunk's length: about 1.9 GB
  write (out + "/chunk_past_end.glb", chunk);
  gltf::Parts accessor = parts;
  accessor.json["accessors"][0]["count"] = 5000000;
  write (out + "/accessor_out_of_range.glb", glbOf (accessor));
  gltf::Primitive index = grid ();
  index.indices[7] = 100000;
  write (out + "/index_out_of_range.glb", glbOf (gltf::build (gltf::singleNode (index))));
  gltf::Primitive draco = grid ();
  draco.draco = true;
  gltf::Parts garbled = gltf::build (gltf::singleNode (draco));
  const std::size_t payload = garbled.json["bufferViews"].back ()["byteOffset"];
  for (std::size_t i = payload + 11; i < garbled.bin.size (); ++i)
    garbled.bin[i] = static_cast<unsigned char> (i * 37);
  write (out + "/bad_draco.glb", glbOf (garbled));
  gltf::writeGltf (out + "/missing_buffer.gltf", parts, "missing_buffer.bin");
  std::filesystem::remove (out + "/missing_buffer.bin");
  gltf::Parts absurd = parts;
  absurd.json["accessors"][0]["count"] = 1000000000000000ull;
  gltf::writeGltf (out + "/absurd_counts.gltf", absurd, "");
}

/** The glTF versions of one real scan, if its file exists. */
void
writeScanVersions (const std::string& out, const std::string& name, const std::string& scan,
                   const std::string& texture = "")
{
  if (!std::filesystem::exists (scan)) {
    std::cout << scan << " is absent: no glTF versions of " << name << "\n";
    return;
  }
  const morphreg::test::GlbSource source = morphreg::test::glbSource (scan, texture);
  for (const morphreg::test::GlbVariant variant : morphreg::test::kGlbVariants)
    gltf::writeGlb (out + "/" + name + "_" + morphreg::test::variantName (variant) + ".glb",
                    gltf::build (morphreg::test::variantDocument (source, variant)));
  std::cout << "wrote the glTF versions of " << scan << "\n";
}
} // namespace

int
main (int argc, char** argv)
{
  if (argc < 2 || argc > 3) {
    std::cerr << "usage: gltf_test_files OUT_DIR [SHARED_DATA_DIR]\n";
    return 2;
  }
  try {
    std::filesystem::create_directories (argv[1]);
    writeBrokenFiles (argv[1]);
    if (argc == 3) {
      const std::string scans = std::string (argv[2]) + "/real_head_scans/";
      writeScanVersions (argv[1], "lee", scans + "leeperrysmith_head_mm.ply");
      writeScanVersions (argv[1], "james", scans + "menpo3d_james/james.obj", scans + "menpo3d_james/james.jpg");
      writeScanVersions (argv[1], "demoface", scans + "meshmonk_demoface/demoface_10k.obj");
    }
  }
  catch (const std::exception& e) {
    std::cerr << "gltf_test_files: " << e.what () << "\n";
    return 1;
  }
  return 0;
}

// SPDX-License-Identifier: BSD-3-Clause
// The shared real scans (Lee Perry-Smith's mesh, the james capture with its texture, the demoface capture) written as
// glTF by the tests' writer (plain, Draco, under a node transform, as two primitives, in an arbitrary unit) and read
// back: the geometry is the original's to float precision (after the m to mm conversion, the node's transform and
// the arbitrary unit's scale), and the james texture gives the OBJ's colours. Their registrations: CliTest.GltfSameFit.
#include "support/scan_glb_variants.h"
#include "support/temp_directory.h"

#include <morphreg/io/gltf_reader.h>
#include <morphreg/io/mesh_io.h>

#include <gtest/gtest.h>

#include <filesystem>

namespace
{
using namespace morphreg::test;

struct RealScan
{
  const char* name;
  const char* file;
  const char* texture;
};

const RealScan kScans[] = {{"lee", "leeperrysmith_head_mm.ply", ""},
                           {"james", "menpo3d_james/james.obj", "menpo3d_james/james.jpg"},
                           {"demoface", "meshmonk_demoface/demoface_10k.obj", ""}};

std::string
scanPath (const std::string& file)
{
  return std::string (MORPHREG_SHARED_DATA_DIR) + "/real_head_scans/" + file;
}

/** Every read vertex at its vertex of \a expected (float precision: 1e-6 of the coordinates' size, 0.4 um here), the
 *  triangles the original's in order (Draco: as a set of vertices, since Edgebreaker reorders them). */
void
expectGeometry (const morphreg::ColouredSurface& read, const Eigen::Matrix3Xd& expected,
                const morphreg::TriangleMesh& source, bool ordered, const std::string& what)
{
  const double tolerance = 1e-6 * expected.cwiseAbs ().maxCoeff ();
  ASSERT_EQ (read.triangles.cols (), source.triangles.cols ()) << what;
  double worst = 0.0;
  if (ordered)
    for (Eigen::Index t = 0; t < source.triangles.cols (); ++t)
      for (int k = 0; k < 3; ++k)
        worst = std::max (
            worst,
            (read.points.col (read.triangles (k, t)) - expected.col (source.triangles (k, t))).cwiseAbs ().maxCoeff ());
  else
    for (Eigen::Index v = 0; v < read.points.cols (); ++v)
      worst = std::max (worst, (expected.colwise () - read.points.col (v)).colwise ().norm ().minCoeff ());
  EXPECT_LE (worst, tolerance) << what << ": a vertex is " << worst << " mm from the original's";
}
} // namespace

TEST (GltfRealScanTest, EveryVersionReadsAsTheOriginalGeometry)
{
  for (const RealScan& scan : kScans) {
    if (!std::filesystem::exists (scanPath (scan.file))) {
      GTEST_SKIP () << scanPath (scan.file)
                    << " is absent (../shared/data): the real scans' glTF versions are not tested";
    }
    TempDirectory dir;
    const GlbSource source = glbSource (scanPath (scan.file), *scan.texture ? scanPath (scan.texture) : "");
    const auto original_vertices = morphreg::loadPolygonMesh (scanPath (scan.file)).cloud.width;
    for (const GlbVariant variant : kGlbVariants) {
      const std::string what = std::string (scan.name) + " " + variantName (variant);
      const std::string path = dir.file (what + ".glb");
      gltf::writeGlb (path, gltf::build (variantDocument (source, variant)));
      const morphreg::GltfContent content = morphreg::readGltfFile (path);
      // texture seams and Draco's non-manifold splits repeat vertices in the file; read, the original's remain
      EXPECT_EQ (content.surface.points.cols (), original_vertices) << what;
      expectGeometry (content.surface, variantExpectedVertices (source, variant), source.mesh,
                      variant != GlbVariant::draco, what);
    }
  }
}

TEST (GltfRealScanTest, JamesTextureGivesTheObjColours)
{
  const std::string obj = scanPath ("menpo3d_james/james.obj");
  if (!std::filesystem::exists (obj))
    GTEST_SKIP () << obj << " is absent (../shared/data): the glTF texture of james is not tested";
  TempDirectory dir;
  const GlbSource source = glbSource (obj, scanPath ("menpo3d_james/james.jpg"));
  gltf::writeGlb (dir.file ("james.glb"), gltf::build (variantDocument (source, GlbVariant::plain)));
  const morphreg::ColouredSurface glb = morphreg::readGltfFile (dir.file ("james.glb")).surface;
  const morphreg::ColouredSurface original = morphreg::loadColouredSurface (obj);
  ASSERT_EQ (glb.textures.size (), 1u);
  EXPECT_EQ (glb.textures[0].width, 2400);
  EXPECT_EQ (glb.textures[0].height, 1600);
  // the colours at the surface near every original vertex (1 mm off it, along a fixed direction)
  const Eigen::Matrix3Xd queries = original.points.colwise () + Eigen::Vector3d (0.6, -0.5, 0.6);
  const morphreg::VertexColours from_glb = morphreg::sampleNearestColours (glb, queries);
  const morphreg::VertexColours from_obj = morphreg::sampleNearestColours (original, queries);
  // the same colour but where the nearest surface point lies on a texture seam (equidistant triangles of both sides)
  const Eigen::ArrayXi difference = (from_glb.cast<int> () - from_obj.cast<int> ()).cwiseAbs ().colwise ().maxCoeff ();
  EXPECT_GE ((difference <= 1).cast<double> ().mean (), 0.99) << "largest difference " << difference.maxCoeff ();
  EXPECT_GT ((from_obj.cast<int> ().row (0) - from_obj.cast<int> ().row (2)).cast<double> ().mean (), 20.0)
      << "james's skin should be red above blue";
}

// SPDX-License-Identifier: BSD-3-Clause
// Texture from the frontal photo: the PNG/JPEG reader, visibility (facing, occlusion) on meshes whose answer is
// known, and the colours of a fitted synthetic head.
#include "photo_test_model.h"
#include "support/accuracy_bound.h"
#include "support/temp_directory.h"

#include <morphreg/io/rgb_image_io.h>
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/photo/photo_texture.h>
#include <morphreg/photo/photo_fitting.h>
#include <morphreg/synthetic/photo_simulator.h>

#include <gtest/gtest.h>

#include <fstream>
#include <iostream>

namespace
{
using morphreg::RgbImage;

/** A test photo whose colour encodes the pixel: red = column / \a step, green = row / \a step, blue 77. */
RgbImage
gradientImage (int width, int height, int step)
{
  RgbImage image{width, height, std::vector<unsigned char> (3 * static_cast<size_t> (width) * height)};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      unsigned char* p = image.data.data () + 3 * (static_cast<size_t> (y) * width + x);
      p[0] = static_cast<unsigned char> (x / step);
      p[1] = static_cast<unsigned char> (y / step);
      p[2] = 77;
    }
  return image;
}

/** A grid of \a n x \a n vertices over [-half, half]^2 at depth \a z, triangulated facing +Z (or -Z if \a away). */
morphreg::TriangleMesh
square (int n, double half, double z, bool away = false)
{
  morphreg::TriangleMesh mesh;
  mesh.vertices.resize (3, n * n);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      mesh.vertices.col (j * n + i) << -half + 2.0 * half * i / (n - 1), -half + 2.0 * half * j / (n - 1), z;
  mesh.triangles.resize (3, 2 * (n - 1) * (n - 1));
  int t = 0;
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      mesh.triangles.col (t++) = away ? Eigen::Vector3i (a, c, b) : Eigen::Vector3i (a, b, c);
      mesh.triangles.col (t++) = away ? Eigen::Vector3i (b, c, d) : Eigen::Vector3i (b, d, c);
    }
  return mesh;
}

morphreg::TriangleMesh
merge (const morphreg::TriangleMesh& a, const morphreg::TriangleMesh& b)
{
  morphreg::TriangleMesh mesh;
  mesh.vertices.resize (3, a.numVertices () + b.numVertices ());
  mesh.vertices << a.vertices, b.vertices;
  mesh.triangles.resize (3, a.triangles.cols () + b.triangles.cols ());
  mesh.triangles << a.triangles, (b.triangles.array () + static_cast<int> (a.numVertices ())).matrix ();
  return mesh;
}

TEST (FrontalTextureTest, PngRoundTripAndUnreadableFilesAreNamed)
{
  const morphreg::test::TempDirectory directory;
  const RgbImage image = gradientImage (37, 23, 1);
  morphreg::saveRgbImage (directory.file ("photo.png"), image);
  const RgbImage read = morphreg::loadRgbImage (directory.file ("photo.png"));
  EXPECT_EQ (read.width, 37);
  EXPECT_EQ (read.height, 23);
  EXPECT_EQ (read.data, image.data);
  EXPECT_EQ (read.pixel (5, 20), morphreg::Rgb8 (5, 20, 77)); // row 20 from the top
  EXPECT_THROW (morphreg::loadRgbImage (directory.file ("missing.png")), morphreg::IoError);
  std::ofstream (directory.file ("text.png")) << "not an image";
  try {
    morphreg::loadRgbImage (directory.file ("text.png"));
    ADD_FAILURE () << "no exception";
  }
  catch (const morphreg::FormatError& e) {
    EXPECT_NE (std::string (e.what ()).find ("text.png"), std::string::npos) << e.what ();
  }
  EXPECT_THROW (morphreg::saveRgbImage (directory.file ("empty.png"), RgbImage ()), morphreg::InvalidInputError);
}

TEST (FrontalTextureTest, HiddenAndAwayFacingVerticesAreFlaggedOthersGetTheirPixel)
{
  // A 200 x 200 photo centred on the origin: pixel = 100 + 200 (u, -v). A front square over the middle of a larger
  // back square hides the back square's 3 x 3 middle vertices; a square facing away is never seen.
  const morphreg::PhotoNormalisation frame (200, 200, Eigen::Vector2d (100.0, 100.0), "test");
  const morphreg::TriangleMesh back = square (5, 0.2, 0.0), front = square (2, 0.15, 0.05);
  const morphreg::TriangleMesh mesh = merge (merge (back, front), square (3, 0.1, 0.1, true));
  const morphreg::VertexTexture texture = morphreg::frontalTexture (mesh, frame, gradientImage (200, 200, 1));
  for (Eigen::Index i = 0; i < mesh.numVertices (); ++i) {
    const Eigen::Vector3d v = mesh.vertices.col (i);
    const bool hidden = i < back.numVertices () && std::abs (v.x ()) < 0.11 && std::abs (v.y ()) < 0.11;
    const bool away = i >= back.numVertices () + front.numVertices ();
    EXPECT_EQ (texture.visible[i], !hidden && !away) << "vertex " << i;
    if (!texture.visible[i]) {
      EXPECT_EQ (texture.colours.col (i), morphreg::Rgb8 (128, 128, 128));
      continue;
    }
    const Eigen::Vector2d pixel = frame.toPixel (v.head<2> ());
    // The gradient is linear, so the bilinear sample is the pixel position (clamped to the last column and row).
    EXPECT_NEAR (texture.colours (0, i), std::min (std::round (pixel.x () - 0.5), 199.0), 1.0) << i;
    EXPECT_NEAR (texture.colours (1, i), std::min (std::round (pixel.y () - 0.5), 199.0), 1.0) << i;
    EXPECT_EQ (texture.colours (2, i), 77);
  }
  EXPECT_EQ (texture.visibleCount (), 16 + 4);
  EXPECT_THROW (morphreg::frontalTexture (mesh, frame, gradientImage (100, 200, 1)), morphreg::InvalidInputError);
}

TEST (FrontalTextureTest, FittedHeadTakesTheColoursAtItsLandmarks)
{
  const auto& generator = morphreg::test::headGenerator (morphreg::test::kPhotoResolution);
  const Eigen::Matrix3Xd truth = generator.sample (500000).mesh.vertices;
  morphreg::synthetic::PhotoSimulator::Parameters camera;
  const auto photos = morphreg::synthetic::PhotoSimulator (camera).photograph (
      truth, morphreg::test::frontalLandmarks (), generator.profileLine (), 3);
  const morphreg::PhotoFit fit =
      morphreg::PhotoFitting (morphreg::test::photoTestModel ().model).fitJoint (photos.profile, photos.frontal);
  const RgbImage image = gradientImage (camera.width, camera.height, 5);
  const morphreg::VertexTexture texture =
      morphreg::frontalTexture (fit.image_mesh, photos.frontal.normalisation (), image);
  const auto& landmarks = morphreg::test::photoTestModel ().model->landmarks ();
  // Face landmarks are seen and coloured as the photo where they were marked (within the fit's error of a few px).
  for (const char* id : {"nose_tip", "left_eye_outer", "right_mouth_corner", "upper_lip_center"}) {
    const int vertex = landmarks.at (id);
    ASSERT_TRUE (texture.visible[vertex]) << id;
    const Eigen::Vector2d marked = photos.frontal.landmarks ().at (id);
    const morphreg::Rgb8 expected = image.pixel (static_cast<int> (marked.x ()), static_cast<int> (marked.y ()));
    EXPECT_LE (std::abs (texture.colours (0, vertex) - expected[0]), 2) << id;
    EXPECT_LE (std::abs (texture.colours (1, vertex) - expected[1]), 2) << id;
  }
  // The back of the head faces away.
  Eigen::Index back;
  fit.image_mesh.vertices.row (2).minCoeff (&back);
  EXPECT_FALSE (texture.visible[back]);
  // Visible: the vertices facing the camera, but for the few hidden behind others (under the nose, behind the ears).
  const Eigen::Matrix3Xd normals = morphreg::vertexNormals (fit.image_mesh);
  const int facing = static_cast<int> ((normals.row (2).array () > 0.0).count ());
  std::cout << "visible from the front: " << texture.visibleCount () << " of " << facing << " facing the camera, "
            << fit.image_mesh.numVertices () << " in all\n";
  // Measured: 2346 of 2431 (0.965).
  EXPECT_LE (texture.visibleCount (), facing);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightLowerBound, static_cast<double> (texture.visibleCount ()) / facing, 0.957);
  EXPECT_LT (facing, 0.8 * fit.image_mesh.numVertices ());
}

/** A \a width x \a height photo of one colour. */
RgbImage
plainImage (int width, int height, unsigned char red, unsigned char green, unsigned char blue)
{
  RgbImage image{width, height, std::vector<unsigned char> (3 * static_cast<size_t> (width) * height)};
  for (size_t k = 0; k < image.data.size (); k += 3) {
    image.data[k] = red;
    image.data[k + 1] = green;
    image.data[k + 2] = blue;
  }
  return image;
}

// Texture from every photo (issue 34, item 4): a square facing +Z seen straight on by a red photo and at 60 degrees by
// a blue one takes both, weighted by the squared cosine of the viewing angle (1 and 1/4: 4/5 red, 1/5 blue); a green
// photo from behind sees its back and gives nothing.
TEST (FrontalTextureTest, EveryPhotoColoursTheVerticesItSeesWeightedByTheViewingAngle)
{
  const morphreg::TriangleMesh mesh = square (9, 10.0, 0.0);
  const Eigen::Matrix3d front = Eigen::Vector3d (1.0, -1.0, -1.0).asDiagonal (); // looks along -Z, image y down
  const auto camera = [&] (double degrees) {
    return morphreg::PhotoCamera::orthographic (
        front * Eigen::AngleAxisd (degrees * M_PI / 180.0, Eigen::Vector3d::UnitY ()).toRotationMatrix (), 4.0,
        Eigen::Vector2d (100.0, 100.0));
  };
  const RgbImage red = plainImage (200, 200, 200, 0, 0), blue = plainImage (200, 200, 0, 0, 200),
                 green = plainImage (200, 200, 0, 200, 0);
  const morphreg::VertexTexture texture =
      morphreg::blendedTexture (mesh, {{camera (0.0), &red}, {camera (60.0), &blue}, {camera (180.0), &green}});
  EXPECT_EQ (texture.visibleCount (), static_cast<int> (mesh.numVertices ()));
  for (Eigen::Index v = 0; v < mesh.numVertices (); ++v) {
    EXPECT_NEAR (texture.colours (0, v), 160, 1) << v;
    EXPECT_EQ (texture.colours (1, v), 0) << v;
    EXPECT_NEAR (texture.colours (2, v), 40, 1) << v;
  }
  // Only the photo from behind: nothing is seen.
  EXPECT_EQ (morphreg::blendedTexture (mesh, {{camera (180.0), &green}}).visibleCount (), 0);
  // A photo whose pixels are missing is named.
  const RgbImage empty{200, 200, {}};
  EXPECT_THROW (morphreg::blendedTexture (mesh, {{camera (0.0), &empty}}), morphreg::InvalidInputError);
}
} // namespace

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/photo/photo_texture.h>
#include <morphreg/photo/photo_view.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace morphreg
{
namespace
{
/** Largest depth (pixels, towards the camera) of \a mesh's triangles at each pixel centre (row by row). */
std::vector<double>
depthBuffer (const Eigen::Matrix3Xd& pixels, const TriangleMesh::Triangles& triangles, int width, int height)
{
  std::vector<double> depth (static_cast<size_t> (width) * height, -std::numeric_limits<double>::infinity ());
  for (Eigen::Index t = 0; t < triangles.cols (); ++t) {
    const Eigen::Vector3d a = pixels.col (triangles (0, t)), b = pixels.col (triangles (1, t)),
                          c = pixels.col (triangles (2, t));
    const double area = (b.x () - a.x ()) * (c.y () - a.y ()) - (c.x () - a.x ()) * (b.y () - a.y ());
    if (std::abs (area) < 1e-12)
      continue;
    const int x0 = std::max (0, static_cast<int> (std::floor (std::min ({a.x (), b.x (), c.x ()}))));
    const int x1 = std::min (width - 1, static_cast<int> (std::ceil (std::max ({a.x (), b.x (), c.x ()}))));
    const int y0 = std::max (0, static_cast<int> (std::floor (std::min ({a.y (), b.y (), c.y ()}))));
    const int y1 = std::min (height - 1, static_cast<int> (std::ceil (std::max ({a.y (), b.y (), c.y ()}))));
    for (int y = y0; y <= y1; ++y)
      for (int x = x0; x <= x1; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        // Barycentric coordinates of the pixel centre; inside when all are >= 0.
        const double wa = ((b.x () - px) * (c.y () - py) - (c.x () - px) * (b.y () - py)) / area;
        const double wb = ((c.x () - px) * (a.y () - py) - (a.x () - px) * (c.y () - py)) / area;
        const double wc = 1.0 - wa - wb;
        if (wa < 0.0 || wb < 0.0 || wc < 0.0)
          continue;
        double& d = depth[static_cast<size_t> (y) * width + x];
        d = std::max (d, wa * a.z () + wb * b.z () + wc * c.z ());
      }
  }
  return depth;
}

/** Bilinear colour of \a image at the pixel position \a p (pixel centres at +0.5), clamped to the image. */
Rgb8
sampleBilinear (const RgbImage& image, const Eigen::Vector2d& p)
{
  const double x = std::clamp (p.x () - 0.5, 0.0, image.width - 1.0);
  const double y = std::clamp (p.y () - 0.5, 0.0, image.height - 1.0);
  const int x0 = static_cast<int> (x), y0 = static_cast<int> (y);
  const int x1 = std::min (x0 + 1, image.width - 1), y1 = std::min (y0 + 1, image.height - 1);
  const double fx = x - x0, fy = y - y0;
  const Eigen::Vector3d colour =
      (1 - fy) * ((1 - fx) * image.pixel (x0, y0).cast<double> () + fx * image.pixel (x1, y0).cast<double> ()) +
      fy * ((1 - fx) * image.pixel (x0, y1).cast<double> () + fx * image.pixel (x1, y1).cast<double> ());
  return colour.array ().round ().cast<unsigned char> ();
}

/** One photo's colour of each vertex and its weight (0 where the camera does not see the vertex). */
struct ViewColours
{
  Eigen::Matrix3Xd colours;
  Eigen::VectorXd weights;
};

ViewColours
viewColours (const TriangleMesh& mesh, const TexturePhoto& photo, double depth_tolerance)
{
  const RgbImage& image = *photo.image;
  if (image.width <= 0 || image.height <= 0 ||
      image.data.size () != 3 * static_cast<size_t> (image.width) * static_cast<size_t> (image.height))
    throw InvalidInputError ("blendedTexture: an image is empty or its data does not match its size");
  const Eigen::Index n = mesh.numVertices ();
  const PhotoCamera& camera = photo.camera;
  // Vertices in pixels: (x, y) in the photo, and how near the camera they lie, in pixels at the head.
  const double pixels_per_unit = camera.pixelsPerUnit (mesh.vertices.rowwise ().mean ());
  Eigen::Matrix3Xd pixels (3, n);
  for (Eigen::Index i = 0; i < n; ++i) {
    pixels.col (i).head<2> () = camera.project (mesh.vertices.col (i));
    pixels (2, i) = -camera.toCamera (mesh.vertices.col (i)).z () * pixels_per_unit;
  }
  const std::vector<double> depth = depthBuffer (pixels, mesh.triangles, image.width, image.height);
  const Eigen::Matrix3Xd normals = vertexNormals (mesh);
  ViewColours view{Eigen::Matrix3Xd::Zero (3, n), Eigen::VectorXd::Zero (n)};
  for (Eigen::Index i = 0; i < n; ++i) {
    const double x = pixels (0, i), y = pixels (1, i);
    const double facing = normals.col (i).dot (camera.towardsCamera (mesh.vertices.col (i)));
    if (!(facing > 0.0) || !(x >= 0.0 && x < image.width && y >= 0.0 && y < image.height))
      continue;
    const double front = depth[static_cast<size_t> (y) * image.width + static_cast<size_t> (x)];
    if (pixels (2, i) < front - depth_tolerance)
      continue;
    view.weights[i] = facing * facing;
    view.colours.col (i) = sampleBilinear (image, pixels.col (i).head<2> ()).cast<double> ();
  }
  return view;
}
} // namespace

int
VertexTexture::visibleCount () const
{
  return static_cast<int> (std::count (visible.begin (), visible.end (), true));
}

VertexTexture
blendedTexture (const TriangleMesh& mesh, const std::vector<TexturePhoto>& photos, double depth_tolerance)
{
  const Eigen::Index n = mesh.numVertices ();
  Eigen::Matrix3Xd sum = Eigen::Matrix3Xd::Zero (3, n);
  Eigen::VectorXd weights = Eigen::VectorXd::Zero (n);
  for (const TexturePhoto& photo : photos) {
    const ViewColours view = viewColours (mesh, photo, depth_tolerance);
    sum += view.colours * view.weights.asDiagonal ();
    weights += view.weights;
  }
  VertexTexture texture{VertexColours::Constant (3, n, 128), std::vector<bool> (static_cast<size_t> (n), false)};
  for (Eigen::Index i = 0; i < n; ++i)
    if (weights[i] > 0.0) {
      texture.visible[static_cast<size_t> (i)] = true;
      texture.colours.col (i) = (sum.col (i) / weights[i]).array ().round ().cast<unsigned char> ();
    }
  return texture;
}

VertexTexture
frontalTexture (const TriangleMesh& image_mesh, const PhotoNormalisation& frontal, const RgbImage& image,
                double depth_tolerance)
{
  if (image.width != frontal.width () || image.height != frontal.height ())
    throw InvalidInputError ("frontalTexture: the image is " + std::to_string (image.width) + " x " +
                             std::to_string (image.height) + " px, but the frontal annotations are for " +
                             std::to_string (frontal.width ()) + " x " + std::to_string (frontal.height ()) + " px");
  return blendedTexture (image_mesh, {{frontalCamera (frontal), &image}}, depth_tolerance);
}
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/coloured_surface.h>
#include <morphreg/mesh/triangle_locator.h>

#include <pcl/kdtree/kdtree_flann.h>
#include <pcl/point_types.h>

#include <cmath>

namespace morphreg
{
namespace
{
const Rgb8 kWhite (255, 255, 255);

/** The channel-wise product of two 8-bit colours (white is the identity). */
Rgb8
modulate (const Rgb8& a, const Rgb8& b)
{
  return ((a.cast<int> ().array () * b.cast<int> ().array () + 127) / 255).cast<unsigned char> ();
}

/** \a index wrapped into [0, size). */
int
wrap (long long index, int size)
{
  const long long r = index % size;
  return static_cast<int> (r < 0 ? r + size : r);
}

/** Whether triangle \a triangle has texture coordinates and a texture (a non-empty image). */
bool
isTextured (const ColouredSurface& surface, Eigen::Index triangle)
{
  if (surface.corner_uv.cols () != 3 * surface.triangles.cols () ||
      static_cast<std::size_t> (triangle) >= surface.triangle_texture.size ())
    return false;
  const int texture = surface.triangle_texture[triangle];
  if (texture < 0 || static_cast<std::size_t> (texture) >= surface.textures.size ())
    return false;
  const RgbImage& image = surface.textures[texture];
  return image.width > 0 && image.height > 0 && image.data.size () == 3 * std::size_t (image.width) * image.height;
}

/** The point colour of point \a p, white without point colours. */
Rgb8
pointColour (const ColouredSurface& surface, Eigen::Index p)
{
  return surface.colours.cols () == surface.points.cols () ? Rgb8 (surface.colours.col (p)) : kWhite;
}

/** The colour at barycentric \a weights of triangle \a t. */
Rgb8
colourOnTriangle (const ColouredSurface& surface, Eigen::Index t, const Eigen::Vector3d& weights)
{
  Eigen::Vector3d blended = Eigen::Vector3d::Zero ();
  for (int k = 0; k < 3; ++k)
    blended += weights[k] * pointColour (surface, surface.triangles (k, t)).cast<double> ();
  Rgb8 colour = blended.array ().round ().cwiseMax (0.0).cwiseMin (255.0).cast<unsigned char> ();
  if (!isTextured (surface, t))
    return colour;
  Eigen::Vector2f uv = Eigen::Vector2f::Zero ();
  for (int k = 0; k < 3; ++k)
    uv += static_cast<float> (weights[k]) * surface.corner_uv.col (3 * t + k);
  return modulate (colour, sampleTexture (surface.textures[surface.triangle_texture[t]], uv));
}

void
requireColours (const ColouredSurface& surface)
{
  if (!surface.hasColours ())
    throw InvalidInputError ("the scan's surface has no colours (neither point colours nor a texture)");
}

VertexColours
nearestPointColours (const ColouredSurface& surface, const Eigen::Matrix3Xd& queries)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  cloud->resize (surface.points.cols ());
  for (Eigen::Index i = 0; i < surface.points.cols (); ++i)
    (*cloud)[i].getVector3fMap () = surface.points.col (i).cast<float> ();
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud (cloud);
  VertexColours colours (3, queries.cols ());
#pragma omp parallel for
  for (Eigen::Index q = 0; q < queries.cols (); ++q) {
    pcl::Indices nearest (1);
    std::vector<float> distances (1);
    pcl::PointXYZ query;
    query.getVector3fMap () = queries.col (q).cast<float> ();
    tree.nearestKSearch (query, 1, nearest, distances);
    colours.col (q) = pointColour (surface, nearest[0]);
  }
  return colours;
}
} // namespace

bool
ColouredSurface::hasColours () const
{
  if (points.cols () > 0 && colours.cols () == points.cols ())
    return true;
  for (Eigen::Index t = 0; t < triangles.cols (); ++t)
    if (isTextured (*this, t))
      return true;
  return false;
}

Rgb8
sampleTexture (const RgbImage& texture, const Eigen::Vector2f& uv)
{
  const double x = static_cast<double> (uv.x ()) * texture.width - 0.5;
  const double y = static_cast<double> (uv.y ()) * texture.height - 0.5;
  if (!std::isfinite (x) || !std::isfinite (y) || std::abs (x) > 1e9 || std::abs (y) > 1e9)
    return kWhite;
  const double x0 = std::floor (x), y0 = std::floor (y);
  const double fx = x - x0, fy = y - y0;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const double weight = (dx ? fx : 1.0 - fx) * (dy ? fy : 1.0 - fy);
      const Rgb8 pixel = texture.pixel (wrap (static_cast<long long> (x0) + dx, texture.width),
                                        wrap (static_cast<long long> (y0) + dy, texture.height));
      sum += weight * pixel.cast<double> ();
    }
  return sum.array ().round ().cwiseMax (0.0).cwiseMin (255.0).cast<unsigned char> ();
}

VertexColours
pointColours (const ColouredSurface& surface)
{
  requireColours (surface);
  VertexColours colours (3, surface.points.cols ());
  std::vector<bool> textured (surface.points.cols (), false);
  for (Eigen::Index p = 0; p < surface.points.cols (); ++p)
    colours.col (p) = pointColour (surface, p);
  for (Eigen::Index t = 0; t < surface.triangles.cols (); ++t)
    for (int k = 0; k < 3 && isTextured (surface, t); ++k) {
      const int p = surface.triangles (k, t);
      if (textured[p])
        continue;
      textured[p] = true;
      const RgbImage& texture = surface.textures[surface.triangle_texture[t]];
      colours.col (p) = modulate (colours.col (p), sampleTexture (texture, surface.corner_uv.col (3 * t + k)));
    }
  return colours;
}

VertexColours
sampleNearestColours (const ColouredSurface& surface, const Eigen::Matrix3Xd& queries)
{
  requireColours (surface);
  if (!queries.allFinite ())
    throw InvalidInputError ("sampleNearestColours: a query point is not finite");
  if (surface.triangles.cols () == 0)
    return nearestPointColours (surface, queries);
  const TriangleLocator locator (TriangleMesh{surface.points, surface.triangles});
  VertexColours colours (3, queries.cols ());
#pragma omp parallel for
  for (Eigen::Index q = 0; q < queries.cols (); ++q) {
    const TriangleLocator::Hit hit = locator.closestPoint (queries.col (q));
    colours.col (q) = colourOnTriangle (surface, hit.triangle, hit.barycentric);
  }
  return colours;
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// The glTF versions of a real scan the tests write (test/support/glb_writer.h): plain, Draco-compressed, under a node
// transform, as two primitives, and in an arbitrary unit (a scale in the node), each with what reading it must give.
#include "glb_writer.h"

#include <morphreg/io/coloured_surface_io.h>
#include <morphreg/mesh/triangle_mesh.h>

#include <Eigen/LU>

#include <fstream>
#include <iterator>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace morphreg
{
namespace test
{
/** A scan as glTF holds it: its mesh in mm, split where texture coordinates differ at a vertex (glTF has one set per
 *  vertex), with its texture coordinates and its texture file's bytes if it is textured. */
struct GlbSource
{
  TriangleMesh mesh;
  Eigen::Matrix2Xf uv;                ///< per vertex, glTF's convention (v down), or none
  std::vector<unsigned char> texture; ///< the encoded texture, or none
  std::string mime;
};

/** The versions written. */
enum class GlbVariant
{
  plain,          ///< one triangle primitive in metres
  draco,          ///< the same, compressed by Draco (Edgebreaker, lossless)
  node_transform, ///< the positions moved by the inverse of the rotation and scale their node's matrix applies
  two_primitives, ///< the triangles in two primitives of one mesh sharing the vertex accessors
  arbitrary_unit  ///< a node scales the scene by kArbitraryUnitScale: a unit that is no unit
};

const GlbVariant kGlbVariants[] = {GlbVariant::plain, GlbVariant::draco, GlbVariant::node_transform,
                                   GlbVariant::two_primitives, GlbVariant::arbitrary_unit};

/** The scene is this many times the scan in the arbitrary unit's version: a capture whose unit is 93 mm, read as
 *  glTF's metres, is 1000 / 93 times its size in mm (a head in no unit: register estimates its scale from the head). */
constexpr double kArbitraryUnitScale = 1000.0 / 93.0;

inline std::string
variantName (GlbVariant variant)
{
  static const char* const names[] = {"plain", "draco", "node_transform", "two_primitives", "arbitrary_unit"};
  return names[static_cast<int> (variant)];
}

/** The scan file \a path (read by loadColouredSurface) as glTF holds it; \a texture_file, if given, is embedded. */
inline GlbSource
glbSource (const std::string& path, const std::string& texture_file = "")
{
  const ColouredSurface surface = loadColouredSurface (path);
  GlbSource source;
  const bool textured = !texture_file.empty () && surface.corner_uv.cols () == 3 * surface.triangles.cols ();
  std::map<std::pair<int, std::pair<float, float>>, int> split; // (vertex, uv) -> glTF vertex
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector2f> uv;
  source.mesh.triangles.resize (3, surface.triangles.cols ());
  for (Eigen::Index t = 0; t < surface.triangles.cols (); ++t)
    for (int k = 0; k < 3; ++k) {
      const int v = surface.triangles (k, t);
      const Eigen::Vector2f corner =
          textured ? Eigen::Vector2f (surface.corner_uv.col (3 * t + k)) : Eigen::Vector2f::Zero ();
      const auto [entry, added] = split.emplace (std::make_pair (v, std::make_pair (corner.x (), corner.y ())),
                                                 static_cast<int> (vertices.size ()));
      if (added) {
        vertices.push_back (surface.points.col (v));
        uv.push_back (corner);
      }
      source.mesh.triangles (k, t) = entry->second;
    }
  source.mesh.vertices.resize (3, static_cast<Eigen::Index> (vertices.size ()));
  for (std::size_t v = 0; v < vertices.size (); ++v)
    source.mesh.vertices.col (static_cast<Eigen::Index> (v)) = vertices[v];
  if (textured) {
    source.uv = Eigen::Map<const Eigen::Matrix2Xf> (uv.data ()->data (), 2, static_cast<Eigen::Index> (uv.size ()));
    std::ifstream in (texture_file, std::ios::binary);
    source.texture.assign (std::istreambuf_iterator<char> (in), std::istreambuf_iterator<char> ());
    source.mime = texture_file.substr (texture_file.size () - 4) == ".png" ? "image/png" : "image/jpeg";
  }
  return source;
}

/** The node matrix of the node_transform version: a rotation by 90 degrees about y and a scale of 2, exact in
 *  floating point both ways, so that the file holds the scan's own numbers (a translation or another angle would
 *  round them, and a fit is sensitive to the last digit of a point). Arbitrary transforms: gltf_reader_test.cpp. */
inline Eigen::Matrix4d
variantNodeMatrix ()
{
  Eigen::Matrix4d matrix = Eigen::Matrix4d::Identity ();
  matrix.topLeftCorner<3, 3> () << 0, 0, 2, 0, 2, 0, -2, 0, 0;
  return matrix;
}

/** The glTF document of \a variant of \a source. */
inline gltf::Document
variantDocument (const GlbSource& source, GlbVariant variant)
{
  gltf::Primitive primitive = gltf::meshPrimitive (source.mesh);
  gltf::Node node;
  if (source.uv.cols () > 0) {
    primitive.uv = source.uv;
    primitive.material = 0;
  }
  if (variant == GlbVariant::draco)
    primitive.draco = true;
  if (variant == GlbVariant::node_transform) {
    const Eigen::Matrix4d matrix = variantNodeMatrix ();
    primitive.positions = (matrix.topLeftCorner<3, 3> ().inverse () * source.mesh.vertices / 1000.0).cast<float> ();
    node.matrix.assign (matrix.data (), matrix.data () + 16);
  }
  if (variant == GlbVariant::arbitrary_unit)
    node.scale = {kArbitraryUnitScale, kArbitraryUnitScale, kArbitraryUnitScale};
  gltf::Document document = gltf::singleNode (primitive, node);
  if (variant == GlbVariant::two_primitives) {
    gltf::Primitive second = primitive;
    const std::size_t half = 3 * (primitive.indices.size () / 6);
    second.indices.assign (primitive.indices.begin () + half, primitive.indices.end ());
    second.shares_vertices_of = 0;
    document.meshes[0][0].indices.resize (half);
    document.meshes[0].push_back (second);
  }
  if (source.uv.cols () > 0) {
    document.images = {{source.texture, source.mime}};
    document.materials = {{0, {}}};
  }
  return document;
}

/** Where reading \a variant must put the vertices (mm): the scan's, scaled in the arbitrary unit's version. */
inline Eigen::Matrix3Xd
variantExpectedVertices (const GlbSource& source, GlbVariant variant)
{
  return variant == GlbVariant::arbitrary_unit ? Eigen::Matrix3Xd (kArbitraryUnitScale * source.mesh.vertices)
                                               : source.mesh.vertices;
}
} // namespace test
} // namespace morphreg

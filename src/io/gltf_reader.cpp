// SPDX-License-Identifier: BSD-3-Clause
#include "gltf_accessor.h"
#include "gltf_file.h"
#include "gltf_scene.h"
#include "tiny_gltf_hidden.h"
#include "vertex_cloud.h"

#include <morphreg/common/length_unit.h>
#include <morphreg/io/gltf_reader.h>

#include <Eigen/LU>

#include <algorithm>
#include <cstring>
#include <map>

namespace morphreg
{
namespace
{
using gltf::GltfFile;
using gltf::PrimitiveData;
using gltf::PrimitiveLook;

/** Scenes with more vertices in all are refused, before more is allocated (16.7 million). */
constexpr std::size_t kMaxVertices = std::size_t (1) << 24;

/** The triangles of a primitive's corner list in mode TRIANGLES, TRIANGLE_STRIP or TRIANGLE_FAN (strips and fans
 *  without their degenerate triangles), each counter-clockwise. */
std::vector<Eigen::Vector3i>
primitiveTriangles (const GltfFile& file, const std::vector<std::uint32_t>& corners, int mode, const std::string& what)
{
  std::vector<Eigen::Vector3i> triangles;
  const std::size_t n = corners.size ();
  if (mode == TINYGLTF_MODE_TRIANGLES && n % 3 != 0)
    file.fail (what + ": " + std::to_string (n) + " corners, not a multiple of 3 as triangles need");
  const auto add = [&] (std::size_t a, std::size_t b, std::size_t c) {
    const Eigen::Vector3i t (corners[a], corners[b], corners[c]);
    if (mode == TINYGLTF_MODE_TRIANGLES || (t[0] != t[1] && t[1] != t[2] && t[0] != t[2]))
      triangles.push_back (t);
  };
  for (std::size_t i = 0; mode == TINYGLTF_MODE_TRIANGLES && i + 2 < n; i += 3)
    add (i, i + 1, i + 2);
  for (std::size_t i = 0; mode == TINYGLTF_MODE_TRIANGLE_STRIP && i + 2 < n; ++i)
    add (i, i + 1 + i % 2, i + 2 - i % 2);
  for (std::size_t i = 1; mode == TINYGLTF_MODE_TRIANGLE_FAN && i + 1 < n; ++i)
    add (i, i + 1, 0);
  return triangles;
}

/** The corners in file order: the indices, or every vertex in order; each checked against the vertex count. */
std::vector<std::uint32_t>
cornerList (const GltfFile& file, const PrimitiveData& data, const std::string& what)
{
  const auto vertices = static_cast<std::uint32_t> (data.positions.cols ());
  if (data.indices.empty ()) {
    std::vector<std::uint32_t> all (vertices);
    for (std::uint32_t v = 0; v < vertices; ++v)
      all[v] = v;
    return all;
  }
  for (std::size_t i = 0; i < data.indices.size (); ++i)
    if (data.indices[i] >= vertices)
      file.fail (what + ": index " + std::to_string (i) + " is " + std::to_string (data.indices[i]) +
                 ", beyond the primitive's " + std::to_string (vertices) + " vertices");
  return data.indices;
}

/** A hash of a position's bits (-0 taken as 0, which compares equal to it), each coordinate's bits mixed by
 *  splitmix64's finaliser: the low bits of a double converted from a float are all zero. */
struct PositionHash
{
  static std::uint64_t
  mix (std::uint64_t x)
  {
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ull;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebull;
    return x ^ (x >> 31);
  }

  std::size_t
  operator() (const Eigen::Vector3d& p) const
  {
    std::uint64_t hash = 0;
    for (int k = 0; k < 3; ++k) {
      const double value = p[k] == 0.0 ? 0.0 : p[k];
      std::uint64_t bits;
      std::memcpy (&bits, &value, sizeof (bits));
      hash = mix (hash ^ bits);
    }
    return static_cast<std::size_t> (hash);
  }
};

/** The vertices a points primitive's indices name, in their order. */
PrimitiveData
indexedPoints (const PrimitiveData& data, const std::vector<std::uint32_t>& corners)
{
  const auto select = [&] (const auto& values) -> Eigen::MatrixXd {
    if (values.cols () != data.positions.cols ())
      return Eigen::MatrixXd (values.rows (), 0);
    return values (Eigen::all, corners);
  };
  PrimitiveData points;
  points.positions = select (data.positions);
  points.normals = select (data.normals);
  points.colours = select (data.colours);
  points.uv = select (data.uv);
  return points;
}

/** The merged scene, primitive by primitive. */
class SceneBuilder
{
public:
  SceneBuilder (const GltfFile& file, const tinygltf::Model& model) : file_ (file), model_ (model) {}

  void
  addMesh (const gltf::MeshInstance& instance);

  GltfContent
  finish ();

private:
  void
  addPrimitive (const tinygltf::Primitive& primitive, const Eigen::Matrix4d& transform, const std::string& what);
  void
  addVertices (const PrimitiveData& data, const Eigen::Matrix4d& transform, const PrimitiveLook& look);
  void
  addFaces (const std::vector<Eigen::Vector3i>& triangles, int first, bool flip, const PrimitiveData& data,
            int texture);
  /** Merges vertices at the same position (glTF repeats a vertex for each texture coordinate, normal or primitive it
   *  has, Draco for each non-manifold fan): one vertex per point of the surface, in order of first appearance. */
  void
  weldIdenticalPositions ();

  const GltfFile& file_;
  const tinygltf::Model& model_;
  gltf::BaseColourTextures textures_;
  std::vector<Eigen::Vector3d> points_;
  std::vector<Eigen::Vector3f> normals_;
  std::vector<Rgb8> colours_;
  std::vector<Eigen::Vector3i> triangles_;
  std::vector<Eigen::Vector2f> corner_uv_;
  std::vector<int> triangle_texture_;
  std::map<std::pair<int, std::map<std::string, int>>, int> shared_vertices_; ///< of the current mesh instance
  bool all_normals_ = true, any_colour_ = false, any_texture_ = false;        ///< any_texture_: corner_uv_ is kept
};

void
SceneBuilder::addMesh (const gltf::MeshInstance& instance)
{
  const tinygltf::Mesh& mesh = model_.meshes[instance.mesh];
  shared_vertices_.clear ();
  for (std::size_t p = 0; p < mesh.primitives.size (); ++p)
    addPrimitive (mesh.primitives[p], instance.transform,
                  "mesh " + std::to_string (instance.mesh) + " primitive " + std::to_string (p));
}

void
SceneBuilder::addPrimitive (const tinygltf::Primitive& primitive, const Eigen::Matrix4d& transform,
                            const std::string& what)
{
  const bool draco = primitive.extensions.count ("KHR_draco_mesh_compression") > 0;
  int mode = primitive.mode;
  if (mode == TINYGLTF_MODE_LINE || mode == TINYGLTF_MODE_LINE_LOOP || mode == TINYGLTF_MODE_LINE_STRIP)
    return; // lines carry no surface
  if (mode < TINYGLTF_MODE_POINTS || mode > TINYGLTF_MODE_TRIANGLE_FAN)
    file_.fail (what + ": unknown primitive mode " + std::to_string (mode));
  const PrimitiveLook look = textures_.look (file_, model_, primitive.material, what);
  const int texcoord = look.texture >= 0 ? look.texcoord : -1;
  const PrimitiveData data = draco ? gltf::decodeDracoPrimitive (file_, model_, primitive, what, texcoord)
                                   : gltf::readPrimitiveAccessors (file_, model_, primitive, what, texcoord);
  if (draco && mode != TINYGLTF_MODE_POINTS)
    mode = TINYGLTF_MODE_TRIANGLES; // Draco stores triangle lists
  if (points_.size () + std::size_t (data.positions.cols ()) > kMaxVertices)
    file_.fail ("the scene holds more than " + std::to_string (kMaxVertices) +
                " vertices in all (meshes instanced by many nodes?), more than morphreg reads");
  const std::vector<std::uint32_t> corners = cornerList (file_, data, what);
  if (mode == TINYGLTF_MODE_POINTS) {
    addVertices (data.indices.empty () ? data : indexedPoints (data, corners), transform, look);
    return;
  }
  const std::vector<Eigen::Vector3i> triangles = primitiveTriangles (file_, corners, mode, what);
  if (triangles_.size () + triangles.size () > 2 * kMaxVertices)
    file_.fail ("the scene holds more than " + std::to_string (2 * kMaxVertices) + " triangles in all, more than " +
                "morphreg reads");
  // Primitives of one mesh that share their vertex accessors and material share their vertices.
  const auto key = std::make_pair (primitive.material, primitive.attributes);
  const auto known = draco ? shared_vertices_.end () : shared_vertices_.find (key);
  const int first = known != shared_vertices_.end () ? known->second : static_cast<int> (points_.size ());
  if (known == shared_vertices_.end ()) {
    addVertices (data, transform, look);
    if (!draco)
      shared_vertices_[key] = first;
  }
  addFaces (triangles, first, transform.topLeftCorner<3, 3> ().determinant () < 0.0, data, look.texture);
}

void
SceneBuilder::addVertices (const PrimitiveData& data, const Eigen::Matrix4d& transform, const PrimitiveLook& look)
{
  const double mm = millimetresPer (LengthUnit::metre);
  const Eigen::Matrix3d linear = transform.topLeftCorner<3, 3> ();
  const Eigen::Matrix3d normal_map = linear.inverse ().transpose ();
  const Eigen::Index n = data.positions.cols ();
  all_normals_ = all_normals_ && data.normals.cols () == n;
  const bool coloured = data.colours.cols () == n;
  any_colour_ = any_colour_ || coloured || look.texture >= 0;
  const Eigen::Vector3d factor =
      look.texture >= 0 ? Eigen::Vector3d::Ones () : Eigen::Vector3d (look.factor.head<3> ());
  const auto srgb = [] (const Eigen::Vector3d& linear_colour) {
    return Rgb8 (gltf::linearToSrgb8 (linear_colour[0]), gltf::linearToSrgb8 (linear_colour[1]),
                 gltf::linearToSrgb8 (linear_colour[2]));
  };
  const Rgb8 constant = srgb (factor);
  points_.reserve (points_.size () + n), colours_.reserve (colours_.size () + n);
  for (Eigen::Index v = 0; v < n; ++v) {
    points_.push_back (mm * (linear * data.positions.col (v) + transform.block<3, 1> (0, 3)));
    if (all_normals_)
      normals_.push_back ((normal_map * data.normals.col (v)).normalized ().cast<float> ());
    colours_.push_back (coloured ? srgb (factor.cwiseProduct (data.colours.col (v).head<3> ())) : constant);
  }
}

void
SceneBuilder::addFaces (const std::vector<Eigen::Vector3i>& triangles, int first, bool flip, const PrimitiveData& data,
                        int texture)
{
  const bool textured = texture >= 0 && data.uv.cols () == data.positions.cols () && !triangles.empty ();
  if (textured && !any_texture_) { // the triangles before the first textured ones have no texture
    corner_uv_.assign (3 * triangles_.size (), Eigen::Vector2f::Zero ());
    triangle_texture_.assign (triangles_.size (), -1);
    any_texture_ = true;
  }
  triangles_.reserve (triangles_.size () + triangles.size ());
  for (Eigen::Vector3i t : triangles) {
    if (flip) // a mirroring transform turns the winding: keep it counter-clockwise
      std::swap (t[1], t[2]);
    triangles_.push_back (t.array () + first);
    if (!any_texture_)
      continue;
    triangle_texture_.push_back (textured ? texture : -1);
    for (int k = 0; k < 3; ++k)
      corner_uv_.push_back (textured ? Eigen::Vector2f (data.uv.col (t[k]).cast<float> ()) : Eigen::Vector2f::Zero ());
  }
}

void
SceneBuilder::weldIdenticalPositions ()
{
  std::size_t slots = 2;
  while (slots < 2 * points_.size ())
    slots *= 2;
  std::vector<int> table (slots, -1); // open addressing: the kept vertex at each position
  std::vector<int> index (points_.size ());
  std::size_t kept = 0;
  for (std::size_t v = 0; v < points_.size (); ++v) {
    std::size_t slot = PositionHash () (points_[v]) & (slots - 1);
    while (table[slot] >= 0 && points_[table[slot]] != points_[v])
      slot = (slot + 1) & (slots - 1);
    if (table[slot] < 0) {
      points_[kept] = points_[v], colours_[kept] = colours_[v];
      if (all_normals_)
        normals_[kept] = normals_[v];
      table[slot] = static_cast<int> (kept++);
    }
    index[v] = table[slot];
  }
  points_.resize (kept), colours_.resize (kept), normals_.resize (all_normals_ ? kept : 0);
  for (Eigen::Vector3i& t : triangles_)
    t = Eigen::Vector3i (index[t[0]], index[t[1]], index[t[2]]);
}

GltfContent
SceneBuilder::finish ()
{
  if (points_.empty ())
    file_.fail ("the scene holds neither triangles nor points");
  weldIdenticalPositions ();
  GltfContent content;
  ColouredSurface& surface = content.surface;
  const auto n = static_cast<Eigen::Index> (points_.size ()), m = static_cast<Eigen::Index> (triangles_.size ());
  surface.points = Eigen::Map<const Eigen::Matrix3Xd> (points_.data ()->data (), 3, n);
  surface.triangles = Eigen::Map<const Eigen::Matrix3Xi> (m ? triangles_.data ()->data () : nullptr, 3, m);
  if (any_colour_)
    surface.colours = Eigen::Map<const VertexColours> (colours_.data ()->data (), 3, n);
  if (any_texture_) {
    surface.corner_uv = Eigen::Map<const Eigen::Matrix2Xf> (corner_uv_.data ()->data (), 2, 3 * m);
    surface.triangle_texture = triangle_texture_;
    surface.textures = std::move (textures_.textures ());
  }
  if (all_normals_)
    content.normals = Eigen::Map<const Eigen::Matrix3Xf> (normals_.data ()->data (), 3, n);
  return content;
}
} // namespace

GltfContent
readGltfFile (const std::string& path)
{
  GltfFile file = gltf::readGltfBytes (path);
  gltf::checkGltfJson (file);
  const tinygltf::Model model = gltf::loadGltfModel (file);
  SceneBuilder builder (file, model);
  for (const gltf::MeshInstance& instance : gltf::sceneInstances (file, model))
    builder.addMesh (instance);
  return builder.finish ();
}

pcl::PolygonMesh
toPolygonMesh (const GltfContent& content)
{
  const ColouredSurface& surface = content.surface;
  pcl::PolygonMesh mesh;
  mesh.cloud = vertexCloud (surface.points.cast<float> (), content.normals,
                            surface.hasColours () ? pointColours (surface) : VertexColours ());
  mesh.polygons.resize (surface.triangles.cols ());
  for (Eigen::Index t = 0; t < surface.triangles.cols (); ++t)
    mesh.polygons[t].vertices.assign (surface.triangles.col (t).data (), surface.triangles.col (t).data () + 3);
  return mesh;
}

} // namespace morphreg

#include "gltf_accessor.h"
#include "gltf_file.h"
#include "gltf_scene.h"
#include "vertex_cloud.h"

#include <morphreg/common/length_unit.h>
#include <morphreg/io/gltf_reader.h>

#include "tiny_gltf_hidden.h"

#include <algorithm>
#include <map>
#include <numeric>

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
  bool all_normals_ = true, any_colour_ = false, any_texture_ = false;
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
  PrimitiveData data = draco ? gltf::decodeDracoPrimitive (file_, model_, primitive, what, texcoord)
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
  all_normals_ = all_normals_ && data.normals.cols () == data.positions.cols ();
  const bool coloured = data.colours.cols () == data.positions.cols ();
  any_colour_ = any_colour_ || coloured || look.texture >= 0;
  for (Eigen::Index v = 0; v < data.positions.cols (); ++v) {
    points_.push_back (mm * (linear * data.positions.col (v) + transform.block<3, 1> (0, 3)));
    if (all_normals_)
      normals_.push_back ((normal_map * data.normals.col (v)).normalized ().cast<float> ());
    Eigen::Vector3d colour = look.texture >= 0 ? Eigen::Vector3d::Ones () : Eigen::Vector3d (look.factor.head<3> ());
    if (coloured)
      colour = colour.cwiseProduct (data.colours.col (v).head<3> ());
    colours_.emplace_back (gltf::linearToSrgb8 (colour[0]), gltf::linearToSrgb8 (colour[1]),
                           gltf::linearToSrgb8 (colour[2]));
  }
}

void
SceneBuilder::addFaces (const std::vector<Eigen::Vector3i>& triangles, int first, bool flip, const PrimitiveData& data,
                        int texture)
{
  const bool textured = texture >= 0 && data.uv.cols () == data.positions.cols ();
  for (Eigen::Vector3i t : triangles) {
    if (flip) // a mirroring transform turns the winding: keep it counter-clockwise
      std::swap (t[1], t[2]);
    triangles_.push_back (t.array () + first);
    triangle_texture_.push_back (textured ? texture : -1);
    for (int k = 0; k < 3; ++k)
      corner_uv_.push_back (textured ? Eigen::Vector2f (data.uv.col (t[k]).cast<float> ()) : Eigen::Vector2f::Zero ());
  }
  any_texture_ = any_texture_ || (textured && !triangles.empty ());
}

void
SceneBuilder::weldIdenticalPositions ()
{
  std::vector<int> order (points_.size ());
  std::iota (order.begin (), order.end (), 0);
  const auto less = [this] (int a, int b) {
    return std::lexicographical_compare (points_[a].data (), points_[a].data () + 3, points_[b].data (),
                                         points_[b].data () + 3);
  };
  std::stable_sort (order.begin (), order.end (), less);
  std::vector<int> first (points_.size ()); // the first vertex at each vertex's position
  for (std::size_t i = 0; i < order.size (); ++i)
    first[order[i]] = i > 0 && points_[order[i]] == points_[order[i - 1]] ? first[order[i - 1]] : order[i];
  std::vector<int> index (points_.size ());
  std::size_t kept = 0;
  for (std::size_t v = 0; v < points_.size (); ++v) {
    index[v] = first[v] == static_cast<int> (v) ? static_cast<int> (kept) : index[first[v]];
    if (first[v] != static_cast<int> (v))
      continue;
    points_[kept] = points_[v], colours_[kept] = colours_[v];
    if (all_normals_)
      normals_[kept] = normals_[v];
    ++kept;
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

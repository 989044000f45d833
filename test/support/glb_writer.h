// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// A small glTF 2.0 writer for tests (the library only reads glTF): meshes of primitives (triangles, strips, points;
// positions, normals, COLOR_0, TEXCOORD_0; optionally Draco-compressed with the draco library), a node hierarchy with
// matrices or translation / rotation / scale, base-colour materials with embedded images, written as .glb, or as
// .gltf with an external .bin or a data URI. The JSON and the binary buffer are built first, so that tests can break
// them before packing.
#include <morphreg/common/colour_map.h>
#include <morphreg/mesh/triangle_mesh.h>

#include <draco/compression/encode.h>
#include <draco/mesh/mesh.h>
#include <nlohmann/json.hpp>

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace morphreg
{
namespace test
{
namespace gltf
{
/** One primitive. Colours are 8-bit sRGB, written as linear float COLOR_0 (glTF's colours are linear). */
struct Primitive
{
  Eigen::Matrix3Xf positions;         ///< the file's unit: metres, unless a node scales them
  std::vector<std::uint32_t> indices; ///< corners in the mode's layout; none: the vertices in order
  int mode = 4;                       ///< 0 points, 4 triangles, 5 strip, 6 fan
  Eigen::Matrix3Xf normals;           ///< or none
  VertexColours colours;              ///< or none
  Eigen::Matrix2Xf uv;                ///< TEXCOORD_0 (u right, v down), or none
  int material = -1;
  int shares_vertices_of = -1; ///< use the vertex accessors of this earlier primitive of the mesh (positions ignored)
  bool draco = false;          ///< KHR_draco_mesh_compression
  int draco_method = draco::MESH_EDGEBREAKER_ENCODING;
  int position_bits = 0; ///< Draco position quantization bits, 0 for none (lossless)
};

/** A node: its mesh (-1 none), children, and a matrix (16, column-major) or translation, rotation (x y z w), scale. */
struct Node
{
  int mesh = -1;
  std::vector<int> children;
  std::vector<double> matrix, translation, rotation, scale;
};

/** A base-colour material: its image (-1 none) and factor (linear RGBA). */
struct Material
{
  int image = -1;
  std::vector<double> factor;
};

struct Image
{
  std::vector<unsigned char> bytes; ///< PNG or JPEG
  std::string mime = "image/png";
};

struct Document
{
  std::vector<std::vector<Primitive>> meshes;
  std::vector<Node> nodes;
  std::vector<int> scene; ///< the root nodes of the one scene
  std::vector<Material> materials;
  std::vector<Image> images;
};

/** A built document: its JSON and its one binary buffer (buffer 0), before packing. */
struct Parts
{
  nlohmann::json json;
  std::vector<unsigned char> bin;
};

inline double
srgbToLinear (unsigned char value)
{
  const double c = value / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow ((c + 0.055) / 1.055, 2.4);
}

/** Builds the JSON and the buffer: accessors and buffer views appended as the primitives need them. */
class Builder
{
public:
  Parts
  build (const Document& document)
  {
    parts_.json = {{"asset", {{"version", "2.0"}, {"generator", "morphreg tests"}}},
                   {"scene", 0},
                   {"scenes", {{{"nodes", document.scene}}}}};
    addNodes (document);
    for (const Image& image : document.images)
      parts_.json["images"].push_back (
          {{"bufferView", addView (image.bytes.data (), image.bytes.size (), -1)}, {"mimeType", image.mime}});
    for (std::size_t i = 0; i < document.images.size (); ++i)
      parts_.json["textures"].push_back ({{"source", i}});
    for (const Material& material : document.materials)
      parts_.json["materials"].push_back (materialJson (material));
    for (const auto& mesh : document.meshes) {
      nlohmann::json primitives = nlohmann::json::array ();
      for (const Primitive& primitive : mesh)
        primitives.push_back (primitiveJson (primitive, primitives));
      parts_.json["meshes"].push_back ({{"primitives", primitives}});
    }
    parts_.json["buffers"] = {{{"byteLength", parts_.bin.size ()}}};
    return std::move (parts_);
  }

private:
  void
  addNodes (const Document& document)
  {
    for (const Node& node : document.nodes) {
      nlohmann::json json = nlohmann::json::object ();
      if (node.mesh >= 0)
        json["mesh"] = node.mesh;
      for (const auto& [key, values] : {std::pair<const char*, const std::vector<double>&> ("matrix", node.matrix),
                                        {"translation", node.translation},
                                        {"rotation", node.rotation},
                                        {"scale", node.scale}})
        if (!values.empty ())
          json[key] = values;
      if (!node.children.empty ())
        json["children"] = node.children;
      parts_.json["nodes"].push_back (json);
    }
  }

  static nlohmann::json
  materialJson (const Material& material)
  {
    nlohmann::json pbr = nlohmann::json::object ();
    if (material.image >= 0)
      pbr["baseColorTexture"] = {{"index", material.image}};
    if (!material.factor.empty ())
      pbr["baseColorFactor"] = material.factor;
    return {{"pbrMetallicRoughness", pbr}};
  }

  /** Appends \a bytes (4-byte aligned) as a buffer view; returns its index. */
  int
  addView (const void* bytes, std::size_t size, int target)
  {
    while (parts_.bin.size () % 4 != 0)
      parts_.bin.push_back (0);
    nlohmann::json view = {{"buffer", 0}, {"byteOffset", parts_.bin.size ()}, {"byteLength", size}};
    if (target > 0)
      view["target"] = target;
    const auto* data = static_cast<const unsigned char*> (bytes);
    parts_.bin.insert (parts_.bin.end (), data, data + size);
    parts_.json["bufferViews"].push_back (view);
    return static_cast<int> (parts_.json["bufferViews"].size ()) - 1;
  }

  /** Float columns as a VEC2 / VEC3 accessor (with min and max for positions); returns its index. */
  template <typename Matrix>
  int
  addFloats (const Matrix& values, bool bounds)
  {
    const Eigen::MatrixXf dense = values.template cast<float> ();
    nlohmann::json accessor = {{"bufferView", addView (dense.data (), sizeof (float) * dense.size (), 34962)},
                               {"componentType", 5126},
                               {"count", dense.cols ()},
                               {"type", dense.rows () == 2   ? "VEC2"
                                        : dense.rows () == 3 ? "VEC3"
                                                             : "VEC4"}};
    if (bounds) {
      const Eigen::VectorXf low = dense.rowwise ().minCoeff (), high = dense.rowwise ().maxCoeff ();
      accessor["min"] = std::vector<float> (low.data (), low.data () + low.size ());
      accessor["max"] = std::vector<float> (high.data (), high.data () + high.size ());
    }
    return addAccessor (accessor);
  }

  int
  addIndices (const std::vector<std::uint32_t>& indices)
  {
    return addAccessor ({{"bufferView", addView (indices.data (), 4 * indices.size (), 34963)},
                         {"componentType", 5125},
                         {"count", indices.size ()},
                         {"type", "SCALAR"}});
  }

  int
  addAccessor (const nlohmann::json& accessor)
  {
    parts_.json["accessors"].push_back (accessor);
    return static_cast<int> (parts_.json["accessors"].size ()) - 1;
  }

  static Eigen::Matrix3Xf
  linearColours (const VertexColours& colours)
  {
    Eigen::Matrix3Xf linear (3, colours.cols ());
    for (Eigen::Index i = 0; i < colours.size (); ++i)
      linear.data ()[i] = static_cast<float> (srgbToLinear (colours.data ()[i]));
    return linear;
  }

  nlohmann::json
  attributesJson (const Primitive& primitive)
  {
    nlohmann::json attributes = {{"POSITION", addFloats (primitive.positions, true)}};
    if (primitive.normals.cols () > 0)
      attributes["NORMAL"] = addFloats (primitive.normals, false);
    if (primitive.colours.cols () > 0)
      attributes["COLOR_0"] = addFloats (linearColours (primitive.colours), false);
    if (primitive.uv.cols () > 0)
      attributes["TEXCOORD_0"] = addFloats (primitive.uv, false);
    return attributes;
  }

  nlohmann::json
  primitiveJson (const Primitive& primitive, const nlohmann::json& earlier)
  {
    nlohmann::json json = {{"mode", primitive.mode}};
    if (primitive.material >= 0)
      json["material"] = primitive.material;
    if (primitive.draco)
      return dracoJson (primitive, json);
    json["attributes"] = primitive.shares_vertices_of >= 0 ? earlier[primitive.shares_vertices_of]["attributes"]
                                                           : attributesJson (primitive);
    if (!primitive.indices.empty ())
      json["indices"] = addIndices (primitive.indices);
    return json;
  }

  /** The primitive compressed by Draco: accessors without buffer views, the payload in its own view. */
  nlohmann::json
  dracoJson (const Primitive& primitive, nlohmann::json json)
  {
    draco::Mesh mesh;
    const auto n = static_cast<std::uint32_t> (primitive.positions.cols ());
    mesh.set_num_points (n);
    nlohmann::json ids, attributes;
    const auto add = [&] (const char* name, draco::GeometryAttribute::Type type, const Eigen::MatrixXf& values) {
      draco::GeometryAttribute attribute;
      attribute.Init (type, nullptr, static_cast<std::uint8_t> (values.rows ()), draco::DT_FLOAT32, false,
                      sizeof (float) * values.rows (), 0);
      const int id = mesh.AddAttribute (attribute, true, n);
      for (std::uint32_t i = 0; i < n; ++i)
        mesh.attribute (id)->SetAttributeValue (draco::AttributeValueIndex (i), values.col (i).data ());
      ids[name] = mesh.attribute (id)->unique_id ();
      attributes[name] =
          addAccessor ({{"componentType", 5126}, {"count", n}, {"type", values.rows () == 2 ? "VEC2" : "VEC3"}});
    };
    add ("POSITION", draco::GeometryAttribute::POSITION, primitive.positions);
    if (primitive.colours.cols () > 0)
      add ("COLOR_0", draco::GeometryAttribute::COLOR, linearColours (primitive.colours));
    if (primitive.uv.cols () > 0)
      add ("TEXCOORD_0", draco::GeometryAttribute::TEX_COORD, primitive.uv);
    for (std::size_t c = 0; c + 2 < primitive.indices.size (); c += 3)
      mesh.AddFace ({draco::PointIndex (primitive.indices[c]), draco::PointIndex (primitive.indices[c + 1]),
                     draco::PointIndex (primitive.indices[c + 2])});
    draco::Encoder encoder;
    encoder.SetEncodingMethod (primitive.draco_method);
    if (primitive.position_bits > 0)
      encoder.SetAttributeQuantization (draco::GeometryAttribute::POSITION, primitive.position_bits);
    draco::EncoderBuffer buffer;
    const draco::Status status = encoder.EncodeMeshToBuffer (mesh, &buffer);
    if (!status.ok ())
      throw std::runtime_error ("draco encoding failed: " + status.error_msg_string ());
    json["attributes"] = attributes;
    json["indices"] = addAccessor ({{"componentType", 5125}, {"count", primitive.indices.size ()}, {"type", "SCALAR"}});
    json["extensions"]["KHR_draco_mesh_compression"] = {{"bufferView", addView (buffer.data (), buffer.size (), -1)},
                                                        {"attributes", ids}};
    parts_.json["extensionsUsed"] = {"KHR_draco_mesh_compression"};
    parts_.json["extensionsRequired"] = {"KHR_draco_mesh_compression"};
    return json;
  }

  Parts parts_;
};

inline Parts
build (const Document& document)
{
  return Builder ().build (document);
}

inline void
appendUint32 (std::vector<unsigned char>& out, std::uint32_t value)
{
  for (int i = 0; i < 4; ++i)
    out.push_back (static_cast<unsigned char> (value >> (8 * i)));
}

/** The GLB bytes: header, JSON chunk (space-padded) and BIN chunk (zero-padded). */
inline std::vector<unsigned char>
glbBytes (const Parts& parts)
{
  std::string json = parts.json.dump ();
  while (json.size () % 4 != 0)
    json += ' ';
  std::vector<unsigned char> bin = parts.bin;
  while (bin.size () % 4 != 0)
    bin.push_back (0);
  std::vector<unsigned char> out = {'g', 'l', 'T', 'F'};
  appendUint32 (out, 2);
  appendUint32 (out, static_cast<std::uint32_t> (12 + 8 + json.size () + (bin.empty () ? 0 : 8 + bin.size ())));
  appendUint32 (out, static_cast<std::uint32_t> (json.size ()));
  appendUint32 (out, 0x4E4F534A);
  out.insert (out.end (), json.begin (), json.end ());
  if (!bin.empty ()) {
    appendUint32 (out, static_cast<std::uint32_t> (bin.size ()));
    appendUint32 (out, 0x004E4942);
    out.insert (out.end (), bin.begin (), bin.end ());
  }
  return out;
}

inline void
writeBytes (const std::string& path, const void* data, std::size_t size)
{
  std::ofstream out (path, std::ios::binary | std::ios::trunc);
  out.write (static_cast<const char*> (data), static_cast<std::streamsize> (size));
  if (!out)
    throw std::runtime_error (path + ": cannot be written");
}

inline void
writeGlb (const std::string& path, const Parts& parts)
{
  const std::vector<unsigned char> bytes = glbBytes (parts);
  writeBytes (path, bytes.data (), bytes.size ());
}

inline std::string
base64 (const std::vector<unsigned char>& bytes)
{
  static const char digits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  for (std::size_t i = 0; i < bytes.size (); i += 3) {
    const std::size_t left = bytes.size () - i;
    const std::uint32_t group = bytes[i] << 16 | (left > 1 ? bytes[i + 1] << 8 : 0) | (left > 2 ? bytes[i + 2] : 0);
    text += digits[(group >> 18) & 63];
    text += digits[(group >> 12) & 63];
    text += left > 1 ? digits[(group >> 6) & 63] : '=';
    text += left > 2 ? digits[group & 63] : '=';
  }
  return text;
}

/** A .gltf file: the JSON, its buffer in \a bin_name next to it (written too), or, if \a bin_name is empty, in a data
 *  URI. */
inline void
writeGltf (const std::string& path, Parts parts, const std::string& bin_name)
{
  if (bin_name.empty ())
    parts.json["buffers"][0]["uri"] = "data:application/octet-stream;base64," + base64 (parts.bin);
  else {
    parts.json["buffers"][0]["uri"] = bin_name;
    const std::string folder = path.substr (0, path.find_last_of ('/') + 1);
    writeBytes (folder + bin_name, parts.bin.data (), parts.bin.size ());
  }
  const std::string json = parts.json.dump (1);
  writeBytes (path, json.data (), json.size ());
}

/** A mesh in mm as one triangle primitive in metres (positions / 1000 / \a scale: a node with \a scale brings them
 *  back), with its colours if given. */
inline Primitive
meshPrimitive (const TriangleMesh& mesh, double scale = 1.0, const VertexColours& colours = VertexColours ())
{
  Primitive primitive;
  primitive.positions = (mesh.vertices / (1000.0 * scale)).cast<float> ();
  primitive.indices.assign (mesh.triangles.data (), mesh.triangles.data () + mesh.triangles.size ());
  primitive.colours = colours;
  return primitive;
}

/** One mesh in one node. */
inline Document
singleNode (const Primitive& primitive, const Node& node = Node ())
{
  Document document;
  document.meshes = {{primitive}};
  document.nodes = {node};
  document.nodes[0].mesh = 0;
  document.scene = {0};
  return document;
}
} // namespace gltf
} // namespace test
} // namespace morphreg

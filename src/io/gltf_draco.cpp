// SPDX-License-Identifier: BSD-3-Clause
#include "gltf_accessor.h"

#include <draco/compression/decode.h>
#include "tiny_gltf_hidden.h"

#include <algorithm>
#include <cstring>

namespace morphreg
{
namespace gltf
{
namespace
{
const char* const kDraco = "KHR_draco_mesh_compression";

/** The extension's whole-number member \a key (a buffer view or an attribute id), -1 if it is not one. */
int
wholeNumber (const tinygltf::Value& value)
{
  if (value.IsInt ())
    return value.GetNumberAsInt ();
  const double number = value.IsReal () ? value.GetNumberAsDouble () : -1.0;
  return number >= 0.0 && number < 2147483647.0 && number == static_cast<int> (number) ? static_cast<int> (number) : -1;
}

/** The payload: the bytes of the extension's buffer view (checked against the file by checkGltfJson). */
std::pair<const unsigned char*, std::size_t>
payload (const GltfFile& file, const tinygltf::Model& model, const tinygltf::Value& extension, const std::string& what)
{
  const int view = extension.Has ("bufferView") ? wholeNumber (extension.Get ("bufferView")) : -1;
  if (view < 0 || static_cast<std::size_t> (view) >= model.bufferViews.size ())
    file.fail (what + ": its " + kDraco + " extension has no valid bufferView");
  const tinygltf::BufferView& bytes = model.bufferViews[view];
  if (bytes.buffer < 0 || static_cast<std::size_t> (bytes.buffer) >= model.buffers.size ())
    file.fail (what + ": the Draco buffer view " + std::to_string (view) + " has no buffer");
  const std::vector<unsigned char>& buffer = model.buffers[bytes.buffer].data;
  if (bytes.byteOffset > buffer.size () || bytes.byteLength > buffer.size () - bytes.byteOffset)
    file.fail (what + ": the Draco buffer view " + std::to_string (view) + " lies outside its buffer");
  if (bytes.byteLength < 5 || std::memcmp (buffer.data () + bytes.byteOffset, "DRACO", 5) != 0)
    file.fail (what + ": bad Draco payload: buffer view " + std::to_string (view) +
               " does not start with the Draco header 'DRACO'");
  return {buffer.data () + bytes.byteOffset, bytes.byteLength};
}

/** The decoded geometry, or FormatError with Draco's reason. */
template <typename Decoded>
std::unique_ptr<draco::PointCloud>
decoded (const GltfFile& file, Decoded result, const std::string& kind, const std::string& what)
{
  if (!result.ok () || !result.value ())
    file.fail (what + ": bad Draco payload: it cannot be decoded as a " + kind + " (" +
               result.status ().error_msg_string ().substr (0, 200) + ")");
  return std::move (result).value ();
}

/** Decodes the payload as a mesh (triangles) or a point cloud (points). */
std::unique_ptr<draco::PointCloud>
decode (const GltfFile& file, std::pair<const unsigned char*, std::size_t> bytes, bool mesh, const std::string& what)
{
  draco::DecoderBuffer buffer;
  buffer.Init (reinterpret_cast<const char*> (bytes.first), bytes.second);
  draco::Decoder decoder;
  if (mesh)
    return decoded (file, decoder.DecodeMeshFromBuffer (&buffer), "mesh", what);
  return decoded (file, decoder.DecodePointCloudFromBuffer (&buffer), "point cloud", what);
}

/** Attribute \a name's values at every point (components x points), checked against what Draco decoded. */
Eigen::MatrixXd
attributeValues (const GltfFile& file, const draco::PointCloud& cloud, int id, const AccessorUse& use, bool normalized)
{
  const draco::PointAttribute* attribute = id >= 0 ? cloud.GetAttributeByUniqueId (id) : nullptr;
  if (!attribute)
    file.fail (use.what + ": the Draco payload has no attribute with id " + std::to_string (id));
  const int components = attribute->num_components ();
  if (std::find (use.components.begin (), use.components.end (), components) == use.components.end () ||
      attribute->byte_stride () <= 0 || !attribute->buffer () ||
      attribute->buffer ()->data_size () < attribute->size () * std::size_t (attribute->byte_stride ()))
    file.fail (use.what + ": the Draco attribute " + std::to_string (id) + " has " + std::to_string (components) +
               " components or an inconsistent size");
  Eigen::MatrixXd values (components, cloud.num_points ());
  for (draco::PointIndex p (0); p < cloud.num_points (); ++p) {
    const draco::AttributeValueIndex index = attribute->mapped_index (p);
    if (index.value () >= attribute->size () ||
        !attribute->ConvertValue<double> (index, static_cast<std::int8_t> (components), &values (0, p.value ())))
      file.fail (use.what + ": the Draco attribute " + std::to_string (id) + " has no value for point " +
                 std::to_string (p.value ()));
  }
  if (normalized && !attribute->normalized () && attribute->data_type () == draco::DT_UINT8)
    values /= 255.0;
  else if (normalized && !attribute->normalized () && attribute->data_type () == draco::DT_UINT16)
    values /= 65535.0;
  if (!values.allFinite ())
    file.fail (use.what + ": the Draco attribute " + std::to_string (id) + " holds a value that is not finite");
  return values;
}
} // namespace

PrimitiveData
decodeDracoPrimitive (const GltfFile& file, const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                      const std::string& what, int texcoord)
{
  const tinygltf::Value& extension = primitive.extensions.at (kDraco);
  if (!extension.IsObject () || !extension.Has ("attributes") || !extension.Get ("attributes").IsObject ())
    file.fail (what + ": its " + kDraco + " extension is not an object with attributes");
  const bool mesh = primitive.mode != TINYGLTF_MODE_POINTS;
  const auto cloud = decode (file, payload (file, model, extension, what), mesh, what);
  const tinygltf::Value& ids = extension.Get ("attributes");
  const auto read = [&] (const std::string& name, bool required) -> Eigen::MatrixXd {
    if (!ids.Has (name) && !required)
      return {};
    // The decoded points count, whatever the accessors declare: Edgebreaker splits non-manifold vertices.
    const AccessorUse use = attributeUse (what, name);
    return attributeValues (file, *cloud, ids.Has (name) ? wholeNumber (ids.Get (name)) : -1, use,
                            use.normalized_integers);
  };
  PrimitiveData data;
  data.positions = read ("POSITION", true);
  data.normals = read ("NORMAL", false);
  data.colours = read ("COLOR_0", false);
  if (texcoord >= 0)
    data.uv = read ("TEXCOORD_" + std::to_string (texcoord), false);
  if (mesh) {
    const auto& faces = static_cast<const draco::Mesh&> (*cloud);
    data.indices.reserve (3 * std::size_t (faces.num_faces ()));
    for (draco::FaceIndex f (0); f < faces.num_faces (); ++f)
      for (int k = 0; k < 3; ++k)
        data.indices.push_back (faces.face (f)[k].value ());
  }
  return data;
}
} // namespace gltf
} // namespace morphreg

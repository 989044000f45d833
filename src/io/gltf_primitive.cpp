// SPDX-License-Identifier: BSD-3-Clause
#include "gltf_accessor.h"

#include "tiny_gltf_hidden.h"

namespace morphreg
{
namespace gltf
{
namespace
{
constexpr int kByte = TINYGLTF_COMPONENT_TYPE_BYTE, kUbyte = TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE,
              kShort = TINYGLTF_COMPONENT_TYPE_SHORT, kUshort = TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT,
              kUint = TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT, kFloat = TINYGLTF_COMPONENT_TYPE_FLOAT;

/** The accessor of attribute \a name, -1 if the primitive has none. */
int
attributeAccessor (const tinygltf::Primitive& primitive, const std::string& name)
{
  const auto found = primitive.attributes.find (name);
  return found == primitive.attributes.end () ? -1 : found->second;
}

/** Reads attribute \a name (if the primitive has it) with \a use; its element count must be the positions'. */
Eigen::MatrixXd
readAttribute (const GltfFile& file, const tinygltf::Model& model, const tinygltf::Primitive& primitive,
               const std::string& name, const AccessorUse& use, Eigen::Index vertices)
{
  const int accessor = attributeAccessor (primitive, name);
  if (accessor < 0)
    return {};
  Eigen::MatrixXd values = readAccessor (file, model, accessor, use);
  if (values.cols () != vertices)
    file.fail (use.what + ": " + std::to_string (values.cols ()) + " elements, but POSITION has " +
               std::to_string (vertices));
  return values;
}
} // namespace

AccessorUse
attributeUse (const std::string& what, const std::string& name)
{
  if (name == "POSITION") // integers with KHR_mesh_quantization
    return {what + " POSITION", {3}, {kByte, kUbyte, kShort, kUshort, kFloat}};
  if (name == "NORMAL")
    return {what + " NORMAL", {3}, {kByte, kShort, kFloat}};
  if (name == "COLOR_0")
    return {what + " COLOR_0", {3, 4}, {kUbyte, kUshort, kFloat}, true};
  if (name == "indices")
    return {what + " indices", {1}, {kUbyte, kUshort, kUint}};
  return {what + " " + name, {2}, {kByte, kUbyte, kShort, kUshort, kFloat}}; // TEXCOORD_n
}

PrimitiveData
readPrimitiveAccessors (const GltfFile& file, const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                        const std::string& what, int texcoord)
{
  const int position = attributeAccessor (primitive, "POSITION");
  if (position < 0)
    file.fail (what + ": it has no POSITION attribute");
  PrimitiveData data;
  data.positions = readAccessor (file, model, position, attributeUse (what, "POSITION"));
  const Eigen::Index n = data.positions.cols ();
  data.normals = readAttribute (file, model, primitive, "NORMAL", attributeUse (what, "NORMAL"), n);
  data.colours = readAttribute (file, model, primitive, "COLOR_0", attributeUse (what, "COLOR_0"), n);
  if (texcoord >= 0) {
    const std::string name = "TEXCOORD_" + std::to_string (texcoord);
    data.uv = readAttribute (file, model, primitive, name, attributeUse (what, name), n);
  }
  if (primitive.indices >= 0) {
    const Eigen::MatrixXd indices = readAccessor (file, model, primitive.indices, attributeUse (what, "indices"));
    data.indices.resize (indices.cols ());
    for (Eigen::Index i = 0; i < indices.cols (); ++i)
      data.indices[i] = static_cast<std::uint32_t> (indices (0, i));
  }
  return data;
}
} // namespace gltf
} // namespace morphreg

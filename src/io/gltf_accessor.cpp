// SPDX-License-Identifier: BSD-3-Clause
#include "gltf_accessor.h"

#include "tiny_gltf_hidden.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace morphreg
{
namespace gltf
{
namespace
{
/** Bytes per component of a glTF component type, 0 for an unknown type (5124, INT, is not glTF 2.0's). */
int
componentBytes (int type)
{
  switch (type) {
  case TINYGLTF_COMPONENT_TYPE_BYTE:
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
    return 1;
  case TINYGLTF_COMPONENT_TYPE_SHORT:
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
    return 2;
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
  case TINYGLTF_COMPONENT_TYPE_FLOAT:
    return 4;
  default:
    return 0;
  }
}

/** The component at \a data as a double; normalized integers mapped as glTF says (signed: max (c / max, -1)). */
double
componentValue (const unsigned char* data, int type, bool normalized)
{
  const auto as = [data] (auto value) {
    std::memcpy (&value, data, sizeof (value));
    return value;
  };
  switch (type) {
  case TINYGLTF_COMPONENT_TYPE_BYTE:
    return normalized ? std::max (as (std::int8_t ()) / 127.0, -1.0) : as (std::int8_t ());
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
    return normalized ? as (std::uint8_t ()) / 255.0 : as (std::uint8_t ());
  case TINYGLTF_COMPONENT_TYPE_SHORT:
    return normalized ? std::max (as (std::int16_t ()) / 32767.0, -1.0) : as (std::int16_t ());
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
    return normalized ? as (std::uint16_t ()) / 65535.0 : as (std::uint16_t ());
  case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    return as (std::uint32_t ());
  default:
    return as (float ());
  }
}

/** The accessor's type and component type against \a use. */
void
checkAccessorType (const GltfFile& file, const tinygltf::Accessor& accessor, const AccessorUse& use)
{
  const int components = componentCount (accessor.type);
  if (std::find (use.components.begin (), use.components.end (), components) == use.components.end ())
    file.fail (use.what + ": its accessor's type (" + std::to_string (accessor.type) + ") has " +
               std::to_string (components) + " components, not what the attribute needs");
  if (std::find (use.component_types.begin (), use.component_types.end (), accessor.componentType) ==
          use.component_types.end () ||
      (use.normalized_integers && accessor.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT && !accessor.normalized))
    file.fail (use.what + ": component type " + std::to_string (accessor.componentType) +
               (accessor.normalized ? " (normalized)" : "") + " is not one glTF allows for it");
  if (accessor.sparse.isSparse)
    file.fail (use.what + ": sparse accessors are not read");
  if (accessor.count == 0)
    file.fail (use.what + ": the accessor has no elements (count 0)");
}

/** The buffer view of \a accessor and its stride, the accessor's elements checked to lie within the view. */
std::pair<const tinygltf::BufferView*, std::size_t>
checkedView (const GltfFile& file, const tinygltf::Model& model, const tinygltf::Accessor& accessor,
             const AccessorUse& use)
{
  if (accessor.bufferView < 0 || static_cast<std::size_t> (accessor.bufferView) >= model.bufferViews.size ())
    file.fail (use.what + ": its accessor has no buffer view (bufferView " + std::to_string (accessor.bufferView) +
               " of " + std::to_string (model.bufferViews.size ()) + ")");
  const tinygltf::BufferView& view = model.bufferViews[accessor.bufferView];
  if (view.buffer < 0 || static_cast<std::size_t> (view.buffer) >= model.buffers.size () ||
      view.byteOffset > model.buffers[view.buffer].data.size () ||
      view.byteLength > model.buffers[view.buffer].data.size () - view.byteOffset)
    file.fail (use.what + ": buffer view " + std::to_string (accessor.bufferView) + " lies outside its buffer");
  const std::size_t element = componentCount (accessor.type) * std::size_t (componentBytes (accessor.componentType));
  const std::size_t stride = view.byteStride == 0 ? element : view.byteStride;
  if (stride < element)
    file.fail (use.what + ": buffer view " + std::to_string (accessor.bufferView) + "'s byteStride " +
               std::to_string (stride) + " is smaller than the " + std::to_string (element) + "-byte elements");
  const long double needed = static_cast<long double> (accessor.byteOffset) +
                             static_cast<long double> (stride) * (accessor.count - 1) + element;
  if (needed > view.byteLength)
    file.fail (use.what + ": the accessor claims " + std::to_string (accessor.count) + " elements (" +
               std::to_string (static_cast<unsigned long long> (std::min (needed, 1e19L))) +
               " bytes from its byteOffset " + std::to_string (accessor.byteOffset) + ") but buffer view " +
               std::to_string (accessor.bufferView) + " holds " + std::to_string (view.byteLength) + " bytes");
  return {&view, stride};
}
} // namespace

int
componentCount (int type)
{
  switch (type) {
  case TINYGLTF_TYPE_SCALAR:
    return 1;
  case TINYGLTF_TYPE_VEC2:
  case TINYGLTF_TYPE_VEC3:
  case TINYGLTF_TYPE_VEC4:
    return type;
  default:
    return 0;
  }
}

std::size_t
accessorCount (const GltfFile& file, const tinygltf::Model& model, int accessor, const std::string& what)
{
  if (accessor < 0 || static_cast<std::size_t> (accessor) >= model.accessors.size ())
    file.fail (what + ": accessor " + std::to_string (accessor) + " does not exist (the file has " +
               std::to_string (model.accessors.size ()) + ")");
  return model.accessors[accessor].count;
}

Eigen::MatrixXd
readAccessor (const GltfFile& file, const tinygltf::Model& model, int index, const AccessorUse& use)
{
  accessorCount (file, model, index, use.what);
  const tinygltf::Accessor& accessor = model.accessors[index];
  checkAccessorType (file, accessor, use);
  const auto [view, stride] = checkedView (file, model, accessor, use);
  const int components = componentCount (accessor.type), bytes = componentBytes (accessor.componentType);
  const unsigned char* data = model.buffers[view->buffer].data.data () + view->byteOffset + accessor.byteOffset;
  Eigen::MatrixXd values (components, static_cast<Eigen::Index> (accessor.count));
  for (std::size_t e = 0; e < accessor.count; ++e)
    for (int c = 0; c < components; ++c)
      values (c, static_cast<Eigen::Index> (e)) =
          componentValue (data + e * stride + c * bytes, accessor.componentType, accessor.normalized);
  if (!values.allFinite ())
    file.fail (use.what + ": the accessor holds a value that is not finite (NaN or infinite)");
  return values;
}
} // namespace gltf
} // namespace morphreg

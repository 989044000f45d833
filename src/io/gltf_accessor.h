// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private to the glTF reader: the values of accessors, every read checked against the accessor's buffer view, and
// the primitives' vertex data in one form whether it came from accessors or from a Draco payload.
#include "gltf_file.h"

#include <Eigen/Core>

#include <cstdint>
#include <string>
#include <vector>

namespace morphreg
{
namespace gltf
{
/** What a primitive's vertices carry, as doubles: positions (3 x N, the file's unit), and where the primitive has
 *  them normals, colours (3 or 4 x N, linear, 0 to 1) and texture coordinates (2 x N; one set, the one its material's
 *  base-colour texture uses); the indices of its corners in file order (none: the vertices in order). */
struct PrimitiveData
{
  Eigen::Matrix3Xd positions;
  Eigen::Matrix3Xd normals;
  Eigen::MatrixXd colours;
  Eigen::Matrix2Xd uv;
  std::vector<std::uint32_t> indices;
};

/** How an accessor is used, for its checks and messages: its name ("mesh 0 primitive 1 POSITION"), the element types
 *  allowed (numbers of components: 1 SCALAR, 2 VEC2, ... ) and component types allowed (GL codes). */
struct AccessorUse
{
  std::string what;
  std::vector<int> components;
  std::vector<int> component_types;
  bool normalized_integers = false; ///< integer components must be normalized (colours, texture coordinates)
};

/** How primitive \a what's attribute \a name ("POSITION", "NORMAL", "COLOR_0", "TEXCOORD_n") or its "indices" may be
 *  stored: the element and component types glTF allows for it (integer positions, normals and texture coordinates
 *  with KHR_mesh_quantization). */
AccessorUse
attributeUse (const std::string& what, const std::string& name);

/** The number of components of a glTF accessor type (TINYGLTF_TYPE_*), 0 for a matrix or an unknown type. */
int
componentCount (int type);

/** The accessor's elements as doubles (one column per element; normalized integers mapped to [0, 1] or [-1, 1]),
 *  after checking the accessor against \a use and its extent against its buffer view: FormatError naming the file,
 *  the accessor and the problem. Sparse accessors and accessors without a buffer view are refused. */
Eigen::MatrixXd
readAccessor (const GltfFile& file, const tinygltf::Model& model, int accessor, const AccessorUse& use);

/** The element count accessor \a accessor declares, checked to exist (FormatError naming \a what otherwise). */
std::size_t
accessorCount (const GltfFile& file, const tinygltf::Model& model, int accessor, const std::string& what);

/** A primitive's vertex data from its accessors; \a texcoord the TEXCOORD_n set to read (-1: none). */
PrimitiveData
readPrimitiveAccessors (const GltfFile& file, const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                        const std::string& what, int texcoord);

/** A KHR_draco_mesh_compression primitive's vertex data, decoded by Draco from its buffer view (FormatError naming
 *  the primitive if the payload is not Draco or cannot be decoded, or lacks an attribute the extension names). */
PrimitiveData
decodeDracoPrimitive (const GltfFile& file, const tinygltf::Model& model, const tinygltf::Primitive& primitive,
                      const std::string& what, int texcoord);
} // namespace gltf
} // namespace morphreg

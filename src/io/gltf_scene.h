// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private to the glTF reader: where the scene places its meshes (the node hierarchy walked, transforms composed) and
// how a primitive's material colours it (base-colour factor and texture, the textures decoded once each).
#include "gltf_file.h"

#include <morphreg/io/rgb_image_io.h>

#include <Eigen/Core>

#include <array>
#include <map>
#include <vector>

namespace morphreg
{
namespace gltf
{
/** A mesh placed in the scene: its index and the global transform of its node (the file's unit). */
struct MeshInstance
{
  int mesh;
  Eigen::Matrix4d transform;
};

/** The meshes of the default scene (else the first scene, else every root node) with their global transforms: each
 *  node's matrix, or translation * rotation * scale, times its parent's. FormatError naming the file and the node or
 *  scene for an index out of range, a malformed transform, or a node reached twice (a cycle, two parents). */
std::vector<MeshInstance>
sceneInstances (const GltfFile& file, const tinygltf::Model& model);

/** How a primitive's material colours it: the base-colour factor (linear RGBA), and its base-colour texture (an index
 *  into the decoded textures, -1 for none) with the TEXCOORD set it uses. */
struct PrimitiveLook
{
  Eigen::Vector4d factor = Eigen::Vector4d::Ones ();
  int texture = -1;
  int texcoord = -1;
};

/** The base-colour textures of a file's materials, decoded once per image and baked with their factor once per
 *  (image, factor) pair. */
class BaseColourTextures
{
public:
  /** The look of material \a material (-1: glTF's default material) for primitive \a what; FormatError naming the
   *  material, texture or image that is missing or cannot be decoded. */
  PrimitiveLook
  look (const GltfFile& file, const tinygltf::Model& model, int material, const std::string& what);

  /** The decoded textures, indexed by PrimitiveLook::texture. */
  std::vector<RgbImage>&
  textures ()
  {
    return textures_;
  }

private:
  int
  slot (const GltfFile& file, const tinygltf::Model& model, int image, const Eigen::Vector4d& factor,
        const std::string& what);

  std::map<std::pair<int, std::array<double, 3>>, int> slots_;
  std::map<int, RgbImage> decoded_;
  std::vector<RgbImage> textures_;
};

/** 8-bit sRGB of a linear colour channel in [0, 1] (clamped), as glTF's colours are linear. */
unsigned char
linearToSrgb8 (double linear);
} // namespace gltf
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include "gltf_scene.h"

#include "tiny_gltf_hidden.h"

#include <Eigen/Geometry>

#include <cmath>

namespace morphreg
{
namespace gltf
{
namespace
{
/** Textures with more pixels are refused before they are decoded (8192 x 8192, what phone apps export at most). */
constexpr double kMaxTexturePixels = 8192.0 * 8192.0;

std::string
nodeName (int node)
{
  return "node " + std::to_string (node);
}

/** Node \a index's local transform: its matrix (column-major), or translation * rotation * scale. */
Eigen::Matrix4d
localTransform (const GltfFile& file, const tinygltf::Node& node, int index)
{
  const auto fail = [&] (const std::string& problem) { file.fail (nodeName (index) + ": " + problem); };
  if (!node.matrix.empty () && node.matrix.size () != 16)
    fail ("its matrix has " + std::to_string (node.matrix.size ()) + " numbers, not 16");
  if (node.matrix.size () == 16)
    return Eigen::Map<const Eigen::Matrix4d> (node.matrix.data ());
  if ((!node.translation.empty () && node.translation.size () != 3) ||
      (!node.rotation.empty () && node.rotation.size () != 4) || (!node.scale.empty () && node.scale.size () != 3))
    fail ("its translation, rotation or scale has the wrong number of values (3, 4 and 3)");
  Eigen::Affine3d transform = Eigen::Affine3d::Identity ();
  if (!node.translation.empty ())
    transform.translate (Eigen::Vector3d (node.translation[0], node.translation[1], node.translation[2]));
  if (!node.rotation.empty ()) {
    const Eigen::Quaterniond q (node.rotation[3], node.rotation[0], node.rotation[1], node.rotation[2]);
    if (!(q.norm () > 1e-12) || !std::isfinite (q.norm ()))
      fail ("its rotation quaternion has no length");
    transform.rotate (q.normalized ());
  }
  if (!node.scale.empty ())
    transform.scale (Eigen::Vector3d (node.scale[0], node.scale[1], node.scale[2]));
  return transform.matrix ();
}

/** The nodes the walk starts from: the default scene's, else the first scene's, else every node no node has as a
 *  child. */
std::vector<int>
rootNodes (const GltfFile& file, const tinygltf::Model& model)
{
  if (!model.scenes.empty ()) {
    const int scene = model.defaultScene >= 0 ? model.defaultScene : 0;
    if (static_cast<std::size_t> (scene) >= model.scenes.size ())
      file.fail ("the default scene " + std::to_string (scene) + " does not exist (the file has " +
                 std::to_string (model.scenes.size ()) + ")");
    return model.scenes[scene].nodes;
  }
  std::vector<bool> child (model.nodes.size (), false);
  for (const tinygltf::Node& node : model.nodes)
    for (const int c : node.children)
      if (c >= 0 && static_cast<std::size_t> (c) < child.size ())
        child[c] = true;
  std::vector<int> roots;
  for (std::size_t n = 0; n < model.nodes.size (); ++n)
    if (!child[n])
      roots.push_back (static_cast<int> (n));
  return roots;
}
} // namespace

std::vector<MeshInstance>
sceneInstances (const GltfFile& file, const tinygltf::Model& model)
{
  std::vector<MeshInstance> instances;
  std::vector<bool> visited (model.nodes.size (), false);
  std::vector<std::pair<int, Eigen::Matrix4d>> stack;
  const std::vector<int> roots = rootNodes (file, model);
  for (auto root = roots.rbegin (); root != roots.rend (); ++root) // the first root on top: nodes in file order
    stack.emplace_back (*root, Eigen::Matrix4d::Identity ());
  while (!stack.empty ()) {
    const auto [index, parent] = stack.back ();
    stack.pop_back ();
    if (index < 0 || static_cast<std::size_t> (index) >= model.nodes.size ())
      file.fail (nodeName (index) + " does not exist (the file has " + std::to_string (model.nodes.size ()) +
                 " nodes)");
    if (visited[index])
      file.fail (nodeName (index) + " is reached twice: the node hierarchy has a cycle or a node with two parents");
    visited[index] = true;
    const tinygltf::Node& node = model.nodes[index];
    const Eigen::Matrix4d transform = parent * localTransform (file, node, index);
    if (!transform.allFinite ())
      file.fail (nodeName (index) + ": its global transform is not finite");
    if (node.mesh >= 0 && static_cast<std::size_t> (node.mesh) >= model.meshes.size ())
      file.fail (nodeName (index) + ": mesh " + std::to_string (node.mesh) + " does not exist (the file has " +
                 std::to_string (model.meshes.size ()) + ")");
    if (node.mesh >= 0)
      instances.push_back ({node.mesh, transform});
    for (auto child = node.children.rbegin (); child != node.children.rend (); ++child)
      stack.emplace_back (*child, transform);
  }
  return instances;
}

unsigned char
linearToSrgb8 (double linear)
{
  const double c = std::clamp (linear, 0.0, 1.0);
  const double srgb = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow (c, 1.0 / 2.4) - 0.055;
  return static_cast<unsigned char> (std::lround (srgb * 255.0));
}

PrimitiveLook
BaseColourTextures::look (const GltfFile& file, const tinygltf::Model& model, int material, const std::string& what)
{
  PrimitiveLook look;
  if (material < 0)
    return look;
  if (static_cast<std::size_t> (material) >= model.materials.size ())
    file.fail (what + ": material " + std::to_string (material) + " does not exist");
  const tinygltf::PbrMetallicRoughness& pbr = model.materials[material].pbrMetallicRoughness;
  if (pbr.baseColorFactor.size () == 4)
    look.factor = Eigen::Map<const Eigen::Vector4d> (pbr.baseColorFactor.data ()).cwiseMax (0.0).cwiseMin (1.0);
  const int texture = pbr.baseColorTexture.index;
  if (texture < 0)
    return look;
  if (static_cast<std::size_t> (texture) >= model.textures.size ())
    file.fail (what + ": material " + std::to_string (material) + "'s base-colour texture " + std::to_string (texture) +
               " does not exist");
  const int image = model.textures[texture].source;
  if (image < 0 || static_cast<std::size_t> (image) >= model.images.size ())
    file.fail (what + ": texture " + std::to_string (texture) + " has no image (source " + std::to_string (image) +
               ")");
  look.texture = slot (file, model, image, look.factor, what);
  look.texcoord = std::max (pbr.baseColorTexture.texCoord, 0);
  return look;
}

int
BaseColourTextures::slot (const GltfFile& file, const tinygltf::Model& model, int image, const Eigen::Vector4d& factor,
                          const std::string& what)
{
  const std::pair<int, std::array<double, 3>> key{image, {factor[0], factor[1], factor[2]}};
  if (const auto known = slots_.find (key); known != slots_.end ())
    return known->second;
  if (!decoded_.count (image)) {
    const tinygltf::Image& source = model.images[image];
    const std::string name = file.path + ": image " + std::to_string (image);
    if (source.image.empty ())
      file.fail (what + ": image " + std::to_string (image) + " has no data" +
                 (source.uri.empty ()
                      ? std::string ()
                      : " (its file '" + source.uri.substr (0, 200) + "' does not exist or cannot be read)"));
    decoded_[image] = decodeRgbImage (source.image, name, kMaxTexturePixels);
  }
  RgbImage texture = decoded_[image];
  if (factor.head<3> () != Eigen::Vector3d::Ones ())
    for (std::size_t i = 0; i < texture.data.size (); ++i) {
      const double c = texture.data[i] / 255.0;
      const double linear = c <= 0.04045 ? c / 12.92 : std::pow ((c + 0.055) / 1.055, 2.4);
      texture.data[i] = linearToSrgb8 (linear * factor[i % 3]);
    }
  textures_.push_back (std::move (texture));
  return slots_[key] = static_cast<int> (textures_.size ()) - 1;
}
} // namespace gltf
} // namespace morphreg

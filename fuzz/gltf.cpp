// SPDX-License-Identifier: BSD-3-Clause
// Fuzz targets mesh_glb and mesh_gltf: binary and JSON glTF through the mesh loader, the cloud loader and the
// coloured surface loader (the textures decoded, their colours sampled).
#include "fuzz_target.h"

#include <morphreg/io/cloud_io.h>
#include <morphreg/io/coloured_surface_io.h>
#include <morphreg/io/mesh_io.h>

namespace
{
using morphreg::fuzz::Loader;

const Loader load_mesh = [] (const std::string& path) { morphreg::loadPolygonMesh (path); };
const Loader load_cloud = [] (const std::string& path) { morphreg::loadCloud<pcl::PointXYZ> (path); };
const Loader load_colours = [] (const std::string& path) {
  const morphreg::ColouredSurface surface = morphreg::loadColouredSurface (path);
  if (surface.hasColours ())
    morphreg::sampleNearestColours (surface,
                                    surface.points.leftCols (std::min<Eigen::Index> (surface.points.cols (), 8)));
};

const bool registered = morphreg::fuzz::registerTarget ({"mesh_glb", ".glb", {load_mesh, load_cloud, load_colours}}) &&
                        morphreg::fuzz::registerTarget ({"mesh_gltf", ".gltf", {load_mesh, load_cloud, load_colours}});
} // namespace

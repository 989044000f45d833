// SPDX-License-Identifier: BSD-3-Clause
// Fuzz targets mesh_<format>: the mesh loader and the cloud loader on one file of each format they read (the
// mesh loader does not read PCD, the cloud loader does not read VTK).
#include "fuzz_target.h"

#include <morphreg/io/cloud_io.h>
#include <morphreg/io/mesh_io.h>

namespace
{
using morphreg::fuzz::Loader;

const Loader load_mesh = [] (const std::string& path) { morphreg::loadPolygonMesh (path); };
const Loader load_cloud = [] (const std::string& path) { morphreg::loadCloud<pcl::PointXYZ> (path); };

const bool registered = morphreg::fuzz::registerTarget ({"mesh_ply", ".ply", {load_mesh, load_cloud}}) &&
                        morphreg::fuzz::registerTarget ({"mesh_obj", ".obj", {load_mesh, load_cloud}}) &&
                        morphreg::fuzz::registerTarget ({"mesh_pcd", ".pcd", {load_cloud}}) &&
                        morphreg::fuzz::registerTarget ({"mesh_vtk", ".vtk", {load_mesh}}) &&
                        morphreg::fuzz::registerTarget ({"mesh_stl", ".stl", {load_mesh, load_cloud}}) &&
                        morphreg::fuzz::registerTarget ({"mesh_off", ".off", {load_mesh, load_cloud}});
} // namespace

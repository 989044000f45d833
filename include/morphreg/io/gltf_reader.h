// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file gltf_reader.h
 *  \brief morphreg's reader of glTF 2.0 scans and meshes (.gltf with external or data-URI buffers, binary .glb), as
 *  phone and photogrammetry apps export them, through tinygltf and Draco (KHR_draco_mesh_compression).
 *
 *  The default scene (else the first, else every root node) is read whole: each node's mesh placed by the node's
 *  global transform (its matrix, or translation, rotation and scale, composed down the hierarchy), the triangles,
 *  triangle strips and fans and the points of every primitive merged into one surface, vertices at the same position
 *  merged (glTF repeats a vertex for each texture coordinate or normal it has there, Draco for non-manifold fans; the
 *  texture coordinates stay with the triangle corners), Draco's decoded points used whatever count the accessors
 *  declare (Edgebreaker splits non-manifold vertices). glTF's unit is the metre by
 *  specification: positions are converted to millimetres (x 1000). The colours come with it: COLOR_0 (linear,
 *  converted to 8-bit sRGB) and the material's base-colour texture at its TEXCOORD set, both times the base-colour
 *  factor.
 *
 *  Nothing reaches tinygltf or Draco unchecked: the GLB header and chunks against the file's size, the JSON's
 *  nesting, every buffer's byteLength against its source (BIN chunk, data URI, or an external file that must exist)
 *  and every buffer view's extent first; then every accessor against its buffer view, every index against its
 *  primitive's vertices, node references and cycles, and at most 16.7 million vertices in all.
 */
#include <morphreg/mesh/coloured_surface.h>

#include <pcl/PolygonMesh.h>

#include <string>

namespace morphreg
{
/** \brief What a glTF file holds, merged into one surface in the scene's frame, in mm. */
struct GltfContent
{
  ColouredSurface surface;  ///< points (mm), triangles, colours and textures; no colours if the file has none
  Eigen::Matrix3Xf normals; ///< a unit normal per point (NORMAL, transformed), none unless every primitive has them
};

/** \brief Reads a .gltf or .glb file. Throws IoError if it cannot be read, FormatError naming the file and the problem
 *  (and the buffer, buffer view, accessor, mesh and primitive concerned) if it is malformed, cut short, inconsistent,
 *  needs an extension morphreg does not read, or holds neither triangles nor points.
 *  \param[in] path the file
 *  \return its scene in mm
 */
GltfContent
readGltfFile (const std::string& path);

/** \brief The content as a PCL mesh: its points (with normals where the file has them for every point, and an rgb
 *  colour where it has colours: COLOR_0, or the texture at each vertex's texture coordinates; see pointColours()) and
 *  its triangles (none for a file of points).
 *  \param[in] content what readGltfFile() read
 *  \return the mesh, mm
 */
pcl::PolygonMesh
toPolygonMesh (const GltfContent& content);

} // namespace morphreg

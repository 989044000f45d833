// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private to the OBJ readers: what an OBJ file holds, parsed and checked once for the mesh reader (readObjFile) and
// the coloured surface reader (its texture coordinates and materials).
#include <morphreg/mesh/coloured_surface.h>

#include <pcl/Vertices.h>

#include <string>
#include <vector>

namespace morphreg
{
/** An OBJ file's content: vertices (with a colour each if every v line has one), normals, texture coordinates and
 *  polygons in file order, each polygon's material and each corner's texture coordinate. */
struct ObjContent
{
  std::vector<float> positions;            ///< x y z per v line
  std::vector<float> colours;              ///< r g b in [0, 1] per v line that has one
  std::vector<float> normals;              ///< x y z per vn line
  std::vector<float> texcoords;            ///< u v per vt line (v up, OBJ's convention)
  std::vector<pcl::Vertices> polygons;     ///< 0-based vertex indices
  std::vector<long long> corner_texcoords; ///< per corner of the polygons in order: 0-based vt index, -1 for none
  std::vector<int> polygon_material;       ///< per polygon: index in materials, -1 before any usemtl
  std::vector<std::string> materials;      ///< the usemtl names in order of first use
  std::vector<std::string> libraries;      ///< the mtllib file names, relative to the OBJ file's folder
};

/** Parses and checks \a path (FormatError naming the file and line of a malformed line or an index out of range). */
ObjContent
parseObjFile (const std::string& path);

/** The vertex colours as 8-bit RGB, none unless every vertex has one. */
VertexColours
vertexColours (const ObjContent& content);

/** The OBJ file as a coloured surface: polygons cut into triangles, vertex colours, and the diffuse textures
 *  (map_Kd) of its materials (mtllib) at its texture coordinates. IoError naming the OBJ file and the missing file
 *  if a material library or texture is missing; FormatError as parseObjFile() and loadRgbImage(). */
ColouredSurface
readObjSurface (const std::string& path);
} // namespace morphreg

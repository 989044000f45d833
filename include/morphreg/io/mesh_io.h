// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file mesh_io.h
 *  \brief Reading and writing meshes (PLY, OBJ, VTK, STL; OFF, glTF and GLB read) on top of PCL's readers and
 *  morphreg's own, with errors that name the file.
 *  Files are taken to be in millimetres, except glTF, whose metres are converted to mm on reading (gltf_reader.h);
 *  convert data in other units after loading.
 */
#include <morphreg/mesh/triangle_mesh.h>

#include <pcl/PolygonMesh.h>

#include <string>

namespace morphreg
{
/** \brief Loads a polygon mesh (.ply, .obj, .vtk, .stl, ASCII .off, .gltf, .glb). Throws IoError if the file is
 *  missing or unreadable, FormatError if it holds no vertices or no polygons (or, for OFF, naming the line of a bad
 *  count, coordinate or corner index).
 *  \param[in] path the mesh file
 *  \return the mesh as read
 */
pcl::PolygonMesh
loadPolygonMesh (const std::string& path);

/** \brief loadPolygonMesh() without requiring polygons: the vertices of a mesh file and its faces, if any (an OFF or
 *  PLY file of points alone, read as a point cloud).
 *  \param[in] path the mesh file
 *  \return the mesh as read
 */
pcl::PolygonMesh
loadMeshFile (const std::string& path);

/** \brief Reads an OBJ file with morphreg's own reader (PCL's crashes or hangs on some malformed files): its vertices
 *  (with an rgb colour when every vertex has one, with normals when there are as many vn as v lines) and its
 *  polygons, if any (texture coordinates and materials are ignored). FormatError naming the file and line of a
 *  malformed vertex, normal or face, or of a face index beyond the file's vertices.
 *  \param[in] path the OBJ file
 *  \return the mesh (no polygons for a file of vertices only)
 */
pcl::PolygonMesh
readObjFile (const std::string& path);

/** \brief Writes \a mesh as OBJ with morphreg's own writer, atomically with every write checked (a text file cut
 *  at a line end would still look whole, so PCL's unchecked writer is not used): v lines, vn lines when the cloud
 *  has normals, f lines.
 *  \param[in] path the OBJ file
 *  \param[in] mesh the mesh (or a cloud as a mesh without polygons)
 */
void
saveObjFile (const std::string& path, const pcl::PolygonMesh& mesh);

/** \brief Saves \a mesh (.ply binary with every vertex field, by morphreg's writer; .obj by saveObjFile; .vtk by
 *  PCL), whole or not at all (written under a temporary name, checked to be complete, then renamed); throws IoError
 *  naming the file on failure, a full disk included.
 *  \param[in] path the file; its extension chooses the format
 *  \param[in] mesh the mesh to write
 */
void
savePolygonMesh (const std::string& path, const pcl::PolygonMesh& mesh);

/** \brief Which of a mesh's per-vertex colours and "quality" scalar (toPolygonMesh) a format keeps. */
struct SavedVertexData
{
  bool colours = false; ///< the rgb colours
  bool quality = false; ///< the "quality" scalar
};

/** \brief What savePolygonMesh writes of a mesh's colours and quality in the format of \a path: .ply both (uchar red
 *  green blue, float quality: MeshLab's vertex colour and quality), .obj the colours (v x y z r g b in [0, 1]), .vtk
 *  the colours (COLOR_SCALARS; PCL's VTK writer keeps no other vertex data). Throws IoError naming \a path
 *  for another extension.
 *  \param[in] path the mesh file to be written
 *  \return what it will carry
 */
SavedVertexData
savedVertexData (const std::string& path);

/** \brief Loads a triangle mesh (non-triangle polygons are an error) and validates it.
 *  \param[in] path the mesh file (as loadPolygonMesh())
 *  \return the mesh, with vertex colours if the file has them
 */
TriangleMesh
loadTriangleMesh (const std::string& path);

/** \brief Saves a triangle mesh with vertex normals.
 *  \param[in] path the file; its extension chooses the format (as savePolygonMesh())
 *  \param[in] mesh the mesh to write
 */

void
saveTriangleMesh (const std::string& path, const TriangleMesh& mesh);

} // namespace morphreg

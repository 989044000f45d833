// SPDX-License-Identifier: BSD-3-Clause
// Mesh, cloud and landmark files as numpy arrays, read and written by the library (format sniffed from the content,
// validated before PCL or VTK see it, written atomically).
#include "bindings.h"
#include "numpy_arrays.h"

#include <morphreg/common/cloud_matrix.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_io.h>

#include <pybind11/stl.h>

namespace morphreg
{
namespace python
{
namespace
{
py::tuple
loadMesh (const std::string& path)
{
  TriangleMesh mesh = loadTriangleMesh (path);
  return py::make_tuple (toArray (std::move (mesh.vertices)), toArray (std::move (mesh.triangles)));
}

void
saveMesh (const std::string& path, const py::handle& vertices, const py::handle& faces)
{
  saveTriangleMesh (path, toMesh (vertices, faces, path));
}

/** Points, and normals unless the file has none (PCL leaves every normal zero then). */
py::tuple
loadPoints (const std::string& path)
{
  const auto cloud = loadCloud<pcl::PointNormal> (path);
  bool has_normals = false;
  for (const auto& point : *cloud)
    if (point.getNormalVector3fMap ().squaredNorm () > 0.0f) {
      has_normals = true;
      break;
    }
  return py::make_tuple (toArray (pointsOf (*cloud)),
                         has_normals ? py::object (toArray (normalsOf (*cloud))) : py::object (py::none ()));
}

void
savePoints (const std::string& path, const py::handle& points, const py::handle& normals)
{
  saveCloud (path, *toCloud (points, normals, path));
}
} // namespace

void
bindIo (py::module_& m)
{
  m.def ("load_mesh", &loadMesh, py::arg ("path"),
         "Reads a triangle mesh (PLY, OBJ, STL, VTK, OFF, glTF/GLB converted from metres to mm; the format is "
         "recognised from the content).\n"
         "Returns (vertices, faces): (N, 3) float64 and (T, 3) int32.");
  m.def ("save_mesh", &saveMesh, py::arg ("path"), py::arg ("vertices"), py::arg ("faces"),
         "Writes a triangle mesh (format from the extension: .ply, .obj, .vtk), atomically.");
  m.def ("load_cloud", &loadPoints, py::arg ("path"),
         "Reads a point cloud (PCD, PLY, or a mesh file's vertices, glTF/GLB included).\n"
         "Returns (points, normals): (N, 3) float64, and normals (N, 3) or None if the file has none.");
  m.def ("save_cloud", &savePoints, py::arg ("path"), py::arg ("points"), py::arg ("normals") = py::none (),
         "Writes a point cloud (.pcd or .ply), with normals if given, atomically.");
  m.def (
      "load_landmarks", [] (const std::string& path) { return toDict (loadLandmarks (path)); }, py::arg ("path"),
      "Reads a landmark file (MeshLab .pp, JSON, CSV; converted to mm as its units say).\n"
      "Returns a dict id -> (3,) float64 position.");
  m.def (
      "save_landmarks",
      [] (const std::string& path, const py::handle& landmarks) {
        saveLandmarks (path, toLandmarks (landmarks, path));
      },
      py::arg ("path"), py::arg ("landmarks"),
      "Writes landmarks (dict id -> (x, y, z), mm) as .pp, .json or .csv (from the extension), atomically.");
}

} // namespace python
} // namespace morphreg

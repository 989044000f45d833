#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>

#include <pcl/conversions.h>
#include <pcl/io/obj_io.h>
#include <pcl/io/ply_io.h>
#include <pcl/io/vtk_io.h>
#include <pcl/io/vtk_lib_io.h>

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

namespace morphreg
{
namespace
{
/** Reads the next count of an OFF file, skipping comments; FormatError naming the line otherwise. */
class OffTokens
{
public:
  explicit OffTokens (const std::string& path) : path_ (path), stream_ (path) {}

  /** The next whitespace-separated token ("" at the end of the file). */
  std::string
  next ()
  {
    while (!(line_ >> token_)) {
      std::string text;
      if (!std::getline (stream_, text))
        return "";
      ++line_number_;
      line_ = std::istringstream (text.substr (0, text.find ('#')));
    }
    return token_;
  }

  double
  number (const std::string& what)
  {
    const std::string text = next ();
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod (text, &used);
    }
    catch (const std::exception&) {
      used = 0;
    }
    if (text.empty () || used != text.size () || !std::isfinite (value))
      throw FormatError (where () + ": " + what + " '" + text + "' is not a finite number");
    return value;
  }

  /** A whole number in [0, limit). */
  int
  index (const std::string& what, long long limit)
  {
    const double value = number (what);
    if (value != std::floor (value) || value < 0 || value >= static_cast<double> (limit))
      throw FormatError (where () + ": " + what + " " + token_ + " is not a whole number in [0, " +
                         std::to_string (limit) + ")");
    return static_cast<int> (value);
  }

  /** Drops the rest of the current line (a face's colour). */
  void
  skipLine ()
  {
    line_ = std::istringstream ();
  }

  std::string
  where () const
  {
    return path_ + ":" + std::to_string (line_number_);
  }

private:
  std::string path_;
  std::ifstream stream_;
  std::istringstream line_;
  std::string token_;
  int line_number_ = 0;
};

/** An ASCII Object File Format mesh: "OFF", the vertex, face and edge counts, the vertices (x y z), the faces
 *  (n i_1 .. i_n; anything after them on the line, e.g. a colour, is ignored).
 */
pcl::PolygonMesh
readOffMesh (const std::string& path)
{
  OffTokens tokens (path);
  if (tokens.next () != "OFF")
    throw FormatError (path + ": not an ASCII OFF file (the first word must be 'OFF')");
  const int vertices = tokens.index ("the vertex count", std::numeric_limits<int>::max ());
  const int faces = tokens.index ("the face count", std::numeric_limits<int>::max ());
  tokens.number ("the edge count");
  pcl::PointCloud<pcl::PointXYZ> cloud;
  for (int i = 0; i < vertices; ++i) {
    const std::string what = "vertex " + std::to_string (i) + " coordinate";
    const float x = static_cast<float> (tokens.number (what + " x"));
    const float y = static_cast<float> (tokens.number (what + " y"));
    cloud.push_back ({x, y, static_cast<float> (tokens.number (what + " z"))});
  }
  pcl::PolygonMesh mesh;
  for (int f = 0; f < faces; ++f) {
    const std::string what = "face " + std::to_string (f);
    pcl::Vertices polygon;
    polygon.vertices.resize (tokens.index (what + " corner count", 1 << 20));
    for (auto& corner : polygon.vertices)
      corner = tokens.index (what + " corner", vertices);
    mesh.polygons.push_back (polygon);
    tokens.skipLine ();
  }
  pcl::toPCLPointCloud2 (cloud, mesh.cloud);
  return mesh;
}
} // namespace

pcl::PolygonMesh
loadPolygonMesh (const std::string& path)
{
  requireReadableFile (path);
  requireExtension (path, ".ply .obj .vtk .stl .off", "mesh");
  const std::string ext = fileExtension (path);
  pcl::PolygonMesh mesh;
  const int status = callPclIo (path, [&] {
    if (ext == ".off") {
      mesh = readOffMesh (path);
      return 0;
    }
    if (ext == ".ply")
      return pcl::io::loadPLYFile (path, mesh);
    if (ext == ".obj")
      return pcl::io::loadOBJFile (path, mesh);
    return pcl::io::loadPolygonFile (path, mesh) > 0 ? 0 : -1;
  });
  if (status < 0)
    throw FormatError (path + ": not a readable " + ext.substr (1) + " mesh");
  if (mesh.cloud.width * mesh.cloud.height == 0)
    throw FormatError (path + ": mesh has no vertices");
  if (mesh.polygons.empty ())
    throw FormatError (path + ": mesh has no polygons (is it a point cloud?)");
  return mesh;
}

void
savePolygonMesh (const std::string& path, const pcl::PolygonMesh& mesh)
{
  requireExtension (path, ".ply .obj .vtk", "mesh");
  const std::string ext = fileExtension (path);
  const int status = callPclIo (path, [&] {
    if (ext == ".ply")
      return pcl::io::savePLYFileBinary (path, mesh);
    if (ext == ".obj")
      return pcl::io::saveOBJFile (path, mesh);
    return pcl::io::saveVTKFile (path, mesh);
  });
  if (status < 0)
    throw IoError (path + ": cannot write the mesh");
}

TriangleMesh
loadTriangleMesh (const std::string& path)
{
  TriangleMesh mesh = fromPolygonMesh (loadPolygonMesh (path), path);
  validateMesh (mesh, path);
  return mesh;
}

void
saveTriangleMesh (const std::string& path, const TriangleMesh& mesh)
{
  savePolygonMesh (path, toPolygonMesh (mesh));
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include "off_reader.h"

#include "geometry_file_reader.h"

#include <morphreg/common/error.h>

#include <pcl/conversions.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
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

} // namespace

pcl::PolygonMesh
readOffMesh (const std::string& path)
{
  OffTokens tokens (path);
  if (tokens.next () != "OFF")
    throw FormatError (path + ": not an ASCII OFF file (the first word must be 'OFF')");
  const int vertices = tokens.index ("the vertex count", std::numeric_limits<int>::max ());
  const int faces = tokens.index ("the face count", std::numeric_limits<int>::max ());
  tokens.number ("the edge count");
  // Each vertex takes at least 6 characters ("0 0 0\n"), each face at least 8 ("3 0 1 2\n").
  const std::uint64_t size = std::filesystem::file_size (path);
  validation::requireCountFits (path, static_cast<std::uint64_t> (vertices), 6.0, size, "vertices");
  validation::requireCountFits (path, static_cast<std::uint64_t> (faces), 8.0, size - 6 * std::uint64_t (vertices),
                                "faces");
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

} // namespace morphreg

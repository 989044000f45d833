// SPDX-License-Identifier: BSD-3-Clause
#include "geometry_file_reader.h"
#include "obj_content.h"

#include <morphreg/io/rgb_image_io.h>
#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>

#include <filesystem>
#include <map>

namespace morphreg
{
namespace
{
namespace fs = std::filesystem;

/** The diffuse texture (map_Kd, its last word: options such as -s come before the file) of each material of the
 *  MTL file \a mtl, resolved against the MTL file's folder. */
std::map<std::string, std::string>
readMaterialTextures (const std::string& obj, const std::string& mtl)
{
  if (!fs::is_regular_file (mtl))
    throw IoError (obj + ": its material library " + mtl + " does not exist");
  validation::GeometryFileReader reader (mtl);
  std::map<std::string, std::string> textures;
  std::string line, material;
  std::vector<std::string_view> tokens;
  while (reader.nextLine (line)) {
    validation::splitTokens (line, tokens);
    if (tokens.size () >= 2 && tokens[0] == "newmtl")
      material = std::string (tokens[1]);
    else if (tokens.size () >= 2 && tokens[0] == "map_Kd")
      textures[material] = (fs::path (mtl).parent_path () / std::string (tokens.back ())).string ();
  }
  return textures;
}

/** The texture of each material of \a content (-1 for none), its images loaded once each into \a surface. */
std::vector<int>
loadMaterialTextures (const std::string& path, const ObjContent& content, ColouredSurface& surface)
{
  std::map<std::string, std::string> textures;
  for (const std::string& library : content.libraries)
    textures.merge (readMaterialTextures (path, (fs::path (path).parent_path () / library).string ()));
  std::vector<int> material_texture (content.materials.size (), -1);
  std::map<std::string, int> loaded;
  for (std::size_t m = 0; m < content.materials.size (); ++m) {
    const auto texture = textures.find (content.materials[m]);
    if (texture == textures.end ())
      continue;
    if (!loaded.count (texture->second)) {
      if (!fs::is_regular_file (texture->second))
        throw IoError (path + ": the texture " + texture->second + " of material " + content.materials[m] +
                       " does not exist");
      loaded[texture->second] = static_cast<int> (surface.textures.size ());
      surface.textures.push_back (loadRgbImage (texture->second));
    }
    material_texture[m] = loaded[texture->second];
  }
  return material_texture;
}

/** The polygons cut into triangle fans, with their corners' texture coordinates (v flipped to run down) and textures. */
void
addTriangles (const ObjContent& content, const std::vector<int>& material_texture, ColouredSurface& surface)
{
  std::vector<Eigen::Vector3i> triangles;
  std::vector<Eigen::Vector2f> uv;
  std::size_t first_corner = 0;
  for (std::size_t p = 0; p < content.polygons.size (); ++p) {
    const auto& corners = content.polygons[p].vertices;
    const int material = content.polygon_material[p];
    for (std::size_t k = 1; k + 1 < corners.size (); ++k) {
      const std::size_t fan[3] = {first_corner, first_corner + k, first_corner + k + 1};
      triangles.emplace_back (corners[0], corners[k], corners[k + 1]);
      bool textured = material >= 0 && material_texture[material] >= 0;
      for (const std::size_t corner : fan) {
        const long long t = content.corner_texcoords[corner];
        textured = textured && t >= 0;
        uv.emplace_back (t >= 0 ? content.texcoords[2 * t] : 0.0f, t >= 0 ? 1.0f - content.texcoords[2 * t + 1] : 0.0f);
      }
      surface.triangle_texture.push_back (textured ? material_texture[material] : -1);
    }
    first_corner += corners.size ();
  }
  surface.triangles.resize (3, static_cast<Eigen::Index> (triangles.size ()));
  for (std::size_t t = 0; t < triangles.size (); ++t)
    surface.triangles.col (static_cast<Eigen::Index> (t)) = triangles[t];
  surface.corner_uv.resize (2, static_cast<Eigen::Index> (uv.size ()));
  for (std::size_t c = 0; c < uv.size (); ++c)
    surface.corner_uv.col (static_cast<Eigen::Index> (c)) = uv[c];
}
} // namespace

ColouredSurface
readObjSurface (const std::string& path)
{
  const ObjContent content = parseObjFile (path);
  ColouredSurface surface;
  const auto count = static_cast<Eigen::Index> (content.positions.size () / 3);
  surface.points = Eigen::Map<const Eigen::Matrix3Xf> (content.positions.data (), 3, count).cast<double> ();
  surface.colours = vertexColours (content);
  addTriangles (content, loadMaterialTextures (path, content, surface), surface);
  if (surface.textures.empty ()) {
    surface.corner_uv.resize (2, 0);
    surface.triangle_texture.clear ();
  }
  return surface;
}
} // namespace morphreg

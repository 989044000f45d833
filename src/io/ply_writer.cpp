// SPDX-License-Identifier: BSD-3-Clause
#include "ply_writer.h"

#include <morphreg/common/error.h>

#include <pcl/common/io.h>

#include <cstdint>
#include <cstring>
#include <sstream>
#include <vector>

namespace morphreg
{
namespace
{
/** The PLY type of a PCL field type, or "" for one PLY has no type for. */
std::string
plyType (std::uint8_t datatype)
{
  switch (datatype) {
  case pcl::PCLPointField::INT8:
    return "char";
  case pcl::PCLPointField::UINT8:
    return "uchar";
  case pcl::PCLPointField::INT16:
    return "short";
  case pcl::PCLPointField::UINT16:
    return "ushort";
  case pcl::PCLPointField::INT32:
    return "int";
  case pcl::PCLPointField::UINT32:
    return "uint";
  case pcl::PCLPointField::FLOAT32:
    return "float";
  case pcl::PCLPointField::FLOAT64:
    return "double";
  default:
    return "";
  }
}

bool
isColour (const pcl::PCLPointField& field)
{
  return field.name == "rgb" || field.name == "rgba";
}

/** The header's property lines of one field, checked. */
std::string
propertyLines (const std::string& path, const pcl::PCLPointField& field)
{
  if (isColour (field))
    return std::string ("property uchar red\nproperty uchar green\nproperty uchar blue\n") +
           (field.name == "rgba" ? "property uchar alpha\n" : "");
  const std::string type = plyType (field.datatype);
  if (field.count != 1 || type.empty ())
    throw InvalidInputError (path + ": the vertex field '" + field.name + "' (" + std::to_string (field.count) +
                             " value(s) of PCL type " + std::to_string (field.datatype) + ") has no PLY property type");
  const bool normal = field.name.rfind ("normal_", 0) == 0 && field.name.size () == 8;
  return "property " + type + " " + (normal ? "n" + field.name.substr (7) : field.name) + "\n";
}

/** The bytes of one field of one point as the properties have them (in the host's order, little-endian on the
 *  x86-64 and ARM machines PCL runs on, as PCL's own writer does): a packed colour as its channels. */
void
writeField (std::string& bytes, const std::uint8_t* point, const pcl::PCLPointField& field)
{
  const std::uint8_t* value = point + field.offset;
  if (!isColour (field)) {
    bytes.append (reinterpret_cast<const char*> (value), pcl::getFieldSize (field.datatype));
    return;
  }
  std::uint32_t packed;
  std::memcpy (&packed, value, sizeof (packed)); // 0xAARRGGBB
  for (int shift : {16, 8, 0})
    bytes.push_back (static_cast<char> ((packed >> shift) & 0xffu));
  if (field.name == "rgba")
    bytes.push_back (static_cast<char> (packed >> 24));
}
} // namespace

std::string
plyMeshBytes (const std::string& path, const pcl::PolygonMesh& mesh)
{
  std::vector<pcl::PCLPointField> fields;
  std::ostringstream header;
  const std::size_t points = std::size_t (mesh.cloud.width) * mesh.cloud.height;
  header << "ply\nformat binary_little_endian 1.0\ncomment written by morphreg\nelement vertex " << points << '\n';
  for (const pcl::PCLPointField& field : mesh.cloud.fields)
    if (field.name != "_") {
      header << propertyLines (path, field);
      fields.push_back (field);
    }
  header << "element face " << mesh.polygons.size () << "\nproperty list uchar int vertex_indices\nend_header\n";
  std::string bytes = header.str ();
  for (std::size_t i = 0; i < points; ++i)
    for (const pcl::PCLPointField& field : fields)
      writeField (bytes, mesh.cloud.data.data () + i * mesh.cloud.point_step, field);
  for (const pcl::Vertices& polygon : mesh.polygons) {
    if (polygon.vertices.size () > 255)
      throw InvalidInputError (path + ": a polygon of " + std::to_string (polygon.vertices.size ()) +
                               " corners; a PLY face holds at most 255");
    bytes.push_back (static_cast<char> (polygon.vertices.size ()));
    for (const auto corner : polygon.vertices) {
      const auto index = static_cast<std::int32_t> (corner);
      bytes.append (reinterpret_cast<const char*> (&index), sizeof (index));
    }
  }
  return bytes;
}
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include "geometry_file_reader.h"
#include "geometry_validators.h"

#include <morphreg/io/pcd_reader.h>

#include <pcl/io/lzf.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <set>
#include <type_traits>

namespace morphreg
{
namespace
{
using validation::GeometryFileReader;
using validation::splitTokens;

/** LZF, PCL's binary_compressed codec, at best turns 3 bytes into 264 (one back reference). */
constexpr double max_lzf_expansion = 88.0;

/** PCL indexes a cloud's points with pcl::index_t and addresses its rows and fields with 32-bit unsigned numbers. */
constexpr std::uint64_t max_pcl_points = std::numeric_limits<pcl::index_t>::max ();
constexpr std::uint64_t max_pcl_bytes = std::numeric_limits<std::uint32_t>::max ();

struct PcdHeader
{
  std::vector<std::string> fields;
  std::vector<long long> sizes;
  std::vector<std::string> types;
  std::vector<long long> counts;
  long long width = -1;
  long long height = -1;
  long long points = -1;
  float viewpoint[7] = {0.0f, 0.0f, 0.0f, 1.0f, 0.0f, 0.0f, 0.0f};
  std::string data;
};

/** \a a * \a b, or the largest number if that overflows (more than any file holds). */
std::uint64_t
saturatingProduct (std::uint64_t a, std::uint64_t b)
{
  std::uint64_t product = 0;
  return __builtin_mul_overflow (a, b, &product) ? std::numeric_limits<std::uint64_t>::max () : product;
}

/** Parses \a token as a \a T (a leading '+' allowed; "nan" and "inf" for floating point): false if it is none or
 *  beyond T's range. A floating-point number too small for T becomes T's nearest (0 or subnormal), as C++ streams
 *  and PCL's reader read it.
 */
template <typename T>
bool
parseValue (std::string_view token, T& value)
{
  if (token.size () > 1 && token[0] == '+' && token[1] != '-')
    token.remove_prefix (1);
  const char* const end = token.data () + token.size ();
  auto [stop, ec] = std::from_chars (token.data (), end, value);
  if constexpr (std::is_floating_point_v<T>)
    if (ec == std::errc::result_out_of_range) {
      long double wide = 0.0L;
      const auto parsed = std::from_chars (token.data (), end, wide);
      if (parsed.ec != std::errc () || std::abs (wide) > std::numeric_limits<T>::max ())
        return false;
      value = static_cast<T> (wide);
      ec = std::errc ();
    }
  return ec == std::errc () && stop == end && !token.empty ();
}

std::vector<long long>
parseIntegers (const GeometryFileReader& reader, const std::vector<std::string_view>& tokens, long long low,
               long long high)
{
  std::vector<long long> values;
  for (std::size_t i = 1; i < tokens.size (); ++i) {
    long long value = 0;
    if (!parseValue (tokens[i], value) || value < low || value > high)
      reader.failAtLine (std::string (tokens[0]) + " value '" + std::string (tokens[i]) +
                         "' is not a whole number in [" + std::to_string (low) + ", " + std::to_string (high) + "]");
    values.push_back (value);
  }
  return values;
}

long long
parseOneInteger (const GeometryFileReader& reader, const std::vector<std::string_view>& tokens)
{
  if (tokens.size () != 2)
    reader.failAtLine (std::string (tokens[0]) + " must be followed by one number");
  return parseIntegers (reader, tokens, 0, std::numeric_limits<long long>::max ()).front ();
}

void
parseViewpoint (const GeometryFileReader& reader, const std::vector<std::string_view>& tokens, PcdHeader& header)
{
  bool valid = tokens.size () == 8;
  for (std::size_t i = 0; valid && i < 7; ++i)
    valid = parseValue (tokens[i + 1], header.viewpoint[i]) && std::isfinite (header.viewpoint[i]);
  if (!valid)
    reader.failAtLine ("VIEWPOINT must be followed by 7 finite numbers (tx ty tz qw qx qy qz)");
}

/** One header line other than DATA into \a header. */
void
parseHeaderLine (const GeometryFileReader& reader, const std::vector<std::string_view>& tokens, PcdHeader& header)
{
  const std::string_view keyword = tokens[0];
  const std::vector<std::string> words (tokens.begin () + 1, tokens.end ());
  if (keyword == "VERSION")
    return;
  if (keyword == "FIELDS" || keyword == "COLUMNS")
    header.fields = words;
  else if (keyword == "SIZE")
    header.sizes = parseIntegers (reader, tokens, 1, 8);
  else if (keyword == "TYPE")
    header.types = words;
  else if (keyword == "COUNT")
    header.counts = parseIntegers (reader, tokens, 1, 1 << 20);
  else if (keyword == "WIDTH")
    header.width = parseOneInteger (reader, tokens);
  else if (keyword == "HEIGHT")
    header.height = parseOneInteger (reader, tokens);
  else if (keyword == "POINTS")
    header.points = parseOneInteger (reader, tokens);
  else if (keyword == "VIEWPOINT")
    parseViewpoint (reader, tokens, header);
  else
    reader.failAtLine ("unexpected PCD header line starting with '" + std::string (keyword.substr (0, 40)) + "'");
}

/** The header up to and including its DATA line; each keyword at most once. */
PcdHeader
parseHeader (GeometryFileReader& reader)
{
  PcdHeader header;
  std::set<std::string> seen;
  std::string line;
  std::vector<std::string_view> tokens;
  while (header.data.empty ()) {
    if (!reader.nextLine (line))
      reader.fail ("the PCD header has no DATA line (the file is cut short or not a PCD file)");
    splitTokens (line, tokens);
    if (tokens.empty () || tokens[0][0] == '#')
      continue;
    if (tokens[0] != "DATA")
      parseHeaderLine (reader, tokens, header);
    else if (tokens.size () == 2 && (tokens[1] == "ascii" || tokens[1] == "binary" || tokens[1] == "binary_compressed"))
      header.data = std::string (tokens[1]);
    else
      reader.failAtLine ("the DATA line must be 'DATA ascii', 'DATA binary' or 'DATA binary_compressed'");
    if (!seen.insert (tokens[0] == "COLUMNS" ? "FIELDS" : std::string (tokens[0])).second)
      reader.failAtLine (std::string (tokens[0]) + " appears more than once in the PCD header");
  }
  return header;
}

/** PCL's datatype of a field of \a type and \a size, 0 if they are no valid pair. */
std::uint8_t
fieldDatatype (const std::string& type, long long size)
{
  using Field = pcl::PCLPointField;
  if (type == "F")
    return size == 4 ? Field::FLOAT32 : size == 8 ? Field::FLOAT64 : 0;
  if (type != "I" && type != "U")
    return 0;
  const bool is_signed = type == "I";
  switch (size) {
  case 1:
    return is_signed ? Field::INT8 : Field::UINT8;
  case 2:
    return is_signed ? Field::INT16 : Field::UINT16;
  case 4:
    return is_signed ? Field::INT32 : Field::UINT32;
  case 8:
    return is_signed ? Field::INT64 : Field::UINT64;
  default:
    return 0;
  }
}

/** FIELDS, SIZE, TYPE and COUNT (1 each if absent) list one value per field. */
void
checkFieldLists (const GeometryFileReader& reader, PcdHeader& header)
{
  const std::size_t n = header.fields.size ();
  if (n == 0)
    reader.fail ("the PCD header has no FIELDS");
  if (header.counts.empty ())
    header.counts.assign (n, 1);
  if (header.sizes.size () != n || header.types.size () != n || header.counts.size () != n)
    reader.fail ("the PCD header lists " + std::to_string (n) + " FIELDS but " + std::to_string (header.sizes.size ()) +
                 " SIZE, " + std::to_string (header.types.size ()) + " TYPE and " +
                 std::to_string (header.counts.size ()) + " COUNT values");
}

/** The cloud's fields, packed in header order, and its point_step. */
pcl::PCLPointCloud2
cloudFields (const GeometryFileReader& reader, PcdHeader& header)
{
  checkFieldLists (reader, header);
  pcl::PCLPointCloud2 cloud;
  std::set<std::string> names;
  std::uint64_t offset = 0;
  for (std::size_t i = 0; i < header.fields.size (); ++i) {
    pcl::PCLPointField field;
    field.name = header.fields[i];
    field.datatype = fieldDatatype (header.types[i], header.sizes[i]);
    if (field.datatype == 0)
      reader.fail ("PCD field '" + field.name + "' has TYPE " + header.types[i] + " and SIZE " +
                   std::to_string (header.sizes[i]) + ", which is not a valid pair (F 4|8, I or U 1|2|4|8)");
    if (field.name != "_" && !names.insert (field.name).second)
      reader.fail ("PCD field '" + field.name + "' is listed twice in FIELDS");
    field.offset = static_cast<pcl::uindex_t> (offset);
    field.count = static_cast<pcl::uindex_t> (header.counts[i]);
    offset += static_cast<std::uint64_t> (header.sizes[i] * header.counts[i]);
    if (offset > max_pcl_bytes)
      reader.fail ("a point of the PCD file's fields takes more than the 4 GB PCL allows a point");
    cloud.fields.push_back (field);
  }
  cloud.point_step = static_cast<std::uint32_t> (offset);
  return cloud;
}

/** WIDTH, HEIGHT and POINTS are given and WIDTH * HEIGHT = POINTS > 0. */
void
checkDimensions (const GeometryFileReader& reader, const PcdHeader& header)
{
  for (const auto& [value, name] :
       {std::pair (header.width, "WIDTH"), std::pair (header.height, "HEIGHT"), std::pair (header.points, "POINTS")})
    if (value < 0)
      reader.fail (std::string ("the PCD header has no ") + name + " line");
  if (saturatingProduct (header.width, header.height) != static_cast<std::uint64_t> (header.points))
    reader.fail ("the PCD header's WIDTH " + std::to_string (header.width) + " times HEIGHT " +
                 std::to_string (header.height) + " is not its POINTS " + std::to_string (header.points));
  if (header.points == 0)
    reader.fail ("the PCD file holds no points (POINTS 0)");
}

/** Once the data is known to fit in the file: the cloud fits in PCL's; sets its width, height and row_step. */
void
setDimensions (const GeometryFileReader& reader, const PcdHeader& header, pcl::PCLPointCloud2& cloud)
{
  const auto points = static_cast<std::uint64_t> (header.points);
  const auto width = static_cast<std::uint64_t> (header.width);
  if (points > max_pcl_points)
    reader.fail ("the PCD file holds " + std::to_string (points) + " points, more than the " +
                 std::to_string (max_pcl_points) + " of a PCL cloud");
  if (width * cloud.point_step > max_pcl_bytes)
    reader.fail ("a row of the PCD cloud (WIDTH " + std::to_string (width) + " points of " +
                 std::to_string (cloud.point_step) + " bytes) takes more than the 4 GB PCL allows a row");
  cloud.width = static_cast<pcl::uindex_t> (width);
  cloud.height = static_cast<pcl::uindex_t> (header.height);
  cloud.row_step = static_cast<std::uint32_t> (width * cloud.point_step);
}

std::uint32_t
littleEndian32 (const unsigned char* bytes)
{
  return static_cast<std::uint32_t> (bytes[0]) | static_cast<std::uint32_t> (bytes[1]) << 8 |
         static_cast<std::uint32_t> (bytes[2]) << 16 | static_cast<std::uint32_t> (bytes[3]) << 24;
}

/** binary_compressed: the compressed and unpacked sizes that precede the data agree with the file and with POINTS
 *  points of \a point_step bytes. Returns the compressed size.
 */
std::uint64_t
checkCompressedSizes (GeometryFileReader& reader, std::uint64_t points, std::uint64_t point_step)
{
  unsigned char sizes[8];
  if (!reader.readBytes (reinterpret_cast<char*> (sizes), 8))
    reader.fail ("the compressed PCD data has no sizes (the file is cut short)");
  const std::uint64_t compressed = littleEndian32 (sizes);
  const std::uint64_t unpacked = littleEndian32 (sizes + 4);
  if (compressed > reader.remaining ())
    reader.fail ("the compressed PCD data claims " + std::to_string (compressed) + " bytes but the file holds " +
                 std::to_string (reader.remaining ()) + " after its header (the file is cut short)");
  if (unpacked != saturatingProduct (points, point_step))
    reader.fail ("the compressed PCD data unpacks to " + std::to_string (unpacked) + " bytes but POINTS " +
                 std::to_string (points) + " of " + std::to_string (point_step) + " bytes need " +
                 validation::describeBytes (static_cast<double> (points) * static_cast<double> (point_step)));
  if (static_cast<double> (unpacked) > max_lzf_expansion * static_cast<double> (compressed))
    reader.fail ("the compressed PCD data (" + std::to_string (compressed) + " bytes) cannot unpack to the " +
                 std::to_string (unpacked) + " bytes its header claims");
  return compressed;
}

/** The bytes of field \a f of \a cloud (its fields are packed). */
std::uint64_t
fieldBytes (const pcl::PCLPointCloud2& cloud, std::size_t f)
{
  const std::uint64_t end = f + 1 < cloud.fields.size () ? cloud.fields[f + 1].offset : cloud.point_step;
  return end - cloud.fields[f].offset;
}

/** binary_compressed: LZF data holding all points' values of the first field, then of the second, and so on. */
void
readCompressedPoints (GeometryFileReader& reader, std::uint64_t compressed, pcl::PCLPointCloud2& cloud)
{
  std::vector<char> packed (compressed);
  if (!reader.readBytes (packed.data (), compressed))
    reader.fail ("the file ends inside the compressed PCD data");
  const std::uint64_t points = static_cast<std::uint64_t> (cloud.width) * cloud.height;
  const std::uint64_t size = points * cloud.point_step;
  std::vector<std::uint8_t> by_field (size);
  const unsigned int unpacked = pcl::lzfDecompress (packed.data (), static_cast<unsigned int> (compressed),
                                                    by_field.data (), static_cast<unsigned int> (size));
  if (unpacked != size)
    reader.fail ("the compressed PCD data is corrupt: it unpacks to " + std::to_string (unpacked) + " of the " +
                 std::to_string (size) + " bytes its header gives");
  cloud.data.resize (size);
  const std::uint8_t* source = by_field.data ();
  for (std::size_t f = 0; f < cloud.fields.size (); ++f) {
    const std::uint64_t bytes = fieldBytes (cloud, f);
    for (std::uint64_t i = 0; i < points; ++i, source += bytes)
      std::memcpy (cloud.data.data () + i * cloud.point_step + cloud.fields[f].offset, source, bytes);
  }
}

/** Where one value of a point goes: its byte offset in the point, its field and the field's datatype. */
struct ValueSlot
{
  std::uint64_t offset;
  std::uint32_t field;
  std::uint8_t datatype;
};

/** The slots of the values of a point, in the order of an ASCII line. */
std::vector<ValueSlot>
valueSlots (const PcdHeader& header, const pcl::PCLPointCloud2& cloud)
{
  std::vector<ValueSlot> slots;
  for (std::size_t f = 0; f < cloud.fields.size (); ++f)
    for (long long c = 0; c < header.counts[f]; ++c)
      slots.push_back ({cloud.fields[f].offset + static_cast<std::uint64_t> (c * header.sizes[f]),
                        static_cast<std::uint32_t> (f), cloud.fields[f].datatype});
  return slots;
}

template <typename T>
bool
storeValue (std::string_view token, std::uint8_t* out)
{
  T value{};
  if (!parseValue (token, value))
    return false;
  std::memcpy (out, &value, sizeof (T));
  return true;
}

/** Parses \a token as a value of \a datatype into \a out; false if it is not one. */
bool
storeToken (std::string_view token, std::uint8_t datatype, std::uint8_t* out)
{
  using Field = pcl::PCLPointField;
  switch (datatype) {
  case Field::INT8:
    return storeValue<std::int8_t> (token, out);
  case Field::UINT8:
    return storeValue<std::uint8_t> (token, out);
  case Field::INT16:
    return storeValue<std::int16_t> (token, out);
  case Field::UINT16:
    return storeValue<std::uint16_t> (token, out);
  case Field::INT32:
    return storeValue<std::int32_t> (token, out);
  case Field::UINT32:
    return storeValue<std::uint32_t> (token, out);
  case Field::INT64:
    return storeValue<std::int64_t> (token, out);
  case Field::UINT64:
    return storeValue<std::uint64_t> (token, out);
  case Field::FLOAT32:
    return storeValue<float> (token, out);
  default:
    return storeValue<double> (token, out);
  }
}

/** ascii: a line of one value per slot for each point (blank lines skipped). */
void
readAsciiPoints (GeometryFileReader& reader, const PcdHeader& header, pcl::PCLPointCloud2& cloud)
{
  const std::vector<ValueSlot> slots = valueSlots (header, cloud);
  const auto points = static_cast<std::uint64_t> (header.points);
  cloud.data.resize (points * cloud.point_step);
  std::string line;
  std::vector<std::string_view> tokens;
  for (std::uint64_t point = 0; point < points;) {
    if (!reader.nextLine (line))
      reader.fail ("the file ends after " + std::to_string (point) + " of its " + std::to_string (points) +
                   " points (the data is cut short)");
    splitTokens (line, tokens);
    if (tokens.empty ())
      continue;
    if (tokens.size () != slots.size ())
      reader.failAtLine ("point " + std::to_string (point) + " has " + std::to_string (tokens.size ()) +
                         " values, expected " + std::to_string (slots.size ()));
    std::uint8_t* const values = cloud.data.data () + point * cloud.point_step;
    for (std::size_t v = 0; v < tokens.size (); ++v)
      if (!storeToken (tokens[v], slots[v].datatype, values + slots[v].offset))
        reader.failAtLine ("value '" + std::string (tokens[v].substr (0, 40)) + "' of point " + std::to_string (point) +
                           " is not a number of its field's TYPE " + header.types[slots[v].field] + " and SIZE " +
                           std::to_string (header.sizes[slots[v].field]));
    ++point;
  }
}

template <typename T>
bool
fieldIsFinite (const pcl::PCLPointCloud2& cloud, const pcl::PCLPointField& field)
{
  for (std::size_t at = field.offset; at < cloud.data.size (); at += cloud.point_step)
    for (std::size_t c = 0; c < field.count; ++c) {
      T value;
      std::memcpy (&value, cloud.data.data () + at + c * sizeof (T), sizeof (T));
      if (!std::isfinite (value))
        return false;
    }
  return true;
}

/** No float value of \a cloud is NaN or infinite (PCL's is_dense). */
bool
allFinite (const pcl::PCLPointCloud2& cloud)
{
  return std::all_of (cloud.fields.begin (), cloud.fields.end (), [&] (const pcl::PCLPointField& field) {
    if (field.datatype == pcl::PCLPointField::FLOAT32)
      return fieldIsFinite<float> (cloud, field);
    return field.datatype != pcl::PCLPointField::FLOAT64 || fieldIsFinite<double> (cloud, field);
  });
}

/** The data after the header fits in the file (POINTS of the header's fields) before anything is allocated for it.
 *  Returns the size of binary_compressed data, 0 for the other kinds.
 */
std::uint64_t
checkDataFits (GeometryFileReader& reader, const PcdHeader& header, const pcl::PCLPointCloud2& cloud)
{
  const auto points = static_cast<std::uint64_t> (header.points);
  if (header.data == "binary_compressed")
    return checkCompressedSizes (reader, points, cloud.point_step);
  if (header.data == "binary") {
    if (saturatingProduct (points, cloud.point_step) > reader.remaining ())
      throw validation::countBeyondFile (reader.path (), points, cloud.point_step, reader.remaining (), "points");
    return 0;
  }
  double values = 0.0; // a value takes at least 2 bytes: a digit and a separator
  for (const long long count : header.counts)
    values += static_cast<double> (count);
  validation::requireCountFits (reader.path (), points, 2.0 * values, reader.remaining (), "points", true);
  return 0;
}

/** PCL converts the points' positions only from fields x, y and z of one 4-byte float each; without them a cloud
 *  would load as points at the origin. */
void
requirePositionFields (const GeometryFileReader& reader, const pcl::PCLPointCloud2& cloud)
{
  for (const char* axis : {"x", "y", "z"}) {
    const auto field = std::find_if (cloud.fields.begin (), cloud.fields.end (),
                                     [&] (const pcl::PCLPointField& f) { return f.name == axis; });
    if (field == cloud.fields.end () || field->datatype != pcl::PCLPointField::FLOAT32 || field->count != 1)
      reader.fail (std::string ("the PCD file has no field '") + axis +
                   "' of TYPE F, SIZE 4 and COUNT 1, which the points' positions are read from");
  }
}

/** Reads \a path; with \a read_binary_data false, binary data (which any bytes are) is only checked to fit. */
PcdCloud
readPcd (const std::string& path, bool read_binary_data)
{
  GeometryFileReader reader (path);
  PcdHeader header = parseHeader (reader);
  PcdCloud result;
  pcl::PCLPointCloud2& cloud = result.cloud;
  cloud = cloudFields (reader, header);
  checkDimensions (reader, header);
  const std::uint64_t compressed = checkDataFits (reader, header, cloud);
  setDimensions (reader, header, cloud);
  requirePositionFields (reader, cloud);
  if (header.data == "binary") {
    if (!read_binary_data)
      return result;
    cloud.data.resize (static_cast<std::size_t> (cloud.row_step) * cloud.height);
    if (!reader.readBytes (reinterpret_cast<char*> (cloud.data.data ()), cloud.data.size ()))
      reader.fail ("the file ends inside the binary PCD data");
  }
  else if (header.data == "binary_compressed")
    readCompressedPoints (reader, compressed, cloud);
  else
    readAsciiPoints (reader, header, cloud);
  cloud.is_dense = allFinite (cloud);
  const float* viewpoint = header.viewpoint;
  result.origin = Eigen::Vector4f (viewpoint[0], viewpoint[1], viewpoint[2], 0.0f);
  result.orientation = Eigen::Quaternionf (viewpoint[3], viewpoint[4], viewpoint[5], viewpoint[6]);
  return result;
}
} // namespace

PcdCloud
readPcdFile (const std::string& path)
{
  return readPcd (path, true);
}

namespace validation
{
void
validatePcdFile (const std::string& path)
{
  readPcd (path, false);
}
} // namespace validation
} // namespace morphreg

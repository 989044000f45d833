// SPDX-License-Identifier: BSD-3-Clause
#include "../common/number_text.h"
#include "text_fields.h"

#include <morphreg/common/error.h>
#include <morphreg/io/atomic_file.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/landmark_io.h>

#include <nlohmann/json.hpp>
#include <tinyxml2.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

namespace morphreg
{
namespace
{
using detail::numberText;

/** Landmark coordinates beyond this magnitude (10 km in mm) are a corrupt file, whatever the unit. */
constexpr double kMaxLandmarkCoordinate = 1e7;

template <int Dim>
using Point = Eigen::Matrix<double, Dim, 1>;

template <int Dim>
using NamedPoints = std::map<std::string, Point<Dim>>;

/** \brief One landmark as read, with where it was found ("file.csv:4") for error messages. */
template <int Dim>
struct Entry
{
  std::string id;
  Point<Dim> position;
  std::string where;
};

const std::array<const char*, 3> kAxisNames = {"x", "y", "z"};

std::string
axisList (int dim)
{
  std::string list;
  for (int i = 0; i < dim; ++i)
    list += std::string (i ? "," : "") + kAxisNames[i];
  return list;
}

using text::trim;

std::string
toLower (std::string text)
{
  std::transform (text.begin (), text.end (), text.begin (), [] (unsigned char c) { return std::tolower (c); });
  return text;
}

/** \brief Parses the whole of \a text as a finite number; FormatError naming \a where and \a what otherwise. */
double
parseNumber (const std::string& text, const std::string& where, const std::string& what)
{
  std::string value = trim (text);
  if (!value.empty () && value.front () == '+')
    value.erase (0, 1);
  double number = 0.0;
  const auto [end, ec] = std::from_chars (value.data (), value.data () + value.size (), number);
  if (value.empty () || ec != std::errc () || end != value.data () + value.size () || !std::isfinite (number))
    throw FormatError (where + ": " + what + " '" + trim (text) + "' is not a finite number");
  return number;
}

std::string
formatNumber (double value)
{
  std::array<char, 64> buffer;
  const auto result = std::to_chars (buffer.data (), buffer.data () + buffer.size (), value);
  return std::string (buffer.data (), result.ptr);
}

std::string
readWholeFile (const std::string& path)
{
  requireReadableFile (path, kMaxTextFileBytes);
  std::ifstream stream (path, std::ios::binary);
  std::ostringstream content;
  content << stream.rdbuf ();
  return content.str ();
}

// ---------------------------------------------------------------------------------------------------------------
// Readers: each returns the entries in file order; validation of the set is shared (collect).

std::vector<Entry<3>>
readPickedPoints (const std::string& path)
{
  const std::string content = readWholeFile (path);
  tinyxml2::XMLDocument document;
  if (document.Parse (content.data (), content.size ()) != tinyxml2::XML_SUCCESS)
    throw FormatError (path + ":" + std::to_string (document.ErrorLineNum ()) + ": malformed XML (" +
                       document.ErrorStr () + ")");
  const tinyxml2::XMLElement* root = document.RootElement ();
  if (root == nullptr || std::string (root->Name ()) != "PickedPoints")
    throw FormatError (path + ": not a MeshLab PickedPoints file (the root element must be <PickedPoints>)");
  std::vector<Entry<3>> entries;
  for (const auto* point = root->FirstChildElement ("point"); point; point = point->NextSiblingElement ("point")) {
    const std::string where = path + ":" + std::to_string (point->GetLineNum ());
    const char* active = point->Attribute ("active");
    if (active != nullptr && trim (active) == "0")
      continue;
    const char* name = point->Attribute ("name");
    if (name == nullptr)
      throw FormatError (where + ": <point> has no 'name' attribute");
    Entry<3> entry{name, Point<3>::Zero (), where};
    for (int axis = 0; axis < 3; ++axis) {
      const char* value = point->Attribute (kAxisNames[axis]);
      if (value == nullptr)
        throw FormatError (where + ": point '" + entry.id + "' has no '" + kAxisNames[axis] + "' attribute");
      entry.position[axis] = parseNumber (value, where, std::string ("coordinate ") + kAxisNames[axis]);
    }
    entries.push_back (entry);
  }
  return entries;
}

/** \brief The point count of a .pts header: a whole number, at most a billion (so it converts exactly). */
long long
parsePointCount (const std::string& text, const std::string& where)
{
  const double count = parseNumber (text, where, "n_points");
  if (count < 0.0 || count > 1e9 || count != std::floor (count))
    throw FormatError (where + ": n_points '" + trim (text) + "' is not a point count");
  return static_cast<long long> (count);
}

std::vector<std::string>
splitWhitespace (const std::string& line)
{
  std::vector<std::string> fields;
  std::istringstream stream (line);
  for (std::string field; stream >> field;)
    fields.push_back (field);
  return fields;
}

/** \brief An iBUG .pts file: "version: 1", "n_points: 68", then the 68 points between braces, one per line (x y,
 *  or x y z for 3D points). Point k is "ibug68_k" (0-based, two digits).
 */
template <int Dim>
std::vector<Entry<Dim>>
readPts (const std::string& path)
{
  std::istringstream stream (readWholeFile (path));
  long long declared = -1;
  bool open = false, closed = false;
  std::vector<Entry<Dim>> entries;
  int line_number = 0;
  for (std::string line; std::getline (stream, line);) {
    ++line_number;
    line = trim (line);
    const std::string where = path + ":" + std::to_string (line_number);
    if (line.empty () || closed)
      continue;
    if (!open && line.rfind ("n_points:", 0) == 0)
      declared = parsePointCount (line.substr (9), where);
    else if (!open && line == "{")
      open = true;
    else if (!open && line.rfind ("version:", 0) != 0)
      throw FormatError (where + ": expected 'version:', 'n_points:' or '{' in the header, found '" + line + "'");
    else if (open && line == "}")
      closed = true;
    else if (open) {
      const std::vector<std::string> fields = splitWhitespace (line);
      if (fields.size () != Dim)
        throw FormatError (where + ": expected " + std::to_string (Dim) + " coordinates (" + axisList (Dim) +
                           "), found " + std::to_string (fields.size ()));
      if (entries.size () == 68)
        throw FormatError (where + ": more than 68 points (iBUG-68 has 68)");
      Entry<Dim> entry{ibug68LandmarkId (static_cast<int> (entries.size ())), Point<Dim>::Zero (), where};
      for (int axis = 0; axis < Dim; ++axis)
        entry.position[axis] = parseNumber (fields[axis], where, std::string ("coordinate ") + kAxisNames[axis]);
      entries.push_back (entry);
    }
  }
  if (declared != 68)
    throw FormatError (
        path + ": " +
        (declared < 0 ? std::string ("no 'n_points:' line") : "n_points is " + std::to_string (declared)) +
        "; iBUG-68 files have 68 points");
  if (!closed)
    throw FormatError (path + ": the points are not enclosed in '{' ... '}'");
  if (entries.size () != 68)
    throw FormatError (path + ": " + std::to_string (entries.size ()) + " points, but n_points is 68");
  return entries;
}

/** \brief Millimetres per unit for 3D files; pixel files must say "px". */
template <int Dim>
double
unitScale (const std::string& units, const std::string& where)
{
  if (Dim == 2) {
    if (units != "px")
      throw FormatError (where + ": units '" + units + "', but pixel landmarks need \"px\"");
    return 1.0;
  }
  if (units == "mm")
    return 1.0;
  if (units == "cm")
    return 10.0;
  if (units == "m")
    return 1000.0;
  throw FormatError (where + ": units '" + units + "' not supported for 3D landmarks (use \"mm\", \"cm\" or \"m\")");
}

template <int Dim>
Entry<Dim>
readJsonLandmark (const nlohmann::json& item, const std::string& where, double scale)
{
  if (!item.is_object ())
    throw FormatError (where + ": expected an object {\"id\": ..., \"position\": [...]}");
  const auto id = item.find ("id");
  if (id == item.end () || !id->is_string ())
    throw FormatError (where + ": missing or non-string \"id\"");
  Entry<Dim> entry{id->get<std::string> (), Point<Dim>::Zero (), where + " ('" + id->get<std::string> () + "')"};
  const auto position = item.find ("position");
  if (position == item.end () || !position->is_array () || position->size () != Dim)
    throw FormatError (entry.where + ": \"position\" must be an array of " + std::to_string (Dim) + " numbers [" +
                       axisList (Dim) + "]" +
                       (position != item.end () && position->is_array ()
                            ? ", found " + std::to_string (position->size ())
                            : std::string ()));
  for (int axis = 0; axis < Dim; ++axis) {
    const auto& value = (*position)[axis];
    if (!value.is_number ())
      throw FormatError (entry.where + ": coordinate " + kAxisNames[axis] + " (" + value.dump () + ") is not a number");
    entry.position[axis] = scale * value.get<double> ();
  }
  return entry;
}

/** \brief The scalismo / Basel Face Model layout: [{"id": ..., "coordinates": [x, y, z]}, ...] in mm, ids
 *  translated by fromBfmLandmarkId(); other members of an entry (e.g. "uncertainty") are ignored.
 */
std::vector<Entry<3>>
readScalismoEntries (const nlohmann::json& document, const std::string& source)
{
  std::vector<Entry<3>> entries;
  for (std::size_t i = 0; i < document.size (); ++i) {
    const nlohmann::json& item = document[i];
    const std::string where = source + ": [" + std::to_string (i) + "]";
    if (!item.is_object () || !item.contains ("id") || !item["id"].is_string ())
      throw FormatError (where + ": expected an object {\"id\": \"...\", \"coordinates\": [x, y, z]}");
    const std::string id = item["id"].get<std::string> ();
    if (!item.contains ("coordinates") || !item["coordinates"].is_array () || item["coordinates"].size () != 3)
      throw FormatError (where + " ('" + id + "'): \"coordinates\" must be an array of 3 numbers [x,y,z]");
    entries.push_back (
        readJsonLandmark<3> ({{"id", fromBfmLandmarkId (id)}, {"position", item["coordinates"]}}, where, 1.0));
  }
  return entries;
}

nlohmann::json
parseJsonText (const std::string& text, const std::string& source)
{
  try {
    return nlohmann::json::parse (text);
  }
  catch (const nlohmann::json::exception& e) { // a syntax error, or a number too large for a double
    throw FormatError (source + ": malformed JSON (" + e.what () + ")");
  }
}

template <int Dim>
std::vector<Entry<Dim>>
readJson (const std::string& path)
{
  const nlohmann::json document = parseJsonText (readWholeFile (path), path);
  if constexpr (Dim == 3)
    if (document.is_array ())
      return readScalismoEntries (document, path);
  if (!document.is_object ())
    throw FormatError (path + ": the top level must be an object with a \"landmarks\" array" +
                       (Dim == 3 ? " or a scalismo array [{\"id\": ..., \"coordinates\": [...]}]" : ""));
  std::string units = Dim == 3 ? "mm" : "px";
  if (const auto it = document.find ("units"); it != document.end ()) {
    if (!it->is_string ())
      throw FormatError (path + ": \"units\" must be a string");
    units = it->get<std::string> ();
  }
  const double scale = unitScale<Dim> (units, path);
  const auto landmarks = document.find ("landmarks");
  if (landmarks == document.end () || !landmarks->is_array ())
    throw FormatError (path + ": missing \"landmarks\" array");
  std::vector<Entry<Dim>> entries;
  for (std::size_t i = 0; i < landmarks->size (); ++i)
    entries.push_back (
        readJsonLandmark<Dim> ((*landmarks)[i], path + ": landmarks[" + std::to_string (i) + "]", scale));
  return entries;
}

template <int Dim>
std::vector<Entry<Dim>>
readCsv (const std::string& path)
{
  std::istringstream stream (readWholeFile (path));
  const std::string header = "id," + axisList (Dim);
  bool header_seen = false;
  std::vector<Entry<Dim>> entries;
  int line_number = 0;
  for (std::string line; std::getline (stream, line);) {
    ++line_number;
    if (line_number == 1 && line.rfind ("\xEF\xBB\xBF", 0) == 0) // a UTF-8 byte order mark
      line.erase (0, 3);
    line = trim (line);
    if (line.empty () || line.front () == '#')
      continue;
    const std::string where = path + ":" + std::to_string (line_number);
    std::vector<std::string> fields = text::splitCsvFields (line);
    if (!header_seen) {
      for (auto& field : fields)
        field = toLower (field);
      std::string found;
      for (const auto& field : fields)
        found += (found.empty () ? "" : ",") + field;
      if (found != header)
        throw FormatError (where + ": expected the header '" + header + "', found '" + line + "'");
      header_seen = true;
      continue;
    }
    if (fields.size () != Dim + 1)
      throw FormatError (where + ": expected " + std::to_string (Dim + 1) + " fields (" + header + "), found " +
                         std::to_string (fields.size ()));
    Entry<Dim> entry{fields[0], Point<Dim>::Zero (), where};
    for (int axis = 0; axis < Dim; ++axis)
      entry.position[axis] = parseNumber (fields[axis + 1], where, std::string ("coordinate ") + kAxisNames[axis]);
    entries.push_back (entry);
  }
  if (!header_seen)
    throw FormatError (path + ": no header line '" + header + "'");
  return entries;
}

/** \brief Validates ids (non-empty, known, unique) and builds the named set; FormatError if there is none. */
template <int Dim>
NamedPoints<Dim>
collect (const std::vector<Entry<Dim>>& entries, const std::string& path, bool known_ids_only)
{
  NamedPoints<Dim> points;
  std::map<std::string, std::string> first_seen;
  for (const auto& entry : entries) {
    if (entry.id.empty ())
      throw FormatError (entry.where + ": empty landmark id");
    if (known_ids_only)
      requireKnownLandmarkId (entry.id, entry.where);
    const auto [it, inserted] = first_seen.emplace (entry.id, entry.where);
    if (!inserted)
      throw FormatError (entry.where + ": duplicate landmark '" + entry.id + "' (first at " + it->second + ")");
    if (entry.position.cwiseAbs ().maxCoeff () > kMaxLandmarkCoordinate)
      throw FormatError (entry.where + ": landmark '" + entry.id + "' has the coordinate " +
                         numberText (entry.position.cwiseAbs ().maxCoeff ()) +
                         ", beyond +-1e7 in any unit (a corrupt file?)");
    points[entry.id] = entry.position;
  }
  if (points.empty ())
    throw FormatError (path + ": no landmarks in the file");
  return points;
}

template <int Dim>
NamedPoints<Dim>
load (const std::string& path, bool known_ids_only = true)
{
  requireReadableFile (path, kMaxTextFileBytes);
  requireExtension (path, Dim == 3 ? ".pp .json .csv .pts" : ".json .csv .pts",
                    Dim == 3 ? "landmark" : "pixel landmark (PickedPoints files are 3D only)");
  const std::string ext = fileExtension (path);
  if (ext == ".json")
    return collect<Dim> (readJson<Dim> (path), path, known_ids_only);
  if (ext == ".pts")
    return collect<Dim> (readPts<Dim> (path), path, known_ids_only);
  if (ext == ".csv")
    return collect<Dim> (readCsv<Dim> (path), path, known_ids_only);
  if constexpr (Dim == 3)
    return collect<3> (readPickedPoints (path), path, known_ids_only);
  throw IoError (path + ": unsupported landmark format"); // unreachable: requireExtension checked it
}

std::string
joinIds (const std::vector<std::string>& ids)
{
  std::string list;
  for (const auto& id : ids)
    list += (list.empty () ? "" : ", ") + id;
  return list.empty () ? "none" : list;
}

template <int Dim>
void
requireExpectedIds (const NamedPoints<Dim>& points, const std::vector<std::string>& expected_ids,
                    const std::string& path)
{
  std::vector<std::string> missing;
  for (const auto& id : expected_ids)
    if (points.count (id) == 0)
      missing.push_back (id);
  std::vector<std::string> unexpected;
  for (const auto& named : points)
    if (std::find (expected_ids.begin (), expected_ids.end (), named.first) == expected_ids.end ())
      unexpected.push_back (named.first);
  if (missing.empty () && unexpected.empty ())
    return;
  throw FormatError (path + ": " + std::to_string (points.size ()) + " landmarks, but " +
                     std::to_string (expected_ids.size ()) + " expected; missing: " + joinIds (missing) +
                     "; unexpected: " + joinIds (unexpected));
}

// ---------------------------------------------------------------------------------------------------------------
// Writers: the set is validated and put into the vocabulary's order first.

template <int Dim>
std::vector<std::pair<std::string, Point<Dim>>>
orderedForWriting (const NamedPoints<Dim>& points, const std::string& path)
{
  if (points.empty ())
    throw InvalidInputError (path + ": no landmarks to write");
  for (const auto& [id, position] : points) {
    requireKnownLandmarkId (id, path);
    if (!position.allFinite ())
      throw InvalidInputError (path + ": landmark '" + id + "' has a non-finite position");
  }
  std::vector<std::pair<std::string, Point<Dim>>> ordered;
  for (const auto* ids : {&knownLandmarkIds (), &ibug68LandmarkIds ()})
    for (const auto& id : *ids)
      if (const auto it = points.find (id); it != points.end ())
        ordered.emplace_back (*it);
  return ordered;
}

std::string
pickedPointsText (const std::vector<std::pair<std::string, Point<3>>>& landmarks)
{
  tinyxml2::XMLDocument document;
  document.InsertEndChild (document.NewUnknown ("DOCTYPE PickedPoints"));
  auto* root = document.NewElement ("PickedPoints");
  document.InsertEndChild (root);
  for (const auto& [id, position] : landmarks) {
    auto* point = root->InsertNewChildElement ("point");
    point->SetAttribute ("name", id.c_str ());
    point->SetAttribute ("active", "1");
    for (int axis = 0; axis < 3; ++axis)
      point->SetAttribute (kAxisNames[axis], formatNumber (position[axis]).c_str ());
  }
  tinyxml2::XMLPrinter printer;
  document.Print (&printer);
  return printer.CStr ();
}

template <int Dim>
std::string
jsonText (const std::vector<std::pair<std::string, Point<Dim>>>& landmarks)
{
  nlohmann::json document;
  document["units"] = Dim == 3 ? "mm" : "px";
  document["landmarks"] = nlohmann::json::array ();
  for (const auto& [id, position] : landmarks)
    document["landmarks"].push_back (
        {{"id", id}, {"position", std::vector<double> (position.data (), position.data () + Dim)}});
  return document.dump (2) + "\n";
}

template <int Dim>
std::string
csvText (const std::vector<std::pair<std::string, Point<Dim>>>& landmarks)
{
  std::string text = "id," + axisList (Dim) + "\n";
  for (const auto& [id, position] : landmarks) {
    text += id;
    for (int axis = 0; axis < Dim; ++axis)
      text += "," + formatNumber (position[axis]);
    text += "\n";
  }
  return text;
}

template <int Dim>
void
save (const std::string& path, const NamedPoints<Dim>& points)
{
  requireExtension (path, Dim == 3 ? ".pp .json .csv" : ".json .csv",
                    Dim == 3 ? "landmark" : "pixel landmark (PickedPoints files are 3D only)");
  const auto ordered = orderedForWriting<Dim> (points, path);
  const std::string ext = fileExtension (path);
  if (ext == ".json")
    writeFileAtomically (path, jsonText<Dim> (ordered));
  else if (ext == ".csv")
    writeFileAtomically (path, csvText<Dim> (ordered));
  else if constexpr (Dim == 3)
    writeFileAtomically (path, pickedPointsText (ordered));
}

} // namespace

LandmarkPositions
loadLandmarks (const std::string& path)
{
  return load<3> (path);
}

LandmarkPositions
loadLandmarks (const std::string& path, const std::vector<std::string>& expected_ids)
{
  LandmarkPositions landmarks = load<3> (path);
  requireExpectedIds<3> (landmarks, expected_ids, path);
  return landmarks;
}

LandmarkPositions
loadNamedPoints (const std::string& path)
{
  return load<3> (path, false);
}

LandmarkPositions
parseScalismoLandmarks (const std::string& text, const std::string& source)
{
  const nlohmann::json document = parseJsonText (text, source);
  if (!document.is_array ())
    throw FormatError (source + ": expected a scalismo landmark array [{\"id\": ..., \"coordinates\": [...]}]");
  return collect<3> (readScalismoEntries (document, source), source, false);
}

LandmarkPixels
loadLandmarkPixels (const std::string& path)
{
  return load<2> (path);
}

LandmarkPixels
loadLandmarkPixels (const std::string& path, const std::vector<std::string>& expected_ids)
{
  LandmarkPixels pixels = load<2> (path);
  requireExpectedIds<2> (pixels, expected_ids, path);
  return pixels;
}

void
saveLandmarks (const std::string& path, const LandmarkPositions& landmarks)
{
  save<3> (path, landmarks);
}

nlohmann::json
landmarkPixelsJson (const LandmarkPixels& pixels, const std::string& path)
{
  return nlohmann::json::parse (jsonText<2> (orderedForWriting<2> (pixels, path)));
}

void
saveLandmarkPixels (const std::string& path, const LandmarkPixels& pixels)
{
  save<2> (path, pixels);
}

} // namespace morphreg

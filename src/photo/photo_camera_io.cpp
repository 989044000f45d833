// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/json_file.h>
#include <morphreg/photo/photo_camera_io.h>

#include <nlohmann/json.hpp>

#include <filesystem>

namespace morphreg
{
namespace
{
using nlohmann::json;

/** The \a rows x \a cols matrix \a key of \a camera; FormatError naming \a where otherwise. */
Eigen::MatrixXd
readMatrix (const json& camera, const std::string& key, int rows, int cols, const std::string& where)
{
  if (!camera.contains (key))
    throw FormatError (where + ": missing \"" + key + "\"");
  const json& value = camera.at (key);
  const std::string shape = std::to_string (rows) + " x " + std::to_string (cols);
  Eigen::MatrixXd matrix (rows, cols);
  const bool vector = cols == 1 && value.is_array () && value.size () == static_cast<size_t> (rows) &&
                      (value.empty () || value[0].is_number ());
  if (!vector && (!value.is_array () || value.size () != static_cast<size_t> (rows)))
    throw FormatError (where + ": \"" + key + "\" must be " + shape + " numbers, found " + value.dump ());
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < cols; ++c) {
      const json& entry = vector                                                                   ? value[r]
                          : value[r].is_array () && value[r].size () == static_cast<size_t> (cols) ? value[r][c]
                                                                                                   : json ();
      if (!entry.is_number ())
        throw FormatError (where + ": \"" + key + "\" must be " + shape + " numbers, found " + value.dump ());
      matrix (r, c) = entry.get<double> ();
    }
  return matrix;
}

/** The camera object of \a document for \a image: the document itself, or the entry of its "cameras" whose
 *  "image" is \a image's file name (or the only entry). */
const json&
cameraFor (const json& document, const std::string& image, const std::string& path)
{
  if (!document.is_object ())
    throw FormatError (path + ": expected a JSON object with K, R and t, P, or \"cameras\"");
  if (!document.contains ("cameras"))
    return document;
  const json& cameras = document.at ("cameras");
  if (!cameras.is_object () || cameras.empty ())
    throw FormatError (path + ": \"cameras\" must be a non-empty object of named cameras");
  const std::string name = std::filesystem::path (image).filename ().string ();
  for (const auto& [key, camera] : cameras.items ())
    if (camera.is_object () && camera.value ("image", std::string ()) == name)
      return camera;
  if (cameras.size () == 1)
    return cameras.begin ().value ();
  throw FormatError (path + ": none of its " + std::to_string (cameras.size ()) + " cameras is for the image \"" +
                     name + "\" (their \"image\" members name the photos)");
}

/** FormatError unless the camera's optional width and height are the photo's. */
void
requireImageSize (const json& camera, int width, int height, const std::string& where)
{
  for (const auto& [key, size] : {std::pair<const char*, int> ("width", width), {"height", height}})
    if (camera.contains (key) && !(camera.at (key).is_number () && camera.at (key).get<double> () == size))
      throw FormatError (where + ": the camera's " + key + " " + camera.at (key).dump () + " is not the photo's " +
                         std::to_string (size) + " px");
}

json
matrixJson (const Eigen::MatrixXd& matrix)
{
  json rows = json::array ();
  for (Eigen::Index r = 0; r < matrix.rows (); ++r) {
    json row = json::array ();
    for (Eigen::Index c = 0; c < matrix.cols (); ++c)
      row.push_back (matrix (r, c));
    rows.push_back (matrix.cols () == 1 ? row[0] : row);
  }
  return rows;
}
} // namespace

PhotoCamera
loadPhotoCamera (const std::string& path, const std::string& image, int width, int height)
{
  const json document = readJsonFile (path);
  const json& camera = cameraFor (document, image, path);
  const std::string where = path + " (camera of " + std::filesystem::path (image).filename ().string () + ")";
  requireImageSize (camera, width, height, where);
  if (camera.contains ("K") || !camera.contains ("P"))
    return PhotoCamera::perspective (readMatrix (camera, "K", 3, 3, where), readMatrix (camera, "R", 3, 3, where),
                                     readMatrix (camera, "t", 3, 1, where), where);
  return PhotoCamera::fromProjection (readMatrix (camera, "P", 3, 4, where), where);
}

json
photoCameraJson (const PhotoCamera& camera)
{
  return {{"projection", camera.isPerspective () ? "perspective" : "orthographic"},
          {"K", matrixJson (camera.intrinsics ())},
          {"R", matrixJson (camera.rotation ())},
          {"t", matrixJson (camera.translation ())}};
}
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/io/file_checks.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/photo/jpeg_exif.h>
#include <morphreg/photo/photo_camera_io.h>
#include <morphreg/photo/photo_view_io.h>

#include <limits>

namespace morphreg
{
namespace
{
using nlohmann::json;

/** \brief The value of \a key of \a document; FormatError naming \a path if absent. */
const json&
member (const json& document, const std::string& key, const std::string& path)
{
  if (!document.is_object () || !document.contains (key))
    throw FormatError (path + ": missing \"" + key + "\"");
  return document.at (key);
}

/** \brief "image": {"width": W, "height": H} as integers. */
std::pair<int, int>
readImageSize (const json& document, const std::string& path)
{
  const json& image = member (document, "image", path);
  int size[2];
  const char* keys[2] = {"width", "height"};
  for (int k = 0; k < 2; ++k) {
    const json& value = member (image, keys[k], path + ": image");
    // Compared as JSON numbers, so a count beyond int is reported instead of wrapping around in the conversion.
    if (!value.is_number_integer () || value > std::numeric_limits<int>::max () ||
        value < std::numeric_limits<int>::min ())
      throw FormatError (path + ": image." + keys[k] + " (" + value.dump () + ") is not an integer pixel count");
    size[k] = value.get<int> ();
  }
  return {size[0], size[1]};
}

/** \brief [x, y] as a pixel; FormatError naming \a where otherwise. */
Eigen::Vector2d
readPixel (const json& value, const std::string& where)
{
  if (!value.is_array () || value.size () != 2 || !value[0].is_number () || !value[1].is_number ())
    throw FormatError (where + ": expected [x, y] pixel coordinates, found " + value.dump ());
  return {value[0].get<double> (), value[1].get<double> ()};
}

void
requireView (const json& document, const std::string& view, const std::string& path)
{
  if (member (document, "view", path) != view)
    throw FormatError (path + ": \"view\" is " + document.at ("view").dump () + ", expected \"" + view + "\"");
}

json
imageSize (const PhotoNormalisation& normalisation)
{
  return {{"width", normalisation.width ()}, {"height", normalisation.height ()}};
}
} // namespace

ProfileView
loadProfileView (const std::string& path)
{
  const json document = readJsonFile (path);
  requireView (document, "profile", path);
  const auto [width, height] = readImageSize (document, path);
  const Eigen::Vector2d nose_tip = readPixel (member (document, "nose_tip", path), path + ": nose_tip");
  const json& points = member (document, "silhouette", path);
  if (!points.is_array ())
    throw FormatError (path + ": \"silhouette\" must be an array of [x, y] points");
  std::vector<Eigen::Vector2d> silhouette;
  for (size_t k = 0; k < points.size (); ++k)
    silhouette.push_back (readPixel (points[k], path + ": silhouette[" + std::to_string (k) + "]"));
  return ProfileView (width, height, std::move (silhouette), nose_tip, path);
}

FrontalView
loadFrontalView (const std::string& path)
{
  const json document = readJsonFile (path);
  requireView (document, "frontal", path);
  const auto [width, height] = readImageSize (document, path);
  return FrontalView (width, height, loadLandmarkPixels (path), path);
}

void
saveProfileView (const std::string& path, const ProfileView& view)
{
  json silhouette = json::array ();
  for (const Eigen::Vector2d& point : view.silhouette ())
    silhouette.push_back ({point.x (), point.y ()});
  const Eigen::Vector2d& nose = view.normalisation ().noseTip ();
  writeJsonFile (path, {{"view", "profile"},
                        {"image", imageSize (view.normalisation ())},
                        {"nose_tip", {nose.x (), nose.y ()}},
                        {"silhouette", silhouette}});
}

void
saveFrontalView (const std::string& path, const FrontalView& view)
{
  // The landmark file layout, written by the landmark writer, plus the view and the image size.
  json document = landmarkPixelsJson (view.landmarks (), path);
  document["view"] = "frontal";
  document["image"] = imageSize (view.normalisation ());
  writeJsonFile (path, document);
}

OutlineAnnotation
loadOutline (const std::string& path)
{
  const json document = readJsonFile (path);
  const json& points = member (document, "outline", path);
  if (!points.is_array ())
    throw FormatError (path + ": \"outline\" must be an array of [x, y] points");
  OutlineAnnotation outline;
  for (size_t k = 0; k < points.size (); ++k)
    outline.points.push_back (readPixel (points[k], path + ": outline[" + std::to_string (k) + "]"));
  if (document.contains ("hairline"))
    outline.hairline = readPixel (document.at ("hairline"), path + ": hairline");
  return outline;
}

void
saveOutline (const std::string& path, const OutlineAnnotation& outline)
{
  json points = json::array ();
  for (const Eigen::Vector2d& point : outline.points)
    points.push_back ({point.x (), point.y ()});
  json document = {{"outline", points}};
  if (outline.hairline)
    document["hairline"] = {outline.hairline->x (), outline.hairline->y ()};
  writeJsonFile (path, document);
}

LoadedPhotoView
loadPhotoView (const PhotoViewFiles& files)
{
  RgbImage image = loadRgbImage (files.image);
  if (files.landmarks.empty () && files.outline.empty ())
    throw InvalidInputError (files.image + ": the photo has neither landmarks nor an outline");
  const LandmarkPixels landmarks = files.landmarks.empty () ? LandmarkPixels () : loadLandmarkPixels (files.landmarks);
  for (const auto& [id, pixel] : landmarks)
    if ((pixel.array () < -0.1 * Eigen::Array2d (image.width, image.height)).any () ||
        (pixel.array () > 1.1 * Eigen::Array2d (image.width, image.height)).any ())
      throw InvalidInputError (files.landmarks + ": landmark '" + id + "' (" + std::to_string (pixel.x ()) + ", " +
                               std::to_string (pixel.y ()) + ") lies outside the " + std::to_string (image.width) +
                               " x " + std::to_string (image.height) + " px photo " + files.image);
  PhotoView view (image.width, image.height, landmarks, files.image);
  if (const std::string extension = fileExtension (files.image); extension == ".jpg" || extension == ".jpeg")
    if (const auto focal = jpegFocalLength35mm (files.image))
      view.setFocalLength35mm (*focal);
  if (!files.camera.empty ())
    view.setCamera (loadPhotoCamera (files.camera, files.image, image.width, image.height));
  if (!files.outline.empty ()) {
    const OutlineAnnotation outline = loadOutline (files.outline);
    view.setOutline (outline.points, outline.hairline);
  }
  return {std::move (view), std::move (image)};
}
} // namespace morphreg

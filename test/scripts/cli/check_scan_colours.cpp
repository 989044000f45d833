// SPDX-License-Identifier: BSD-3-Clause
// check_scan_colours FIT.ply JAMES_DIR: passes (exit 0) when the fitted mesh of the james capture carries the person's
// colours: at the cheeks, the nose tip and the chin (from the capture's 68 landmarks), the nearest fitted vertex has
// the colour the photo that sees it best has there (projected with the capture's recovered cameras), and is
// skin-coloured (red above blue), not the grey of an uncoloured mesh or a residual map.
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/rgb_image_io.h>

#include <nlohmann/json.hpp>
#include <pcl/conversions.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <fstream>
#include <iostream>

namespace
{
struct Photo
{
  Eigen::Matrix<double, 3, 4> projection;
  Eigen::Vector3d centre;
  morphreg::RgbImage image;
};

std::vector<Photo>
loadPhotos (const std::string& folder)
{
  std::ifstream in (folder + "/james_cameras.json");
  const nlohmann::json cameras = nlohmann::json::parse (in).at ("cameras");
  std::vector<Photo> photos;
  for (const auto& [side, camera] : cameras.items ()) {
    Photo photo;
    for (int r = 0; r < 3; ++r)
      for (int c = 0; c < 4; ++c)
        photo.projection (r, c) = camera.at ("P")[r][c];
    for (int k = 0; k < 3; ++k)
      photo.centre[k] = camera.at ("camera_center_mm")[k];
    photo.image = morphreg::loadRgbImage (folder + "/" + camera.at ("image").get<std::string> ());
    photos.push_back (std::move (photo));
  }
  return photos;
}

/** The mean colour of the 9 x 9 pixels around \a point's projection in the photo whose camera is nearest to it. */
Eigen::Vector3d
photoColour (const std::vector<Photo>& photos, const Eigen::Vector3d& point)
{
  const Photo* best = &photos[0];
  for (const Photo& photo : photos)
    if ((photo.centre - point).norm () < (best->centre - point).norm ())
      best = &photo;
  const Eigen::Vector3d pixel = best->projection * point.homogeneous ();
  const int u = static_cast<int> (pixel.x () / pixel.z ()), v = static_cast<int> (pixel.y () / pixel.z ());
  Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
  for (int dy = -4; dy <= 4; ++dy)
    for (int dx = -4; dx <= 4; ++dx)
      sum += best->image
                 .pixel (std::clamp (u + dx, 0, best->image.width - 1), std::clamp (v + dy, 0, best->image.height - 1))
                 .cast<double> ();
  return sum / 81.0;
}
} // namespace

int
main (int argc, char** argv)
{
  if (argc != 3) {
    std::cerr << "usage: check_scan_colours FIT.ply JAMES_DIR\n";
    return 2;
  }
  pcl::PointCloud<pcl::PointXYZRGB> fit;
  pcl::fromPCLPointCloud2 (morphreg::loadPolygonMesh (argv[1]).cloud, fit);
  const std::string folder = argv[2];
  const morphreg::LandmarkPositions landmarks = morphreg::loadLandmarks (folder + "/james_landmarks.json");
  const std::vector<Photo> photos = loadPhotos (folder);
  const auto at = [&] (int i) {
    return landmarks.at ("ibug68_" + std::string (i < 10 ? "0" : "") + std::to_string (i));
  };
  const std::vector<std::pair<std::string, Eigen::Vector3d>> points = {{"right cheek", 0.5 * (at (3) + at (31))},
                                                                       {"left cheek", 0.5 * (at (13) + at (35))},
                                                                       {"nose tip", at (30)},
                                                                       {"chin", at (8)}};
  int failures = 0;
  for (const auto& [name, point] : points) {
    std::size_t nearest = 0;
    for (std::size_t v = 0; v < fit.size (); ++v)
      if ((fit[v].getVector3fMap ().cast<double> () - point).norm () <
          (fit[nearest].getVector3fMap ().cast<double> () - point).norm ())
        nearest = v;
    const Eigen::Vector3d vertex = fit[nearest].getVector3fMap ().cast<double> ();
    const Eigen::Vector3d colour (fit[nearest].r, fit[nearest].g, fit[nearest].b), photo = photoColour (photos, vertex);
    const double distance = (vertex - point).norm ();
    const bool ok =
        distance < 30.0 && (colour - photo).cwiseAbs ().maxCoeff () < 45.0 && colour.x () > colour.z () + 15.0;
    std::cout << name << ": fitted vertex " << nearest << " (" << distance << " mm from the landmarks' point) rgb "
              << colour.transpose () << ", the photo there " << photo.transpose ().array ().round ()
              << (ok ? "" : "  <- NOT the person's colour") << "\n";
    failures += ok ? 0 : 1;
  }
  return failures == 0 ? 0 : 1;
}

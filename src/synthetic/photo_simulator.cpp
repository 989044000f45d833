// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/synthetic/photo_simulator.h>

#include <Eigen/LU>

#include <cmath>
#include <random>

namespace morphreg
{
namespace synthetic
{
namespace
{
int
requireVertex (int vertex, const Eigen::Matrix3Xd& head, const std::string& what)
{
  if (vertex < 0 || vertex >= head.cols ())
    throw InvalidInputError ("PhotoSimulator: " + what + " vertex " + std::to_string (vertex) +
                             " is out of range (the head has " + std::to_string (head.cols ()) + " vertices)");
  return vertex;
}
} // namespace

PhotoSimulator::PhotoSimulator (const Parameters& parameters) : parameters_ (parameters)
{
  const Parameters& p = parameters;
  if (p.width <= 0 || p.height <= 0)
    throw InvalidInputError ("PhotoSimulator: width and height must be positive");
  if (!(p.pixels_per_mm > 0.0) || !std::isfinite (p.pixels_per_mm))
    throw InvalidInputError ("PhotoSimulator: pixels_per_mm must be finite and positive");
  if (!(p.landmark_noise >= 0.0) || !(p.silhouette_noise >= 0.0))
    throw InvalidInputError ("PhotoSimulator: the noise levels must be >= 0");
  if (p.silhouette_subdivisions < 0)
    throw InvalidInputError ("PhotoSimulator: silhouette_subdivisions must be >= 0");
  if (!p.rotation.allFinite () || !(p.rotation.transpose () * p.rotation).isIdentity (1e-9) ||
      p.rotation.determinant () < 0.0)
    throw InvalidInputError ("PhotoSimulator: rotation must be a rotation matrix");
  if (!p.frontal_nose.allFinite () || !p.profile_nose.allFinite ())
    throw InvalidInputError ("PhotoSimulator: the nose positions must be finite");
}

SimulatedPhotos
PhotoSimulator::photograph (const Eigen::Matrix3Xd& head, const LandmarkVertices& frontal_landmarks,
                            const std::vector<int>& profile_line, std::uint64_t seed) const
{
  const Parameters& p = parameters_;
  const auto nose = frontal_landmarks.find ("nose_tip");
  if (nose == frontal_landmarks.end ())
    throw InvalidInputError ("PhotoSimulator: the frontal landmarks have no nose_tip");
  if (profile_line.size () < 2)
    throw InvalidInputError ("PhotoSimulator: the profile line needs at least 2 vertices");
  const Eigen::Vector3d nose_tip = head.col (requireVertex (nose->second, head, "nose_tip"));
  std::mt19937_64 rng (seed);
  std::normal_distribution<double> landmark_noise (0.0, p.landmark_noise);
  std::normal_distribution<double> silhouette_noise (0.0, p.silhouette_noise);
  const auto jitter = [&rng] (std::normal_distribution<double>& noise) {
    return Eigen::Vector2d (noise (rng), noise (rng));
  };
  // Pixel of a posed head point relative to the nose tip: image x = +X (front) or +Z (side), image y = -Y.
  const auto pixel = [&] (const Eigen::Vector3d& point, int axis, const Eigen::Vector2d& nose_pixel) {
    const Eigen::Vector3d d = p.rotation * (point - nose_tip) * p.pixels_per_mm;
    return Eigen::Vector2d (nose_pixel.x () + d[axis], nose_pixel.y () - d.y ());
  };

  LandmarkPixels marked;
  for (const auto& landmark : frontal_landmarks)
    marked[landmark.first] =
        pixel (head.col (requireVertex (landmark.second, head, landmark.first)), 0, p.frontal_nose) +
        jitter (landmark_noise);
  std::vector<Eigen::Vector2d> silhouette;
  const int steps = p.silhouette_subdivisions + 1;
  for (size_t k = 0; k < profile_line.size (); ++k) {
    const Eigen::Vector2d a =
        pixel (head.col (requireVertex (profile_line[k], head, "profile line")), 2, p.profile_nose);
    if (k + 1 == profile_line.size ()) {
      silhouette.push_back (a + jitter (silhouette_noise));
      break;
    }
    const Eigen::Vector2d b =
        pixel (head.col (requireVertex (profile_line[k + 1], head, "profile line")), 2, p.profile_nose);
    for (int s = 0; s < steps; ++s)
      silhouette.push_back (a + (b - a) * (static_cast<double> (s) / steps) + jitter (silhouette_noise));
  }
  const Eigen::Vector2d profile_nose = p.profile_nose + jitter (landmark_noise);

  const double scale = p.pixels_per_mm / static_cast<double> (std::max (p.width, p.height));
  return {ProfileView (p.width, p.height, std::move (silhouette), profile_nose, "PhotoSimulator"),
          FrontalView (p.width, p.height, std::move (marked), "PhotoSimulator"), scale, p.rotation,
          -scale * (p.rotation * nose_tip)};
}
} // namespace synthetic
} // namespace morphreg

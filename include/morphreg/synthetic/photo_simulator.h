// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file photo_simulator.h
 *  \brief Simulated, annotated orthographic photos of a head (a profile silhouette and frontal landmarks), with the
 *  ground truth a two-view fit needs.
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/photo/frontal_view.h>
#include <morphreg/photo/profile_view.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace morphreg
{
namespace synthetic
{
/** \brief Two annotated photos and the similarity X = s R v + t that maps the head (mm) into their normalised
 *  frame before the annotation noise (frontal image = (X, Y), profile image = (Z, Y)).
 */
struct SimulatedPhotos
{
  ProfileView profile;         ///< the annotated profile photo
  FrontalView frontal;         ///< the annotated frontal photo
  double scale;                ///< s: normalised units per head millimetre
  Eigen::Matrix3d rotation;    ///< R: the head's pose
  Eigen::Vector3d translation; ///< t, normalised units
};

/** \brief Photographs a head (+Y up, +Z out of the face) orthographically from the front (along -Z) and from its
 *  left side (along -X: the face looks to the right of the image), after rotating it about its origin, and
 *  annotates them as a person would: the frontal landmarks with Gaussian pixel noise, the silhouette as the
 *  projected profile line, subdivided and with Gaussian noise, and the nose tip in both.
 *
 *  \code
 *  morphreg::synthetic::PhotoSimulator camera;
 *  auto photos = camera.photograph (head.vertices, frontal_landmarks, generator.profileLine (), 7);
 *  \endcode
 */
class PhotoSimulator
{
public:
  /** \brief Camera and annotation settings. */
  struct Parameters
  {
    int width = 1000;                                        ///< image width (px), both photos
    int height = 1200;                                       ///< image height (px), both photos
    double pixels_per_mm = 3.5;                              ///< the same in both photos
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity (); ///< the head's pose (about its origin)
    Eigen::Vector2d frontal_nose{480.0, 620.0};              ///< where the nose tip lands in the frontal photo (px)
    Eigen::Vector2d profile_nose{650.0, 600.0};              ///< and in the profile photo
    double landmark_noise = 1.0;     ///< px, standard deviation of each marked coordinate (nose tips too)
    double silhouette_noise = 0.5;   ///< px, of each silhouette point
    int silhouette_subdivisions = 3; ///< points inserted in each segment of the projected profile line
  };

  /** \brief A simulator with the default Parameters. */
  PhotoSimulator () = default;

  /** \brief Throws InvalidInputError naming the setting if \a parameters are out of range.
   *  \param[in] parameters the camera and annotation settings
   */
  explicit PhotoSimulator (const Parameters& parameters);

  /** \brief The simulator's settings.
   *  \return the parameters
   */
  const Parameters&
  parameters () const
  {
    return parameters_;
  }

  /** \brief Photographs \a head (3 x N, mm) with noise drawn from \a seed. \a frontal_landmarks (which must
   *  include nose_tip) and \a profile_line index \a head's columns. Throws InvalidInputError for out-of-range
   *  indices or a profile line of fewer than 2 vertices.
   *  \param[in] head the head's vertices (3 x N, mm)
   *  \param[in] frontal_landmarks the landmarks to mark on the frontal photo
   *  \param[in] profile_line the vertices whose projection is the silhouette, in order
   *  \param[in] seed the seed of the annotation noise
   *  \return the two annotated photos and the true similarity
   */

  SimulatedPhotos
  photograph (const Eigen::Matrix3Xd& head, const LandmarkVertices& frontal_landmarks,
              const std::vector<int>& profile_line, std::uint64_t seed) const;

private:
  Parameters parameters_;
};
} // namespace synthetic
} // namespace morphreg

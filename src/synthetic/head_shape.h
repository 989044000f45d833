// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Internal: the head's surface as a function of direction from the head centre, for one set of parameters.
#include <morphreg/synthetic/head_parameters.h>

#include <Eigen/Core>

#include <vector>

namespace morphreg
{
namespace synthetic
{
/** \brief A bump on the head surface: a radial displacement centred on a direction, with widths in mm.
 *  `flatness` 1 gives a Gaussian, 2 a plateau with steep sides (ears, lips).
 */
struct SurfaceBump
{
  Eigen::Vector3d anchor; ///< a point on the mean head whose direction centres the bump
  double amplitude;       ///< mm, positive outwards
  double width;           ///< horizontal standard width, mm
  double height_up;       ///< vertical width above the centre, mm
  double height_down;     ///< vertical width below the centre, mm
  double flatness;        ///< exponent of the profile
};

/** \brief A smooth local deformation after the bumps: scale about `centre` (per axis) and shift, weighted by a
 *  Gaussian of radius `radius` around `centre`. It changes feature sizes without moving feature vertices.
 */
struct LocalWarp
{
  Eigen::Vector3d centre;
  Eigen::Vector3d scale;
  Eigen::Vector3d shift;
  double radius;
};

/** \brief The surface of one head. Base volumes (cranium, face, jaw, neck) are joined by a smooth maximum of
 *  their ray exit distances, so the surface is a radial graph over the sphere: closed and free of folds.
 */
class HeadShape
{
public:
  explicit HeadShape (const HeadParameters& parameters);

  /** \brief The head surface point along unit direction \a direction (mm). */
  Eigen::Vector3d
  surfacePoint (const Eigen::Vector3d& direction) const;

  /** \brief y of the plane that cuts the neck. */
  double
  neckCutHeight () const
  {
    return neck_bottom_;
  }

private:
  double
  baseRadius (const Eigen::Vector3d& direction) const;

  double
  bumpDisplacement (const Eigen::Vector3d& direction) const;

  Eigen::Vector3d
  applyWarps (const Eigen::Vector3d& point) const;

  struct Ellipsoid
  {
    Eigen::Vector3d centre;
    Eigen::Vector3d axes;
  };

  static double
  exitDistance (const Ellipsoid& e, const Eigen::Vector3d& direction);

  double
  neckExitDistance (const Eigen::Vector3d& direction) const;

  Ellipsoid cranium_, face_, jaw_;
  Eigen::Vector2d neck_axes_;
  double neck_centre_z_;
  double neck_bottom_;
  std::vector<SurfaceBump> bumps_;
  std::vector<LocalWarp> warps_;
};

/** \brief Mirror of a right-side anchor to the subject's left (x -> -x). */
inline Eigen::Vector3d
mirrored (const Eigen::Vector3d& p)
{
  return Eigen::Vector3d (-p.x (), p.y (), p.z ());
}

} // namespace synthetic
} // namespace morphreg

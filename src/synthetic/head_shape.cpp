// SPDX-License-Identifier: BSD-3-Clause
#include "head_shape.h"

#include "head_anatomy.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>

namespace morphreg
{
namespace synthetic
{
namespace
{
constexpr double kTopOfHead = 128.0;     ///< y of the vertex; the chin hangs head_height below it
constexpr double kBlendFace = 12.0;      ///< mm over which the face merges into the cranium
constexpr double kBlendJaw = 24.0;       ///< ... the jaw into face and cranium
constexpr double kBlendNeck = 30.0;      ///< ... the neck into the head
constexpr double kNeckCutRounding = 6.0; ///< mm of rounding where the neck's cut meets its side

/** Polynomial smooth maximum: equals max(a, b) when they differ by more than k, rounds the crease otherwise. */
double
smoothMax (double a, double b, double k)
{
  const double h = std::max (k - std::abs (a - b), 0.0) / k;
  return std::max (a, b) + h * h * k / 4.0;
}

/** Adds a bump on the right side and its mirror image on the left. */
void
addMirroredBump (std::vector<SurfaceBump>& bumps, SurfaceBump bump)
{
  bumps.push_back (bump);
  bump.anchor = mirrored (bump.anchor);
  bumps.push_back (bump);
}

/** Horizontal and vertical unit vectors of the tangent plane at direction u (u must not be vertical). */
void
tangentFrame (const Eigen::Vector3d& u, Eigen::Vector3d& horizontal, Eigen::Vector3d& vertical)
{
  horizontal = Eigen::Vector3d::UnitY ().cross (u).normalized ();
  vertical = u.cross (horizontal);
}

double
bumpProfile (const SurfaceBump& bump, const Eigen::Vector3d& direction)
{
  const Eigen::Vector3d u = bump.anchor.normalized ();
  if (direction.dot (u) <= 0.0)
    return 0.0;
  Eigen::Vector3d horizontal, vertical;
  tangentFrame (u, horizontal, vertical);
  const double reach = bump.anchor.norm (); // angle (rad) * reach = mm on the surface
  const double a = direction.dot (horizontal) * reach / bump.width;
  const double b_mm = direction.dot (vertical) * reach;
  const double b = b_mm / (b_mm > 0.0 ? bump.height_up : bump.height_down);
  const double q2 = a * a + b * b;
  return std::exp (-0.5 * std::pow (q2, bump.flatness));
}
} // namespace

HeadShape::HeadShape (const HeadParameters& p)
{
  using namespace anatomy;
  const double menton = kTopOfHead - p.head_height;
  const double cranium_centre_y = 30.0;
  cranium_ = {Eigen::Vector3d (0.0, cranium_centre_y, 88.0 - p.head_length / 2.0),
              Eigen::Vector3d (p.head_breadth / 2.0, kTopOfHead - cranium_centre_y, p.head_length / 2.0)};
  face_ = {Eigen::Vector3d (0.0, -10.0, 18.0), Eigen::Vector3d (p.face_width / 2.0, 55.0, 72.0)};
  const double jaw_half_height = 46.0;
  jaw_ = {Eigen::Vector3d (0.0, menton + jaw_half_height, 22.0),
          Eigen::Vector3d (p.jaw_width / 2.0, jaw_half_height, 66.0)};
  // Elliptic neck section 1.1 : 0.9 whose perimeter (Ramanujan-free RMS approximation) is the girth.
  const double neck_radius = p.neck_girth / (2.0 * M_PI * std::sqrt ((1.1 * 1.1 + 0.9 * 0.9) / 2.0));
  neck_axes_ = Eigen::Vector2d (1.1 * neck_radius, 0.9 * neck_radius);
  neck_centre_z_ = -12.0;
  neck_bottom_ = menton - p.neck_length;

  // Features: {anchor, amplitude, width, height up, height down, flatness}
  addMirroredBump (bumps_, {kRightEye, -p.eye_depth, 15.0, 10.0, 10.0, 1.0});
  addMirroredBump (bumps_, {kRightEye, 0.45 * p.eye_depth, 9.0, 6.0, 6.0, 1.0});
  addMirroredBump (bumps_, {kRightBrow, p.brow_ridge, 17.0, 6.0, 6.0, 1.0});
  addMirroredBump (bumps_, {kRightCheek, p.cheek_fullness, 16.0, 16.0, 16.0, 1.0});
  addMirroredBump (bumps_, {kRightNoseWing, 5.0, 6.0, 6.0, 6.0, 1.0});
  addMirroredBump (bumps_, {kRightNostril, -3.5, 3.0, 2.5, 2.5, 1.0});
  addMirroredBump (bumps_, {kRightEar, p.ear_protrusion, 15.0, 30.0, 30.0, 2.0});
  addMirroredBump (bumps_, {kRightConcha, -0.55 * p.ear_protrusion, 7.0, 9.0, 9.0, 1.0});
  bumps_.push_back ({kNoseTip, 0.55 * p.nose_projection, 9.0, 9.0, 7.0, 1.0});
  bumps_.push_back ({kNoseRidge, 0.6 * p.nose_projection, 6.5, 20.0, 14.0, 1.0});
  bumps_.push_back ({kNasion, -3.0, 8.0, 6.0, 6.0, 1.0});
  bumps_.push_back ({kUpperLip, 0.9 * p.lip_thickness, 17.0, 5.5, 5.5, 2.0});
  bumps_.push_back ({kLowerLip, p.lip_thickness, 15.0, 6.0, 6.0, 2.0});
  bumps_.push_back ({kMouth, -3.5, 22.0, 2.2, 2.2, 2.0});
  bumps_.push_back ({kChin, p.chin_projection, 15.0, 11.0, 11.0, 1.0});

  // Sizes of features that must not slide over the vertices: {centre, scale, shift, radius}
  const HeadParameters mean;
  const Eigen::Vector3d none = Eigen::Vector3d::Zero (), unit = Eigen::Vector3d::Ones ();
  warps_.push_back ({kNoseCentre,
                     Eigen::Vector3d (p.nose_width / mean.nose_width, p.nose_length / mean.nose_length, 1.0), none,
                     24.0});
  warps_.push_back ({kMouth, Eigen::Vector3d (p.mouth_width / mean.mouth_width, 1.0, 1.0), none, 22.0});
  const double eye_shift = (p.eye_separation - mean.eye_separation) / 2.0;
  warps_.push_back ({kRightEye, unit, Eigen::Vector3d (-eye_shift, 0.0, 0.0), 20.0});
  warps_.push_back ({mirrored (kRightEye), unit, Eigen::Vector3d (eye_shift, 0.0, 0.0), 20.0});
  const double ear_scale = p.ear_length / mean.ear_length;
  for (const Eigen::Vector3d& ear : {kRightEar, mirrored (kRightEar)})
    warps_.push_back (
        {ear, Eigen::Vector3d (1.0, ear_scale, ear_scale), Eigen::Vector3d (0.0, p.ear_height, 0.0), 36.0});
}

double
HeadShape::exitDistance (const Ellipsoid& e, const Eigen::Vector3d& d)
{
  const Eigen::Vector3d da = d.cwiseQuotient (e.axes), ca = e.centre.cwiseQuotient (e.axes);
  const double a = da.squaredNorm (), b = da.dot (ca), c = ca.squaredNorm () - 1.0;
  const double discriminant = b * b - a * c;
  if (discriminant < 0.0)
    return 0.0;
  return std::max ((b + std::sqrt (discriminant)) / a, 0.0);
}

double
HeadShape::neckExitDistance (const Eigen::Vector3d& d) const
{
  // Upward rays see the neck's side fade out smoothly by 35 degrees of elevation: no crease where it ends.
  const double fade = std::clamp (1.0 - d.y () / 0.57, 0.0, 1.0);
  if (fade == 0.0)
    return 0.0;
  const double dx = d.x () / neck_axes_.x (), dz = d.z () / neck_axes_.y (), cz = neck_centre_z_ / neck_axes_.y ();
  const double a = dx * dx + dz * dz, b = dz * cz, c = cz * cz - 1.0;
  const double side = a > 1e-15 ? (b + std::sqrt (b * b - a * c)) / a : std::numeric_limits<double>::infinity ();
  if (d.y () >= 0.0)
    return side * fade * fade * (3.0 - 2.0 * fade);
  const double cut = neck_bottom_ / d.y ();
  return -smoothMax (-side, -cut, kNeckCutRounding);
}

double
HeadShape::baseRadius (const Eigen::Vector3d& d) const
{
  double r = smoothMax (exitDistance (cranium_, d), exitDistance (face_, d), kBlendFace);
  r = smoothMax (r, exitDistance (jaw_, d), kBlendJaw);
  return smoothMax (r, neckExitDistance (d), kBlendNeck);
}

double
HeadShape::bumpDisplacement (const Eigen::Vector3d& d) const
{
  double displacement = 0.0;
  for (const auto& bump : bumps_)
    displacement += bump.amplitude * bumpProfile (bump, d);
  return displacement;
}

Eigen::Vector3d
HeadShape::applyWarps (const Eigen::Vector3d& point) const
{
  Eigen::Vector3d result = point;
  for (const auto& warp : warps_) {
    const Eigen::Vector3d offset = point - warp.centre;
    const double weight = std::exp (-offset.squaredNorm () / (2.0 * warp.radius * warp.radius));
    result += weight * ((warp.scale - Eigen::Vector3d::Ones ()).cwiseProduct (offset) + warp.shift);
  }
  return result;
}

Eigen::Vector3d
HeadShape::surfacePoint (const Eigen::Vector3d& direction) const
{
  const double radius = baseRadius (direction) + bumpDisplacement (direction);
  return applyWarps (std::max (radius, 1.0) * direction);
}

} // namespace synthetic
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/synthetic/head_generator.h>

#include "cube_sphere.h"
#include "head_anatomy.h"
#include "head_shape.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace morphreg
{
namespace synthetic
{
namespace
{
constexpr double kFrontDensity = 0.35; ///< how strongly the sphere's vertices crowd towards the face

/** Right-side (subject's right, -X) landmark positions on the mean head; the left side mirrors them. */
const std::vector<std::pair<std::string, Eigen::Vector3d>>&
sidedLandmarkAnchors ()
{
  static const std::vector<std::pair<std::string, Eigen::Vector3d>> anchors = {
      {"eyebrow", {-30.0, 50.0, 87.0}},       {"eye_outer", {-45.5, 33.0, 73.0}},
      {"eye_inner", {-17.5, 33.0, 82.0}},     {"nose_wing", {-16.0, -8.0, 88.0}},
      {"mouth_corner", {-25.0, -42.0, 88.0}}, {"philtrum", {-5.0, -30.0, 95.0}},
      {"lower_lip", {-10.0, -51.0, 92.0}},    {"ear_attachment_top", {-70.0, 40.0, 0.0}},
      {"ear_top", {-78.0, 40.0, -9.0}},       {"ear_middle", {-80.0, 14.0, -12.0}},
      {"earlobe", {-76.0, -15.0, -6.0}},      {"earlobe_attachment", {-70.0, -15.0, 2.0}},
      {"tragus", {-72.0, 9.0, 9.0}},          {"jaw", {-60.0, -40.0, 40.0}},
      {"jaw_middle", {-48.0, -70.0, 55.0}},   {"chin", {-20.0, -92.0, 72.0}},
      {"neck_top", {-55.0, -105.0, 0.0}},     {"neck_contour", {-60.0, -150.0, -10.0}},
      {"head_contour", {-75.0, 40.0, 0.0}}};
  return anchors;
}

const std::vector<std::pair<std::string, Eigen::Vector3d>>&
midlineLandmarkAnchors ()
{
  static const std::vector<std::pair<std::string, Eigen::Vector3d>> anchors = {
      {"nose_tip", anatomy::kNoseTip},   {"upper_lip_center", anatomy::kUpperLip},
      {"mouth_center", anatomy::kMouth}, {"lower_lip_center", anatomy::kLowerLip},
      {"nasion", anatomy::kNasion},      {"chin", {0.0, -100.0, 62.0}},
      {"forehead", {0.0, 85.0, 80.0}}};
  return anchors;
}

/** The vertex whose direction is closest to \a anchor's direction. */
int
closestDirection (const Eigen::Matrix3Xd& directions, const Eigen::Vector3d& anchor)
{
  Eigen::Index best;
  (directions.transpose () * anchor.normalized ()).maxCoeff (&best);
  return static_cast<int> (best);
}

bool
insideEllipse (double du, double dv, double ru, double rv)
{
  return (du / ru) * (du / ru) + (dv / rv) * (dv / rv) < 1.0;
}

/** Region of a point of the mean head, by anatomical boxes around the features (first match wins). */
HeadRegion
regionOf (const Eigen::Vector3d& p)
{
  using namespace anatomy;
  const double ax = std::abs (p.x ());
  if (ax > 60.0 && insideEllipse (p.y () - kRightEar.y (), p.z () - kRightEar.z (), 40.0, 24.0))
    return HeadRegion::ears;
  if (p.z () < 30.0)
    return HeadRegion::skull_neck;
  if (insideEllipse (ax + kRightEye.x (), p.y () - kRightEye.y (), 20.0, 13.0))
    return HeadRegion::eyes;
  if (insideEllipse (p.x (), p.y () - 10.0, 21.0, 29.0))
    return HeadRegion::nose;
  if (insideEllipse (p.x (), p.y () - kMouth.y (), 32.0, 15.0))
    return HeadRegion::mouth;
  if (insideEllipse (p.x (), p.y () - kChin.y (), 30.0, 19.0))
    return HeadRegion::chin;
  if (insideEllipse (ax + kRightCheek.x (), p.y () - kRightCheek.y (), 22.0, 26.0))
    return HeadRegion::cheeks;
  return HeadRegion::skull_neck;
}
} // namespace

std::string
headRegionName (HeadRegion region)
{
  static const char* names[kNumHeadRegions] = {"eyes", "nose", "mouth", "ears", "chin", "cheeks", "skull_neck"};
  return names[static_cast<int> (region)];
}

HeadGenerator::HeadGenerator (int resolution)
{
  if (resolution < 20 || resolution > 44 || resolution % 2 != 0)
    throw InvalidInputError ("HeadGenerator: resolution must be an even number in [20, 44]");
  const TriangleMesh sphere = makeCubeSphere (resolution, kFrontDensity);
  directions_ = sphere.vertices;
  triangles_ = sphere.triangles;
  const HeadParameters mean;
  const TriangleMesh mean_head = generate (mean);
  placeLandmarks ();
  traceProfileLine (mean_head, HeadShape (mean).neckCutHeight ());
  labelRegions (mean_head);
}

TriangleMesh
HeadGenerator::generate (const HeadParameters& parameters) const
{
  parameters.validate ();
  const HeadShape shape (parameters);
  TriangleMesh mesh;
  mesh.triangles = triangles_;
  mesh.vertices.resize (3, directions_.cols ());
#pragma omp parallel for schedule(static)
  for (Eigen::Index i = 0; i < directions_.cols (); ++i)
    mesh.vertices.col (i) = shape.surfacePoint (directions_.col (i));
  return mesh;
}

SyntheticHead
HeadGenerator::sample (std::uint64_t seed) const
{
  std::mt19937_64 rng (seed);
  SyntheticHead head;
  head.parameters = HeadParameters::sample (rng);
  head.mesh = generate (head.parameters);
  return head;
}

std::vector<SyntheticHead>
HeadGenerator::population (int count, std::uint64_t seed) const
{
  if (count < 0)
    throw InvalidInputError ("HeadGenerator::population: count must not be negative");
  std::vector<SyntheticHead> heads;
  heads.reserve (count);
  for (int i = 0; i < count; ++i)
    heads.push_back (sample (seed + static_cast<std::uint64_t> (i)));
  return heads;
}

RegionLabels
HeadGenerator::regions () const
{
  RegionLabels regions;
  for (int r = 0; r < kNumHeadRegions; ++r)
    regions.names.push_back (headRegionName (static_cast<HeadRegion> (r)));
  for (const HeadRegion label : region_labels_)
    regions.labels.push_back (static_cast<int> (label));
  return regions;
}

void
HeadGenerator::placeLandmarks ()
{
  for (const auto& [name, anchor] : sidedLandmarkAnchors ()) {
    landmarks_["right_" + name] = closestDirection (directions_, anchor);
    landmarks_["left_" + name] = closestDirection (directions_, mirrored (anchor));
  }
  for (const auto& [name, anchor] : midlineLandmarkAnchors ())
    landmarks_[name] = closestDirection (directions_, anchor);
  for (const auto& entry : landmarks_)
    requireKnownLandmarkId (entry.first, "HeadGenerator");
}

void
HeadGenerator::traceProfileLine (const TriangleMesh& mean_head, double neck_cut)
{
  std::vector<std::pair<double, int>> by_angle;
  for (Eigen::Index i = 0; i < directions_.cols (); ++i) {
    const Eigen::Vector3d p = mean_head.vertices.col (i);
    if (directions_ (0, i) != 0.0 || p.y () < neck_cut + 0.5)
      continue; // off the mid-sagittal plane, or on the flat cut under the neck
    // Angle measured from straight down, through the face (+Z) and over the top to the back.
    const double angle = std::atan2 (p.z (), -p.y ());
    by_angle.emplace_back (angle < 0.0 ? angle + 2.0 * M_PI : angle, static_cast<int> (i));
  }
  std::sort (by_angle.begin (), by_angle.end ());
  for (const auto& entry : by_angle)
    profile_line_.push_back (entry.second);
}

void
HeadGenerator::labelRegions (const TriangleMesh& mean_head)
{
  region_labels_.resize (directions_.cols ());
  for (Eigen::Index i = 0; i < directions_.cols (); ++i)
    region_labels_[i] = regionOf (mean_head.vertices.col (i));
}

} // namespace synthetic
} // namespace morphreg

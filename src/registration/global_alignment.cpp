// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/common/order_statistics.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/mesh/surface_sampling.h>
#include <morphreg/registration/global_alignment.h>

#include "distance_field.h"
#include "sensor_footprint.h"
#include "similarity_refinement.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numeric>
#include <sstream>
#include <unordered_map>

namespace morphreg
{
namespace
{
using detail::DistanceField;
using detail::Grid;
using detail::gridOver;
using detail::PointTree;

/** Points with unit normals (sign arbitrary) and the surface area each stands for (relative). */
struct OrientedPoints
{
  Eigen::Matrix3Xd points, normals;
  Eigen::VectorXd areas;
};

/** A sphere the Hough vote found, with its (smoothed) votes. */
struct Sphere
{
  Eigen::Vector3d centre;
  double radius;
  double votes;
};

void
requireSettings (const GlobalAlignmentSettings& s)
{
  if (!(s.voxel_ratio > 0.0) || !(s.min_radius_ratio > 0.0) || !(s.max_radius_ratio > s.min_radius_ratio) ||
      s.centre_candidates < 1 || s.rotation_directions < 1 || s.rotation_twists < 1 || s.score_samples < 10 ||
      s.rotations_per_anchor < 1 || s.refined_poses < 1 || s.refine_iterations < 0 || s.screen_iterations < 0 ||
      !(s.inlier_fraction > 0.0) || !(s.inlier_fraction <= 1.0) || !(s.truncation_ratio > 0.0) ||
      !std::isfinite (s.max_radius_ratio) || !std::isfinite (s.voxel_ratio) || !std::isfinite (s.truncation_ratio))
    throw InvalidInputError ("alignHeadGlobally: the settings need positive, finite ratios with min_radius_ratio < "
                             "max_radius_ratio, at least one candidate, direction, twist and refined pose, "
                             "score_samples >= 10, iterations >= 0 and 0 < inlier_fraction <= 1");
}

/** Area-uniform samples of \a mesh (about \a count) with the normals of their triangles. */
OrientedPoints
surfaceSamples (const TriangleMesh& mesh, int count, std::uint64_t seed)
{
  const double area = triangleAreas (mesh).sum ();
  const SurfaceSamples samples = sampleSurfaceUniformly (mesh, area / count, seed);
  const Eigen::Matrix3Xd face_normals = faceNormals (mesh);
  OrientedPoints result{samples.points, Eigen::Matrix3Xd (3, samples.points.cols ()),
                        Eigen::VectorXd::Ones (samples.points.cols ())};
  for (Eigen::Index i = 0; i < samples.points.cols (); ++i)
    result.normals.col (i) = face_normals.col (samples.triangles[static_cast<size_t> (i)]);
  return result;
}

/** One point per occupied voxel of edge \a voxel: the mean of its points, with the mean of their normals (each
 *  flipped to agree with the voxel's first; NaN where \a normals has none). */
OrientedPoints
thinToVoxels (const Eigen::Matrix3Xd& points, const Eigen::Matrix3Xd& normals, double voxel)
{
  struct Cell
  {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero (), normal = Eigen::Vector3d::Zero ();
    int count = 0;
  };
  std::unordered_map<std::uint64_t, Cell> cells;
  const Eigen::Vector3d origin = points.rowwise ().minCoeff ();
  for (Eigen::Index i = 0; i < points.cols (); ++i) {
    const Eigen::Array3d index = ((points.col (i) - origin) / voxel).array ().floor ();
    const std::uint64_t key = (static_cast<std::uint64_t> (index[0]) << 42) |
                              (static_cast<std::uint64_t> (index[1]) << 21) | static_cast<std::uint64_t> (index[2]);
    Cell& cell = cells[key];
    cell.sum += points.col (i);
    ++cell.count;
    if (normals.cols () == points.cols () && normals.col (i).allFinite ()) {
      const Eigen::Vector3d n = normals.col (i);
      cell.normal += cell.normal.dot (n) < 0.0 ? Eigen::Vector3d (-n) : n;
    }
  }
  OrientedPoints thinned{Eigen::Matrix3Xd (3, cells.size ()), Eigen::Matrix3Xd (3, cells.size ()),
                         Eigen::VectorXd::Ones (static_cast<Eigen::Index> (cells.size ()))};
  Eigen::Index k = 0;
  for (const auto& entry : cells) {
    thinned.points.col (k) = entry.second.sum / entry.second.count;
    const double length = entry.second.normal.norm ();
    thinned.normals.col (k++) =
        length > 1e-9 ? Eigen::Vector3d (entry.second.normal / length) : Eigen::Vector3d::Constant (std::nan (""));
  }
  return thinned;
}

/** Drops isolated points (the 8th neighbour farther than 3 times the median such distance: hair strands,
 *  spray), gives the points without a normal the normal of their 10 neighbours' plane, and each point the area it
 *  stands for (its 4th neighbour's squared distance over the median such: a scan sparse on the skull and dense
 *  on the face then votes by area, not by point count). */
OrientedPoints
surfaceOnly (const OrientedPoints& thinned)
{
  const auto tree = detail::pointTree (thinned.points);
  const Eigen::Index n = thinned.points.cols ();
  const int k = static_cast<int> (std::min<Eigen::Index> (10, n));
  std::vector<double> reach (n), spacing (n);
  Eigen::Matrix3Xd normals = thinned.normals;
#pragma omp parallel for schedule(static)
  for (Eigen::Index i = 0; i < n; ++i) {
    pcl::PointXYZ query;
    query.getVector3fMap () = thinned.points.col (i).cast<float> ();
    pcl::Indices index;
    std::vector<float> squared;
    tree->nearestKSearch (query, k, index, squared);
    reach[i] = std::sqrt (static_cast<double> (squared[std::min<size_t> (7, squared.size () - 1)]));
    spacing[i] = static_cast<double> (squared[std::min<size_t> (4, squared.size () - 1)]);
    if (!normals.col (i).allFinite ()) {
      Eigen::Matrix3Xd neighbours (3, index.size ());
      for (size_t j = 0; j < index.size (); ++j)
        neighbours.col (j) = thinned.points.col (index[j]);
      normals.col (i) = fitPlane (neighbours).normal;
    }
  }
  const double limit = 3.0 * trimmedLimit (reach, 0.5);
  const double typical_spacing = std::max (trimmedLimit (spacing, 0.5), 1e-12);
  OrientedPoints kept{Eigen::Matrix3Xd (3, n), Eigen::Matrix3Xd (3, n), Eigen::VectorXd (n)};
  Eigen::Index count = 0;
  for (Eigen::Index i = 0; i < n; ++i)
    if (reach[i] <= limit && normals.col (i).allFinite ()) {
      kept.points.col (count) = thinned.points.col (i);
      kept.areas[count] = std::min (spacing[i] / typical_spacing, 10.0);
      kept.normals.col (count++) = normals.col (i);
    }
  kept.points.conservativeResize (3, count);
  kept.normals.conservativeResize (3, count);
  kept.areas.conservativeResize (count);
  return kept;
}

/** Sums each cell's 3 x 3 x 3 neighbourhood (separable box filter), in place. */
void
boxFilter (const Grid& grid, std::vector<double>& values)
{
  const Eigen::Index strides[3] = {1, grid.size[0], static_cast<Eigen::Index> (grid.size[0]) * grid.size[1]};
  std::vector<double> out (values.size ());
  for (int axis = 0; axis < 3; ++axis) {
    for (Eigen::Index i = 0; i < grid.count (); ++i) {
      const Eigen::Index coordinate = (i / strides[axis]) % grid.size[axis];
      double sum = values[i];
      if (coordinate > 0)
        sum += values[i - strides[axis]];
      if (coordinate + 1 < grid.size[axis])
        sum += values[i + strides[axis]];
      out[i] = sum;
    }
    values.swap (out);
  }
}

/** Hough vote for spheres with radii in [r_min, r_max] that \a surface lies on: each point votes at p +- r n for
 *  12 radii; votes are summed over 3 x 3 x 3 cells and the \a count strongest peaks at least \a separation apart
 *  are returned, each with the mean radius of its votes. */
std::vector<Sphere>
houghSpheres (const OrientedPoints& surface, double r_min, double r_max, double cell, int count, double separation)
{
  const Eigen::Vector3d low = surface.points.rowwise ().minCoeff ().transpose ().array () - r_max;
  const Eigen::Vector3d high = surface.points.rowwise ().maxCoeff ().transpose ().array () + r_max;
  const Grid grid = gridOver (low, high, cell);
  std::vector<double> votes (grid.count (), 0.0), radii (grid.count (), 0.0);
  constexpr int kRadii = 12;
  for (Eigen::Index i = 0; i < surface.points.cols (); ++i)
    for (int r = 0; r < kRadii; ++r) {
      const double radius = r_min * std::pow (r_max / r_min, r / (kRadii - 1.0));
      for (double sign : {-1.0, 1.0}) {
        const Eigen::Index c = grid.index (surface.points.col (i) + sign * radius * surface.normals.col (i));
        if (c >= 0) {
          votes[c] += surface.areas[i];
          radii[c] += surface.areas[i] * radius;
        }
      }
    }
  boxFilter (grid, votes);
  boxFilter (grid, radii);
  std::vector<Eigen::Index> order (grid.count ());
  std::iota (order.begin (), order.end (), Eigen::Index (0));
  const auto top = std::min<size_t> (order.size (), 4096);
  std::partial_sort (order.begin (), order.begin () + static_cast<long> (top), order.end (),
                     [&votes] (Eigen::Index a, Eigen::Index b) { return votes[a] > votes[b]; });
  std::vector<Sphere> spheres;
  for (size_t k = 0; k < top && static_cast<int> (spheres.size ()) < count; ++k) {
    const Eigen::Index c = order[k];
    if (votes[c] <= 0.0)
      break;
    const Eigen::Vector3d centre = grid.centre (c);
    const bool distinct = std::all_of (spheres.begin (), spheres.end (),
                                       [&] (const Sphere& s) { return (s.centre - centre).norm () >= separation; });
    if (distinct)
      spheres.push_back ({centre, radii[c] / votes[c], votes[c]});
  }
  return spheres;
}

/** Rotations covering SO(3): the model's up axis (+Y) turned onto \a directions Fibonacci-sphere directions, each
 *  with \a twists turns about that axis. */
std::vector<Eigen::Matrix3d>
rotationGrid (int directions, int twists)
{
  std::vector<Eigen::Matrix3d> rotations;
  rotations.reserve (static_cast<size_t> (directions) * twists);
  const double golden = M_PI * (3.0 - std::sqrt (5.0));
  for (int j = 0; j < directions; ++j) {
    const double y = 1.0 - 2.0 * (j + 0.5) / directions;
    const double r = std::sqrt (std::max (0.0, 1.0 - y * y));
    const Eigen::Vector3d direction (r * std::cos (golden * j), y, r * std::sin (golden * j));
    const Eigen::Matrix3d tilt =
        Eigen::Quaterniond::FromTwoVectors (Eigen::Vector3d::UnitY (), direction).toRotationMatrix ();
    for (int t = 0; t < twists; ++t)
      rotations.push_back (tilt * Eigen::AngleAxisd (2.0 * M_PI * t / twists, Eigen::Vector3d::UnitY ()).matrix ());
  }
  return rotations;
}

double
angleBetween (const Eigen::Matrix3d& a, const Eigen::Matrix3d& b)
{
  return Eigen::AngleAxisd (Eigen::Matrix3d (a.transpose () * b)).angle ();
}

/** A rotation search's fixed point: the model point \a model goes to the scan point \a scan at \a scale. */
struct Anchor
{
  Eigen::Vector3d model, scan;
  double scale;
};

/** Per sample (model frame points and unit normals), whether it faces \a viewpoint once posed by \a pose: every
 *  sample without a viewpoint. */
std::vector<char>
facingSamples (const Eigen::Matrix4d& pose, const Eigen::Matrix3Xd& points, const Eigen::Matrix3Xd& normals,
               const std::optional<Eigen::Vector3d>& viewpoint)
{
  std::vector<char> facing (static_cast<size_t> (points.cols ()), 1);
  if (!viewpoint)
    return facing;
  const Eigen::Matrix3d linear = pose.topLeftCorner<3, 3> ();
  const Eigen::Vector3d t = pose.topRightCorner<3, 1> ();
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    facing[static_cast<size_t> (i)] = (linear * normals.col (i)).dot (*viewpoint - (linear * points.col (i) + t)) > 0.0;
  return facing;
}

/** The columns of \a points flagged in \a keep. */
Eigen::Matrix3Xd
kept (const Eigen::Matrix3Xd& points, const std::vector<char>& keep)
{
  Eigen::Matrix3Xd result (3, std::count (keep.begin (), keep.end (), 1));
  Eigen::Index k = 0;
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    if (keep[static_cast<size_t> (i)])
      result.col (k++) = points.col (i);
  return result;
}

/** A one-view scan as its sensor sees it: the direction to the sensor from the scan's centroid and the scan's
 *  outline across it. */
struct SensorView
{
  Eigen::Vector3d scan_centroid;
  Eigen::Vector3d towards;
  detail::SensorFootprint footprint;
};

/** The view of \a scan (3 x N) from settings.viewpoint, its outline in cells of edge \a cell; none without a
 *  viewpoint. */
std::optional<SensorView>
sensorView (const Eigen::Matrix3Xd& scan, double cell, const GlobalAlignmentSettings& settings)
{
  if (!settings.viewpoint)
    return std::nullopt;
  const Eigen::Vector3d centroid = scan.rowwise ().mean ();
  const Eigen::Vector3d towards = (*settings.viewpoint - centroid).normalized ();
  return SensorView{centroid, towards, detail::SensorFootprint (scan, towards, cell)};
}

/** The anchor of the poses placed by the side of the model facing the sensor (viewPoses), not about a point. */
constexpr int kViewAnchor = -1;

/** A pose and its score (lower is better), its coverage and the anchor it was searched about (an index into the
 *  anchors, or kViewAnchor). */
struct Pose
{
  Eigen::Matrix4d similarity;
  double score = std::numeric_limits<double>::infinity ();
  double coverage = 0.0;
  int anchor = 0;
};

/** How well \a samples (model surface samples with normals) posed by \a pose and \a scan agree: the mean of the
 *  distances from each posed sample to the tangent plane of its closest scan point (a sparse scan is a surface
 *  between its points), the truncation where that point is farther than it or the normals disagree by more than 45
 *  degrees, averaged with the mean truncated distance from the scan points within the posed model's reach (at its
 *  own size at least) to their closest posed sample (a face turned backwards lies inside the scan's face: only this direction sees the nose
 *  sticking out); and the share of the samples within \a near. A scale outside [min_scale, max_scale] scores the
 *  truncation. */
void
scorePose (const PointTree& tree, const OrientedPoints& scan, const OrientedPoints& all_samples, double truncation,
           double near, const GlobalAlignmentSettings& settings, Pose& pose)
{
  const double scale = detail::similarityScale (pose.similarity);
  const double min_scale = settings.min_radius_ratio, max_scale = settings.max_radius_ratio;
  const std::vector<char> facing =
      pose.similarity.allFinite ()
          ? facingSamples (pose.similarity, all_samples.points, all_samples.normals, settings.viewpoint)
          : std::vector<char> ();
  if (!pose.similarity.allFinite () || !(scale >= min_scale && scale <= max_scale) ||
      std::count (facing.begin (), facing.end (), 1) < 10) {
    pose.score = truncation;
    pose.coverage = 0.0;
    return;
  }
  const OrientedPoints samples{kept (all_samples.points, facing), kept (all_samples.normals, facing), {}};
  const Eigen::Matrix3Xd posed = detail::transformed (pose.similarity, samples.points);
  const Eigen::Matrix3d rotation = pose.similarity.topLeftCorner<3, 3> () / scale;
  const detail::Closest closest = detail::closestPoints (tree, posed);
  double forward = 0.0, covered = 0.0;
  for (Eigen::Index i = 0; i < posed.cols (); ++i) {
    const Eigen::Vector3d normal = scan.normals.col (closest.index[i]);
    const double agreement = std::abs ((rotation * samples.normals.col (i)).dot (normal));
    const double d =
        agreement >= std::sqrt (0.5) && closest.distance[i] <= truncation
            ? std::min (std::abs (normal.dot (posed.col (i) - scan.points.col (closest.index[i]))), truncation)
            : truncation;
    forward += d;
    covered += d <= near ? 1.0 : 0.0;
  }
  const Eigen::Vector3d centre = posed.rowwise ().mean ();
  // The model's reach at its own size at least: a model shrunk into the scan must not shed the points it leaves out.
  const double reach = (posed.colwise () - centre).colwise ().norm ().maxCoeff () * std::max (1.0, 1.0 / scale);
  const auto posed_tree = detail::pointTree (posed);
  double backward = 0.0, count = 0.0;
  for (Eigen::Index j = 0; j < scan.points.cols (); ++j)
    if ((scan.points.col (j) - centre).norm () <= reach) {
      pcl::PointXYZ query;
      query.getVector3fMap () = scan.points.col (j).cast<float> ();
      pcl::Indices index (1);
      std::vector<float> squared (1);
      posed_tree->nearestKSearch (query, 1, index, squared);
      backward += std::min (std::sqrt (static_cast<double> (squared[0])), truncation);
      count += 1.0;
    }
  const double n = static_cast<double> (posed.cols ());
  pose.score = 0.5 * (forward / n + (count > 0.0 ? backward / count : truncation));
  pose.coverage = covered / n;
}

/** The \a count best-scoring rotations of \a rotations at least 30 degrees apart. */
std::vector<size_t>
bestDistinct (const std::vector<Eigen::Matrix3d>& rotations, const std::vector<double>& scores, int count)
{
  std::vector<size_t> order (rotations.size ());
  std::iota (order.begin (), order.end (), size_t (0));
  std::sort (order.begin (), order.end (), [&scores] (size_t a, size_t b) { return scores[a] < scores[b]; });
  std::vector<size_t> chosen;
  for (size_t k = 0; k < order.size () && static_cast<int> (chosen.size ()) < count; ++k) {
    const bool distinct = std::all_of (chosen.begin (), chosen.end (), [&] (size_t c) {
      return angleBetween (rotations[c], rotations[order[k]]) > M_PI / 6.0;
    });
    if (distinct)
      chosen.push_back (order[k]);
  }
  return chosen;
}

void
requireInputs (const TriangleMesh& model_mean, const Eigen::Matrix3Xd& scan, const Eigen::Matrix3Xd& scan_normals)
{
  validateMesh (model_mean, "alignHeadGlobally: the model mean");
  if (scan.cols () < 10)
    throw InvalidInputError ("alignHeadGlobally: the scan has " + std::to_string (scan.cols ()) +
                             " points, at least 10 are needed");
  if (!scan.allFinite ())
    throw InvalidInputError ("alignHeadGlobally: the scan has non-finite points");
  if (scan_normals.cols () != 0 && scan_normals.cols () != scan.cols ())
    throw InvalidInputError ("alignHeadGlobally: " + std::to_string (scan_normals.cols ()) + " normals for " +
                             std::to_string (scan.cols ()) + " scan points");
}

/** The model's side of the search: its surface samples, size, voxel and head sphere. */
struct ModelFrame
{
  OrientedPoints samples;
  Eigen::Vector3d centroid;
  double radius;
  double voxel;
  Sphere sphere;
  /** Truncated distance to the model's surface in the model's frame, for the scan-to-model half of the grid scores
   *  of one-view scans; null without a viewpoint. */
  std::shared_ptr<const DistanceField> field;
};

ModelFrame
modelFrame (const TriangleMesh& model_mean, const GlobalAlignmentSettings& settings)
{
  ModelFrame model;
  model.samples = surfaceSamples (model_mean, 1500, 11);
  model.centroid = model.samples.points.rowwise ().mean ();
  model.radius = std::sqrt ((model.samples.points.colwise () - model.centroid).colwise ().squaredNorm ().mean ());
  model.voxel = settings.voxel_ratio * model.radius;
  const std::vector<Sphere> spheres =
      houghSpheres (model.samples, 0.4 * model.radius, 1.2 * model.radius, model.voxel, 1, model.radius);
  if (spheres.empty ())
    throw InvalidInputError ("alignHeadGlobally: the model mean has no head-like sphere");
  model.sphere = spheres.front ();
  if (!settings.viewpoint)
    return model;
  // Dense enough (about 2 mm apart on a head) for the field's cells of half a voxel.
  const OrientedPoints dense = surfaceSamples (model_mean, 30000, 13);
  const double truncation = settings.truncation_ratio * model.radius;
  model.field = std::make_shared<const DistanceField> (
      detail::gridAround (dense.points, truncation + model.voxel, 0.5 * model.voxel), dense.points, truncation);
  return model;
}

/** The mean truncated distance from the points of \a scan within \a reach of \a centre (scan frame) to the model's
 *  surface posed by \a similarity, read from the model's distance field at each point mapped back to the model's
 *  frame: the scan-to-model half of a pose's score, so that a face is not matched to a smaller, smoother part of
 *  the model (the back of the head) that leaves its nose and chin out. */
double
backwardScore (const ModelFrame& model, const Eigen::Matrix3Xd& scan, const Eigen::Matrix4d& similarity,
               const Eigen::Vector3d& centre, double reach, double truncation)
{
  const double scale = detail::similarityScale (similarity);
  const Eigen::Matrix3d inverse = similarity.topLeftCorner<3, 3> ().transpose () / (scale * scale);
  const Eigen::Vector3d translation = similarity.topRightCorner<3, 1> ();
  double sum = 0.0, count = 0.0;
  for (Eigen::Index j = 0; j < scan.cols (); ++j)
    if ((scan.col (j) - centre).squaredNorm () <= reach * reach) {
      sum += std::min (scale * model.field->at (inverse * (scan.col (j) - translation)), truncation);
      count += 1.0;
    }
  return count > 0.0 ? sum / count : truncation;
}

/** The scan thinned to the model's voxels, without isolated points, with normals. */
OrientedPoints
scanSurface (const Eigen::Matrix3Xd& scan, const Eigen::Matrix3Xd& scan_normals, double voxel)
{
  OrientedPoints surface = surfaceOnly (thinToVoxels (scan, scan_normals, voxel));
  if (surface.points.cols () < 10)
    throw InvalidInputError ("alignHeadGlobally: fewer than 10 scan points are left on a surface (" +
                             std::to_string (surface.points.cols ()) + " after thinning to " + std::to_string (voxel) +
                             " mm and dropping isolated points)");
  return surface;
}

/** Where the model's anchor goes and at what scale: each head sphere of the scan, and the scan's centroid with the
 *  model's centroid at the ratio of their spreads (a scan of the head alone, where a cut crown leaves no clear
 *  sphere). */
std::vector<Anchor>
anchorsOf (const ModelFrame& model, const OrientedPoints& surface, const std::vector<Sphere>& spheres,
           const GlobalAlignmentSettings& settings)
{
  std::vector<Anchor> anchors;
  for (const Sphere& sphere : spheres)
    anchors.push_back ({model.sphere.centre, sphere.centre, sphere.radius / model.sphere.radius});
  const Eigen::Vector3d scan_centroid = surface.points.rowwise ().mean ();
  const double scan_radius = std::sqrt ((surface.points.colwise () - scan_centroid).colwise ().squaredNorm ().mean ());
  anchors.push_back ({model.centroid, scan_centroid,
                      std::clamp (scan_radius / model.radius, settings.min_radius_ratio, settings.max_radius_ratio)});
  return anchors;
}

/** What every grid rotation is scored with: the model's score samples, weighted (samples off the model's head sphere,
 *  on the nose, chin, ears and neck, tell the rotations apart; the cranium hardly does). */
struct GridScoring
{
  Eigen::Matrix3Xd samples, normals;
  Eigen::VectorXd weights;
  double truncation;
  double reach; ///< the farthest sample from the model's centroid
};

GridScoring
gridScoring (const ModelFrame& model, const GlobalAlignmentSettings& settings)
{
  GridScoring scoring;
  scoring.samples = detail::evenSamples (model.samples.points, settings.score_samples);
  scoring.normals = detail::evenSamples (model.samples.normals, settings.score_samples);
  scoring.weights.resize (scoring.samples.cols ());
  for (Eigen::Index i = 0; i < scoring.samples.cols (); ++i)
    scoring.weights[i] =
        1.0 +
        4.0 * std::min (1.0, std::abs ((scoring.samples.col (i) - model.sphere.centre).norm () - model.sphere.radius) /
                                 (0.3 * model.sphere.radius));
  scoring.truncation = settings.truncation_ratio * model.radius;
  scoring.reach = (scoring.samples.colwise () - model.centroid).colwise ().norm ().maxCoeff ();
  return scoring;
}

/** The grid score of \a similarity (lower is better): the weighted mean of the scan's distance \a field at the posed
 *  samples that face the sensor; for a one-view scan (a \a viewpoint), averaged with the backward score of the
 *  \a scan points (a few hundred about the place searched) near the posed model (within its reach at its own size at
 *  least). The truncation when the sensor sees less than a quarter of the model. */
double
gridScore (const GridScoring& scoring, const ModelFrame& model, const DistanceField& field,
           const Eigen::Matrix3Xd& scan, const Eigen::Matrix4d& similarity,
           const std::optional<Eigen::Vector3d>& viewpoint)
{
  const std::vector<char> facing = facingSamples (similarity, scoring.samples, scoring.normals, viewpoint);
  const Eigen::Matrix3d linear = similarity.topLeftCorner<3, 3> ();
  const Eigen::Vector3d translation = similarity.topRightCorner<3, 1> ();
  double sum = 0.0, weight = 0.0;
  for (Eigen::Index i = 0; i < scoring.samples.cols (); ++i)
    if (facing[static_cast<size_t> (i)]) {
      sum += scoring.weights[i] * field.at (linear * scoring.samples.col (i) + translation);
      weight += scoring.weights[i];
    }
  if (weight < 0.25 * scoring.weights.sum ())
    return scoring.truncation;
  if (!viewpoint) // around a whole head, shoulders, a chair and hair would weigh in the scan-to-model half
    return sum / weight;
  const double reach = std::max (1.0, detail::similarityScale (similarity)) * scoring.reach;
  return 0.5 * (sum / weight + backwardScore (model, scan, similarity, linear * model.centroid + translation, reach,
                                              scoring.truncation));
}

/** About settings.score_samples of the \a scan points within \a radius of \a centre (all of them if fewer): the
 *  scan-to-model half of the grid scores about an anchor, taken where the head may be and not from a whole room. */
Eigen::Matrix3Xd
scanSamplesNear (const Eigen::Matrix3Xd& scan, const Eigen::Vector3d& centre, double radius,
                 const GlobalAlignmentSettings& settings)
{
  std::vector<char> inside (static_cast<size_t> (scan.cols ()));
  for (Eigen::Index i = 0; i < scan.cols (); ++i)
    inside[static_cast<size_t> (i)] = (scan.col (i) - centre).squaredNorm () <= radius * radius;
  return detail::evenSamples (kept (scan, inside), settings.score_samples);
}

/** The best-scoring grid rotations about every anchor, settings.rotations_per_anchor of them per anchor. */
std::vector<Pose>
anchorPoses (const ModelFrame& model, const GridScoring& scoring, const OrientedPoints& surface,
             const std::vector<Anchor>& anchors, const std::vector<Eigen::Matrix3d>& rotations,
             const GlobalAlignmentSettings& settings)
{
  std::vector<Pose> poses;
  for (size_t a = 0; a < anchors.size (); ++a) {
    const Anchor& anchor = anchors[a];
    const double reach = (scoring.samples.colwise () - anchor.model).colwise ().norm ().maxCoeff ();
    const Eigen::Vector3d half = Eigen::Vector3d::Constant (anchor.scale * reach + scoring.truncation);
    const DistanceField field (gridOver (anchor.scan - half, anchor.scan + half, model.voxel), surface.points,
                               scoring.truncation);
    // Only one-view scans are scored scan to model (gridScore).
    const Eigen::Matrix3Xd near =
        settings.viewpoint ? scanSamplesNear (surface.points, anchor.scan,
                                              std::max (1.0, anchor.scale) * reach + scoring.truncation, settings)
                           : Eigen::Matrix3Xd ();
    std::vector<double> scores (rotations.size ());
#pragma omp parallel for schedule(static)
    for (size_t r = 0; r < rotations.size (); ++r)
      scores[r] = gridScore (scoring, model, field, near,
                             detail::similarityAbout (anchor.scale, rotations[r], anchor.model, anchor.scan),
                             settings.viewpoint);
    for (size_t r : bestDistinct (rotations, scores, settings.rotations_per_anchor))
      poses.push_back ({detail::similarityAbout (anchor.scale, rotations[r], anchor.model, anchor.scan), scores[r], 0.0,
                        static_cast<int> (a)});
  }
  return poses;
}

/** The similarity of \a scale and \a rotation that lays the part of the model facing the sensor onto the scan: its
 *  centroid first on the scan's, then (twice) the centroid of the part within the scan's \a footprint moved onto
 *  the scan's centroid, so that model parts a cropped scan lacks (the neck, the crown) do not pull it aside. */
Eigen::Matrix4d
viewPlacement (const GridScoring& scoring, const SensorView& view, double scale, const Eigen::Matrix3d& rotation)
{
  const Eigen::Vector3d& towards = view.towards;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero ();
  double count = 0.0;
  for (Eigen::Index i = 0; i < scoring.samples.cols (); ++i)
    if ((rotation * scoring.normals.col (i)).dot (towards) > 0.0) {
      sum += scoring.samples.col (i);
      count += 1.0;
    }
  Eigen::Matrix4d similarity =
      detail::similarityAbout (scale, rotation, sum / std::max (count, 1.0), view.scan_centroid);
  for (int step = 0; step < 2; ++step) {
    Eigen::Vector3d inside = Eigen::Vector3d::Zero ();
    double inside_count = 0.0;
    for (Eigen::Index i = 0; i < scoring.samples.cols (); ++i) {
      const Eigen::Vector3d posed =
          similarity.topLeftCorner<3, 3> () * scoring.samples.col (i) + similarity.topRightCorner<3, 1> ();
      if ((rotation * scoring.normals.col (i)).dot (towards) > 0.0 && view.footprint.covers (posed)) {
        inside += posed;
        inside_count += 1.0;
      }
    }
    if (inside_count < 10.0)
      break;
    similarity.topRightCorner<3, 1> () += view.scan_centroid - inside / inside_count;
  }
  return similarity;
}

/** The head scales the one-view search tries (small to large heads against the model's mean), those within the
 *  searched radius range; none without a viewpoint. */
std::vector<double>
viewScales (const GlobalAlignmentSettings& settings)
{
  std::vector<double> scales;
  if (settings.viewpoint)
    for (double scale : {0.8, 0.92, 1.05, 1.2})
      if (scale >= settings.min_radius_ratio && scale <= settings.max_radius_ratio)
        scales.push_back (scale);
  return scales;
}

/** One-view scans (settings.viewpoint set): a face seen from the front has no head sphere, and the model's centroid
 *  lies deep behind it, so per grid rotation the model's side facing the sensor is laid onto the scan
 *  (viewPlacement) at a few head scales; the best distinct rotations per scale. None without a viewpoint. */
std::vector<Pose>
viewPoses (const ModelFrame& model, const GridScoring& scoring, const OrientedPoints& surface,
           const std::optional<SensorView>& view, const std::vector<Eigen::Matrix3d>& rotations,
           const GlobalAlignmentSettings& settings)
{
  if (!view)
    return {};
  const Eigen::Matrix3Xd scan = detail::evenSamples (surface.points, settings.score_samples);
  const DistanceField field (detail::gridAround (surface.points, 0.6 * model.radius + scoring.truncation, model.voxel),
                             surface.points, scoring.truncation);
  std::vector<Pose> poses;
  for (double scale : viewScales (settings)) {
    std::vector<Eigen::Matrix4d> similarities (rotations.size ());
    std::vector<double> scores (rotations.size ());
#pragma omp parallel for schedule(static)
    for (size_t r = 0; r < rotations.size (); ++r) {
      similarities[r] = viewPlacement (scoring, *view, scale, rotations[r]);
      scores[r] = gridScore (scoring, model, field, scan, similarities[r], settings.viewpoint);
    }
    for (size_t r : bestDistinct (rotations, scores, settings.rotations_per_anchor))
      poses.push_back ({similarities[r], scores[r], 0.0, kViewAnchor});
  }
  return poses;
}

/** The settings.refined_poses best of \a poses, best first (an anchor off the head scores badly for every
 *  rotation, and only the best grid scores over all anchors go on). */
std::vector<Pose>
bestPoses (std::vector<Pose> poses, const GlobalAlignmentSettings& settings)
{
  std::sort (poses.begin (), poses.end (), [] (const Pose& a, const Pose& b) { return a.score < b.score; });
  poses.resize (std::min<size_t> (poses.size (), static_cast<size_t> (settings.refined_poses)));
  return poses;
}

/** Refines every pose a few similarity ICP steps and the best three to the end, each scored on the scan's k-d
 *  tree; returns the pose indices, best first. */
std::vector<size_t>
refinePoses (const ModelFrame& model, const OrientedPoints& surface, const PointTree::Ptr& tree,
             const std::vector<Anchor>& anchors, const GlobalAlignmentSettings& settings, std::vector<Pose>& poses)
{
  const Eigen::Matrix3Xd samples = detail::evenSamples (model.samples.points, 600);
  const Eigen::Matrix3Xd normals = detail::evenSamples (model.samples.normals, 600);
  const double truncation = settings.truncation_ratio * model.radius;
  const auto refine = [&] (const std::vector<size_t>& active, int iterations) {
#pragma omp parallel for schedule(dynamic, 1)
    for (size_t k = 0; k < active.size (); ++k) {
      Pose& pose = poses[active[k]];
      const Eigen::Vector3d centre =
          pose.similarity.topLeftCorner<3, 3> () *
              (pose.anchor == kViewAnchor ? model.centroid : anchors[static_cast<size_t> (pose.anchor)].model) +
          pose.similarity.topRightCorner<3, 1> ();
      const Eigen::Matrix3Xd seen =
          kept (samples, facingSamples (pose.similarity, samples, normals, settings.viewpoint));
      if (seen.cols () >= 10)
        pose.similarity = detail::refineSimilarity (tree, surface.points, surface.normals, centre, seen,
                                                    pose.similarity, iterations, settings.inlier_fraction);
      scorePose (*tree, surface, model.samples, truncation, 2.0 * model.voxel, settings, pose);
    }
  };
  const auto by_score = [&poses] (size_t a, size_t b) { return poses[a].score < poses[b].score; };
  std::vector<size_t> active (poses.size ());
  std::iota (active.begin (), active.end (), size_t (0));
  const int screening = std::min (settings.screen_iterations, settings.refine_iterations);
  refine (active, screening);
  std::sort (active.begin (), active.end (), by_score);
  const std::vector<size_t> finalists (active.begin (),
                                       active.begin () + std::min<long> (3, static_cast<long> (active.size ())));
  refine (finalists, settings.refine_iterations - screening);
  std::sort (active.begin (), active.end (), by_score);
  return active;
}

/** The score of the best pose of \a ranked (pose indices, best first) at least 30 degrees or a model radius away
 *  from the first; 0 if there is none. */
double
runnerUpScore (const std::vector<Pose>& poses, const std::vector<size_t>& ranked, double model_radius)
{
  const Pose& best = poses[ranked.front ()];
  const Eigen::Matrix3d best_rotation =
      best.similarity.topLeftCorner<3, 3> () / detail::similarityScale (best.similarity);
  for (size_t k = 1; k < ranked.size (); ++k) {
    const Pose& other = poses[ranked[k]];
    const Eigen::Matrix3d rotation =
        other.similarity.topLeftCorner<3, 3> () / detail::similarityScale (other.similarity);
    const double shift = (other.similarity.topRightCorner<3, 1> () - best.similarity.topRightCorner<3, 1> ()).norm ();
    if (angleBetween (rotation, best_rotation) > M_PI / 6.0 || shift > model_radius)
      return other.score;
  }
  return 0.0;
}

/** The scan points within the truncation distance of the model's samples posed by \a similarity: the head. */
std::vector<int>
headIndices (const Eigen::Matrix3Xd& scan, const Eigen::Matrix3Xd& samples, const Eigen::Matrix4d& similarity,
             double truncation)
{
  const auto model_tree = detail::pointTree (detail::transformed (similarity, samples));
  const double head_reach = truncation * detail::similarityScale (similarity);
  std::vector<int> indices;
  for (Eigen::Index i = 0; i < scan.cols (); ++i) {
    pcl::PointXYZ query;
    query.getVector3fMap () = scan.col (i).cast<float> ();
    pcl::Indices index (1);
    std::vector<float> squared (1);
    model_tree->nearestKSearch (query, 1, index, squared);
    if (std::sqrt (static_cast<double> (squared[0])) <= head_reach)
      indices.push_back (static_cast<int> (i));
  }
  return indices;
}

/** The sentence of GlobalAlignment::method. */
std::string
methodSentence (const GlobalAlignment& result, const ModelFrame& model, const OrientedPoints& surface, size_t spheres,
                size_t viewed, const std::string& winner, size_t rotations, Eigen::Index scan_points)
{
  std::ostringstream method;
  method.precision (3);
  method << "global: the scan thinned to " << surface.points.cols () << " points (" << model.voxel << " mm voxels); "
         << spheres << " head sphere(s) by Hough vote and the scan's centroid as anchors"
         << (viewed ? ", and the model's side facing the sensor laid onto the scan at " + std::to_string (viewed) +
                          " scales"
                    : std::string ())
         << "; the winner " << winner << " at (" << result.head_centre.transpose () << "), head radius "
         << result.head_radius << " mm (the model's " << model.sphere.radius << " mm); " << rotations
         << " rotations per anchor or scale scored on distance transforms of the scan and the model; "
         << result.poses_refined << " poses refined by similarity ICP; best truncated distance " << result.score
         << " mm, runner-up " << result.runner_up_score << " mm; coverage " << result.coverage << "; "
         << result.head_indices.size () << " of " << scan_points << " scan points on the head";
  return method.str ();
}
} // namespace

GlobalAlignment
alignHeadGlobally (const TriangleMesh& model_mean, const Eigen::Matrix3Xd& scan, const Eigen::Matrix3Xd& scan_normals,
                   const GlobalAlignmentSettings& settings)
{
  requireSettings (settings);
  requireInputs (model_mean, scan, scan_normals);
  const ModelFrame model = modelFrame (model_mean, settings);
  const OrientedPoints surface = scanSurface (scan, scan_normals, model.voxel);
  const std::vector<Sphere> spheres = houghSpheres (surface, settings.min_radius_ratio * model.sphere.radius,
                                                    settings.max_radius_ratio * model.sphere.radius, model.voxel,
                                                    settings.centre_candidates, model.sphere.radius);
  const std::vector<Anchor> anchors = anchorsOf (model, surface, spheres, settings);
  const std::vector<Eigen::Matrix3d> rotations = rotationGrid (settings.rotation_directions, settings.rotation_twists);
  const std::optional<SensorView> view = sensorView (surface.points, model.voxel, settings);
  const GridScoring scoring = gridScoring (model, settings);
  std::vector<Pose> poses = anchorPoses (model, scoring, surface, anchors, rotations, settings);
  const std::vector<Pose> seen_poses = viewPoses (model, scoring, surface, view, rotations, settings);
  poses.insert (poses.end (), seen_poses.begin (), seen_poses.end ());
  poses = bestPoses (std::move (poses), settings);
  const std::vector<size_t> ranked =
      refinePoses (model, surface, detail::pointTree (surface.points), anchors, settings, poses);

  const Pose& best = poses[ranked.front ()];
  GlobalAlignment result;
  result.similarity = best.similarity;
  result.score = best.score;
  result.coverage = best.coverage;
  result.runner_up_score = runnerUpScore (poses, ranked, model.radius);
  const double distinctness = result.runner_up_score > 0.0 ? 1.0 - result.score / result.runner_up_score : 1.0;
  result.confidence = std::clamp (result.coverage * distinctness, 0.0, 1.0);
  const size_t viewed = viewScales (settings).size ();
  const double scale = detail::similarityScale (best.similarity);
  const Anchor view_anchor{
      model.sphere.centre,
      best.similarity.topLeftCorner<3, 3> () * model.sphere.centre + best.similarity.topRightCorner<3, 1> (), scale};
  const Anchor& anchor = best.anchor == kViewAnchor ? view_anchor : anchors[static_cast<size_t> (best.anchor)];
  result.head_centre = anchor.scan;
  result.head_radius = anchor.scale * model.sphere.radius;
  result.rotations_scored = static_cast<int> (rotations.size () * (anchors.size () + viewed));
  result.poses_refined = static_cast<int> (poses.size ());
  result.head_indices =
      headIndices (scan, model.samples.points, best.similarity, settings.truncation_ratio * model.radius);
  const std::string winner = best.anchor == kViewAnchor                            ? "the side facing the sensor"
                             : static_cast<size_t> (best.anchor) < spheres.size () ? "a sphere"
                                                                                   : "the centroid";
  result.method =
      methodSentence (result, model, surface, spheres.size (), viewed, winner, rotations.size (), scan.cols ());
  return result;
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include "hole_filling.h"
#include "scan_surface.h"

#include <morphreg/common/error.h>
#include <morphreg/common/order_statistics.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/resampling/scan_resampler.h>

#include <pcl/common/io.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>
#include <numeric>
#include <sstream>

namespace morphreg
{
namespace detail
{
/** The holes of a resampling, largest first: their vertices and their statistics. */
struct Holes
{
  std::vector<std::vector<int>> vertices;
  std::vector<ResamplingHole> holes;
};
} // namespace detail

namespace
{
using detail::Holes;
using Clock = std::chrono::steady_clock;

/** Sizes further apart than this factor are another unit (cm, inches and m are 10, 25.4 and 1000 times mm), not a
 *  partial scan of the same head. */
constexpr double kMaxSizeRatio = 4.0;

double
secondsSince (Clock::time_point start)
{
  return std::chrono::duration<double> (Clock::now () - start).count ();
}

/** RMS distance of the columns from their centroid. */
double
rmsRadius (const Eigen::Matrix3Xd& points)
{
  const Eigen::Vector3d centroid = points.rowwise ().mean ();
  return std::sqrt ((points.colwise () - centroid).colwise ().squaredNorm ().mean ());
}

void
requireComparableSize (const Eigen::Matrix3Xd& reference, const Eigen::Matrix3Xd& scan)
{
  const double ratio = rmsRadius (scan) / std::max (rmsRadius (reference), std::numeric_limits<double>::min ());
  if (ratio <= kMaxSizeRatio && ratio >= 1.0 / kMaxSizeRatio)
    return;
  std::ostringstream message;
  message << "ScanResampler: the scan is " << ratio << " times the reference's size; are they in different units "
          << "(both must be in mm)?";
  throw InvalidInputError (message.str ());
}

/** Each vertex's share of the surface: a third of the area of each triangle it belongs to. */
Eigen::VectorXd
vertexAreas (const TriangleMesh& mesh)
{
  const Eigen::VectorXd triangle = triangleAreas (mesh);
  Eigen::VectorXd areas = Eigen::VectorXd::Zero (mesh.numVertices ());
  for (Eigen::Index t = 0; t < mesh.numTriangles (); ++t)
    for (int k = 0; k < 3; ++k)
      areas[mesh.triangles (k, t)] += triangle[t] / 3.0;
  return areas;
}

/** Per triangle: its normal turned by more than 90 degrees from the reference's (or it became degenerate). */
std::vector<char>
foldedTriangles (const TriangleMesh& reference, const TriangleMesh& resampled)
{
  const Eigen::Matrix3Xd before = faceNormals (reference), after = faceNormals (resampled);
  std::vector<char> folded (static_cast<std::size_t> (reference.numTriangles ()));
#pragma omp parallel for schedule(static)
  for (Eigen::Index t = 0; t < reference.numTriangles (); ++t)
    folded[t] = before.col (t).dot (after.col (t)) <= 0.0 ? 1 : 0;
  return folded;
}

/** Marks missed the corners of every triangle whose three corners were observed but whose observed positions turn it
 *  over (by more than 90 degrees against the reference): vertices on both sides of a crease the scan does not have
 *  (an eyelid's margin, a nostril's rim) landing on the one surface the scan has there. The hole fills take them.
 *  Missed vertices stand at their \a start positions. */
void
rejectFoldingHits (const TriangleMesh& reference, const Eigen::Matrix3Xd& start, const Eigen::Matrix3Xd& hits,
                   std::vector<char>& missed)
{
  TriangleMesh moved{hits, reference.triangles};
  for (Eigen::Index v = 0; v < hits.cols (); ++v)
    if (missed[v])
      moved.vertices.col (v) = start.col (v);
  const std::vector<char> folded = foldedTriangles (reference, moved);
  for (Eigen::Index t = 0; t < reference.numTriangles (); ++t) {
    const Eigen::Vector3i corners = reference.triangles.col (t);
    if (folded[t] && !missed[corners[0]] && !missed[corners[1]] && !missed[corners[2]])
      for (int k = 0; k < 3; ++k)
        missed[corners[k]] = 1;
  }
}

/** Marks missed the hits whose displacement along the normal differs by more than \a jump (mm) from the median of
 *  their observed neighbours' (a ray that met another surface: an ear's back, an outlier's plane), and those with
 *  fewer observed neighbours than missed ones (ragged hole borders and islands in holes, where the scan's edge is
 *  least reliable). */
void
rejectInconsistentHits (const MeshTopology& topology, const Eigen::Matrix3Xd& offsets, const Eigen::Matrix3Xd& normals,
                        double jump, std::vector<char>& missed)
{
  const Eigen::VectorXd along = offsets.cwiseProduct (normals).colwise ().sum ().transpose ();
  std::vector<char> rejected (missed.size (), 0);
  const auto count = static_cast<std::ptrdiff_t> (missed.size ());
#pragma omp parallel for schedule(static)
  for (std::ptrdiff_t v = 0; v < count; ++v) {
    if (missed[v])
      continue;
    thread_local std::vector<double> around;
    around.clear ();
    const auto [begin, end] = topology.neighbours (static_cast<int> (v));
    for (const int* n = begin; n != end; ++n)
      if (!missed[*n])
        around.push_back (along[*n]);
    const bool isolated =
        around.empty () || 2 * static_cast<int> (around.size ()) < topology.valence (static_cast<int> (v));
    rejected[v] = isolated || std::abs (along[v] - median (around)) > jump ? 1 : 0;
  }
  for (std::size_t v = 0; v < missed.size (); ++v)
    missed[v] = missed[v] || rejected[v];
}

/** The connected misses as holes, largest (by area) first; throws if the largest covers more than \a max_fraction
 *  of the reference's area. */
Holes
findHoles (const MeshTopology& topology, const Eigen::VectorXd& areas, const std::vector<char>& missed,
           double max_fraction)
{
  std::vector<std::vector<int>> components = detail::connectedMisses (topology, missed);
  std::vector<double> component_area;
  for (const auto& component : components) {
    double area = 0.0;
    for (const int v : component)
      area += areas[v];
    component_area.push_back (area);
  }
  std::vector<std::size_t> order (components.size ());
  std::iota (order.begin (), order.end (), 0);
  std::sort (order.begin (), order.end (),
             [&] (std::size_t a, std::size_t b) { return component_area[a] > component_area[b]; });
  Holes result;
  for (const std::size_t k : order) {
    ResamplingHole hole;
    hole.vertices = static_cast<int> (components[k].size ());
    hole.area = component_area[k];
    result.holes.push_back (hole);
    result.vertices.push_back (std::move (components[k]));
  }
  const double total = areas.sum ();
  if (!result.holes.empty () && result.holes.front ().area > max_fraction * total) {
    std::ostringstream message;
    message << "ScanResampler: a hole of " << result.holes.front ().vertices << " vertices covers "
            << 100.0 * result.holes.front ().area / total << " % of the reference's surface (at most "
            << 100.0 * max_fraction << " % may be filled); the scan covers too little of the reference";
    throw InvalidInputError (message.str ());
  }
  return result;
}

/** Fills every hole (see detail::fillHole), recording its anchors; the holes are disjoint and read only observed
 *  vertices, so they are filled on all cores, the largest first. */
void
fillHoles (const MeshTopology& topology, const Eigen::Matrix3Xd& reference, const std::vector<char>& missed, int rings,
           double lambda, Holes& holes, Eigen::Matrix3Xd& displacement)
{
  const auto count = static_cast<std::ptrdiff_t> (holes.holes.size ());
  std::vector<std::exception_ptr> failures (holes.holes.size ());
#pragma omp parallel for schedule(dynamic, 1)
  for (std::ptrdiff_t h = 0; h < count; ++h) {
    try {
      holes.holes[h].ring_vertices =
          detail::fillHole (topology, reference, holes.vertices[h], missed, rings, lambda, displacement);
    }
    catch (...) {
      failures[h] = std::current_exception (); // nothing may leave an OpenMP loop
    }
  }
  for (std::ptrdiff_t h = 0; h < count; ++h) {
    if (!failures[h])
      continue;
    try {
      std::rethrow_exception (failures[h]);
    }
    catch (const Error& e) {
      throw InvalidInputError ("ScanResampler: the hole of " + std::to_string (holes.vertices[h].size ()) +
                               " vertices around reference vertex " + std::to_string (holes.vertices[h].front ()) +
                               " cannot be filled from the observed vertices around it: " + e.what ());
    }
  }
}

/** Counts the folded triangles, in all and per hole (those with a vertex in it). */
void
countFolds (const TriangleMesh& reference, const TriangleMesh& resampled, Holes& holes, ResamplingStatistics& stats)
{
  std::vector<int> hole_of (static_cast<std::size_t> (reference.numVertices ()), -1);
  for (std::size_t h = 0; h < holes.vertices.size (); ++h)
    for (const int v : holes.vertices[h])
      hole_of[v] = static_cast<int> (h);
  const std::vector<char> folded = foldedTriangles (reference, resampled);
  for (Eigen::Index t = 0; t < reference.numTriangles (); ++t) {
    if (!folded[t])
      continue;
    ++stats.folded_triangles;
    int counted[3] = {-1, -1, -1};
    for (int k = 0; k < 3; ++k) {
      const int h = hole_of[reference.triangles (k, t)];
      if (h >= 0 && h != counted[0] && h != counted[1]) {
        ++holes.holes[h].folded_triangles;
        counted[k] = h;
      }
    }
  }
}
} // namespace

ScanResampler::ScanResampler () = default;
ScanResampler::~ScanResampler () = default;

void
ScanResampler::setInputReference (const TriangleMesh& reference)
{
  validateMesh (reference, "ScanResampler reference");
  reference_ = reference;
}

void
ScanResampler::setInputScan (const pcl::PointCloud<pcl::PointNormal>& scan)
{
  Eigen::Matrix3Xd points (3, scan.size ()), normals (3, scan.size ());
  Eigen::Index kept = 0;
  for (const auto& point : scan)
    if (std::isfinite (point.x) && std::isfinite (point.y) && std::isfinite (point.z)) {
      points.col (kept) = point.getVector3fMap ().cast<double> ();
      normals.col (kept++) = point.getNormalVector3fMap ().cast<double> ().normalized ();
    }
  if (kept < settings_.neighbours)
    throw InvalidInputError ("ScanResampler: the scan has " + std::to_string (kept) + " finite points; at least " +
                             std::to_string (settings_.neighbours) + " are needed");
  surface_ = detail::makeCloudSurface (points.leftCols (kept), normals.leftCols (kept), settings_.neighbours);
}

void
ScanResampler::setInputScan (const pcl::PointCloud<pcl::PointXYZ>& scan)
{
  pcl::PointCloud<pcl::PointNormal> with_normals;
  pcl::copyPointCloud (scan, with_normals);
  for (auto& point : with_normals)
    point.getNormalVector3fMap ().setConstant (std::numeric_limits<float>::quiet_NaN ());
  setInputScan (with_normals);
}

void
ScanResampler::setInputScan (const TriangleMesh& scan)
{
  validateMesh (scan, "ScanResampler scan");
  surface_ = detail::makeMeshSurface (scan);
}

void
ScanResampler::setSettings (const ResamplingSettings& settings)
{
  requireValidSettings (settings);
  settings_ = settings;
}

namespace
{
/** \a settings with \a field set to \a value. */
template <typename T>
ResamplingSettings
with (ResamplingSettings settings, T ResamplingSettings::*field, T value)
{
  settings.*field = value;
  return settings;
}
} // namespace

void
ScanResampler::setMaxDistance (double distance)
{
  setSettings (with (settings_, &ResamplingSettings::ray_distance, distance));
}

void
ScanResampler::setNormalAgreement (double degrees)
{
  setSettings (with (settings_, &ResamplingSettings::normal_agreement, degrees));
}

void
ScanResampler::setRingWidth (int rings)
{
  setSettings (with (settings_, &ResamplingSettings::ring_width, rings));
}

void
ScanResampler::setMaxHoleFraction (double fraction)
{
  setSettings (with (settings_, &ResamplingSettings::max_hole_fraction, fraction));
}

void
ScanResampler::setNeighbours (int k)
{
  setSettings (with (settings_, &ResamplingSettings::neighbours, k));
}

void
ScanResampler::setMaxJump (double jump)
{
  setSettings (with (settings_, &ResamplingSettings::max_jump, jump));
}

void
ScanResampler::setPasses (int passes)
{
  setSettings (with (settings_, &ResamplingSettings::passes, passes));
}

void
ScanResampler::setFillRegularization (double lambda)
{
  setSettings (with (settings_, &ResamplingSettings::fill_smoothing, lambda));
}

Eigen::Matrix3Xd
ScanResampler::castRays (const Eigen::Matrix3Xd& origins, const Eigen::Matrix3Xd& normals,
                         const std::vector<char>& cast) const
{
  const double min_cos = std::cos (settings_.normal_agreement * M_PI / 180.0);
  std::vector<Eigen::Index> rays; // the vertices to cast from, listed so that the cores share them evenly
  for (Eigen::Index v = 0; v < origins.cols (); ++v)
    if (cast[v])
      rays.push_back (v);
  const auto count = static_cast<std::ptrdiff_t> (rays.size ());
  Eigen::Matrix3Xd hits = origins;
#pragma omp parallel for schedule(dynamic, 64) if (surface_->threadSafe())
  for (std::ptrdiff_t r = 0; r < count; ++r) {
    const Eigen::Index v = rays[r];
    Eigen::Vector3d hit;
    const bool found = normals.col (v).squaredNorm () > 0.0 &&
                       surface_->intersect (origins.col (v), normals.col (v), settings_.ray_distance, min_cos, hit);
    hits.col (v) = found ? hit : Eigen::Vector3d::Constant (std::numeric_limits<double>::quiet_NaN ());
  }
  return hits;
}

ResamplingResult
ScanResampler::resample () const
{
  if (reference_.numVertices () == 0)
    throw InvalidInputError ("ScanResampler: no reference mesh (setInputReference)");
  if (!surface_)
    throw InvalidInputError ("ScanResampler: no scan (setInputScan)");
  requireComparableSize (reference_.vertices, surface_->points ());
  const MeshTopology topology (reference_);
  const Eigen::VectorXd areas = vertexAreas (reference_);
  ResamplingResult result;
  result.mesh = reference_;
  std::vector<char> missed (static_cast<std::size_t> (reference_.numVertices ()), 1);
  Holes holes;
  for (int pass = 0; pass < settings_.passes; ++pass)
    holes = resamplePass (topology, areas, missed, result);
  summarise (missed, areas, holes, result);
  if (!result.mesh.vertices.allFinite ())
    throw NumericalError ("ScanResampler: the resampled mesh has non-finite vertices");
  return result;
}

Holes
ScanResampler::resamplePass (const MeshTopology& topology, const Eigen::VectorXd& areas, std::vector<char>& missed,
                             ResamplingResult& result) const
{
  const Eigen::Matrix3Xd start = result.mesh.vertices;
  const Eigen::Matrix3Xd normals = vertexNormals (result.mesh);
  const auto ray_start = Clock::now ();
  const Eigen::Matrix3Xd hits = castRays (start, normals, missed);
  Eigen::Matrix3Xd displacement = hits - start;
  for (Eigen::Index v = 0; v < start.cols (); ++v)
    missed[v] = displacement.col (v).allFinite () ? 0 : 1;
  rejectInconsistentHits (topology, displacement, normals, settings_.max_jump, missed);
  rejectFoldingHits (reference_, start, hits, missed);
  for (Eigen::Index v = 0; v < start.cols (); ++v)
    if (missed[v])
      displacement.col (v).setZero ();
  result.statistics.ray_seconds += secondsSince (ray_start);
  if (std::all_of (missed.begin (), missed.end (), [] (char m) { return m != 0; }))
    throw InvalidInputError ("ScanResampler: no reference vertex meets the scan within " +
                             std::to_string (settings_.ray_distance) +
                             " mm along its normal; the scan and the reference do "
                             "not overlap (is the reference fitted to this scan, in its frame?)");
  const auto fill_start = Clock::now ();
  Holes holes = findHoles (topology, areas, missed, settings_.max_hole_fraction);
  fillHoles (topology, start, missed, settings_.ring_width, settings_.fill_smoothing, holes, displacement);
  result.statistics.fill_seconds += secondsSince (fill_start);
  result.mesh.vertices = start + displacement;
  return holes;
}

void
ScanResampler::summarise (const std::vector<char>& missed, const Eigen::VectorXd& areas, Holes& holes,
                          ResamplingResult& result) const
{
  ResamplingStatistics& stats = result.statistics;
  result.displacement = result.mesh.vertices - reference_.vertices;
  result.state.resize (missed.size ());
  std::vector<double> moved;
  double observed_area = 0.0;
  for (std::size_t v = 0; v < missed.size (); ++v) {
    const auto i = static_cast<Eigen::Index> (v);
    result.state[v] = missed[v] ? ResampledVertex::filled : ResampledVertex::observed;
    if (!missed[v]) {
      moved.push_back (result.displacement.col (i).norm ());
      observed_area += areas[i];
    }
  }
  for (std::size_t h = 0; h < holes.holes.size (); ++h)
    for (const int v : holes.vertices[h])
      holes.holes[h].max_fill = std::max (holes.holes[h].max_fill, result.displacement.col (v).norm ());
  stats.vertices = static_cast<int> (missed.size ());
  stats.observed = static_cast<int> (moved.size ());
  stats.filled = stats.vertices - stats.observed;
  stats.coverage = static_cast<double> (stats.observed) / stats.vertices;
  stats.median_displacement = moved.empty () ? 0.0 : median (moved);
  stats.observed_area = observed_area / areas.sum ();
  countFolds (reference_, result.mesh, holes, stats);
  stats.largest_hole_area = holes.holes.empty () ? 0.0 : holes.holes.front ().area / areas.sum ();
  stats.holes = std::move (holes.holes);
}
} // namespace morphreg

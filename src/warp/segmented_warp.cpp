// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/warp/segmented_warp.h>

#include <pcl/conversions.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace morphreg
{
namespace
{
/** 1 at distance 0, 0 at the blend width and beyond, with zero slope at both ends. */
double
falloff (double distance, double width)
{
  if (!(distance < width))
    return 0.0;
  const double t = distance / width;
  return 1.0 - t * t * (3.0 - 2.0 * t);
}

void
requireBlendWidth (double width)
{
  if (!(width >= 0.0) || !std::isfinite (width))
    throw InvalidInputError ("SegmentedWarp: blend width must be a finite number >= 0 (mm), got " +
                             std::to_string (width));
}

std::vector<int>
verticesWithLabel (const std::vector<int>& labels, int segment)
{
  std::vector<int> vertices;
  for (std::size_t v = 0; v < labels.size (); ++v)
    if (labels[v] == segment)
      vertices.push_back (static_cast<int> (v));
  return vertices;
}
} // namespace

SegmentedWarp::SegmentedWarp (std::vector<int> labels, int num_segments) : labels_ (std::move (labels))
{
  if (num_segments < 1)
    throw InvalidInputError ("SegmentedWarp: the number of segments must be at least 1");
  requireSegmentLabels (labels_, num_segments, "SegmentedWarp");
  splines_.resize (static_cast<std::size_t> (num_segments));
  blend_widths_.assign (static_cast<std::size_t> (num_segments), 0.0);
}

void
SegmentedWarp::requireSegment (int segment, const char* caller) const
{
  if (segment < 0 || segment >= numSegments ())
    throw InvalidInputError (std::string ("SegmentedWarp::") + caller + ": segment " + std::to_string (segment) +
                             " does not exist (there are " + std::to_string (numSegments ()) + ")");
}

void
SegmentedWarp::setSegmentLandmarks (int segment, const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target)
{
  requireSegment (segment, "setSegmentLandmarks");
  auto spline = std::make_unique<Spline> ();
  spline->setRegularization (regularization_);
  try {
    spline->fit (source, target);
  }
  catch (const InvalidInputError& e) {
    throw InvalidInputError ("SegmentedWarp: landmarks of segment " + std::to_string (segment) + ": " + e.what ());
  }
  catch (const NumericalError& e) {
    throw NumericalError ("SegmentedWarp: landmarks of segment " + std::to_string (segment) + ": " + e.what ());
  }
  splines_[static_cast<std::size_t> (segment)] = std::move (spline);
}

std::vector<std::vector<int>>
SegmentedWarp::setLandmarks (const TriangleMesh& mesh, const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                             const std::vector<double>& overlap)
{
  if (static_cast<int> (overlap.size ()) != numSegments ())
    throw InvalidInputError ("SegmentedWarp::setLandmarks: " + std::to_string (overlap.size ()) + " overlaps for " +
                             std::to_string (numSegments ()) + " segments");
  if (source.cols () != target.cols ())
    throw InvalidInputError ("SegmentedWarp::setLandmarks: " + std::to_string (source.cols ()) + " source but " +
                             std::to_string (target.cols ()) + " target landmarks");
  const std::vector<std::vector<int>> subsets = assignLandmarksToSegments (mesh, labels_, source, overlap);
  for (int s = 0; s < numSegments (); ++s) {
    const Eigen::Index count = static_cast<Eigen::Index> (subsets[s].size ());
    Eigen::Matrix3Xd from (3, count), to (3, count);
    for (Eigen::Index k = 0; k < count; ++k) {
      from.col (k) = source.col (subsets[s][k]);
      to.col (k) = target.col (subsets[s][k]);
    }
    setSegmentLandmarks (s, from, to);
  }
  return subsets;
}

const SegmentedWarp::Spline&
SegmentedWarp::segmentSpline (int segment) const
{
  requireSegment (segment, "segmentSpline");
  if (!splines_[static_cast<std::size_t> (segment)])
    throw InvalidInputError ("SegmentedWarp: segment " + std::to_string (segment) + " has no landmarks");
  return *splines_[static_cast<std::size_t> (segment)];
}

void
SegmentedWarp::setBlendWidth (double width)
{
  requireBlendWidth (width);
  std::fill (blend_widths_.begin (), blend_widths_.end (), width);
}

double
SegmentedWarp::getBlendWidth () const
{
  return *std::max_element (blend_widths_.begin (), blend_widths_.end ());
}

void
SegmentedWarp::setSegmentBlendWidth (int segment, double width)
{
  requireSegment (segment, "setSegmentBlendWidth");
  requireBlendWidth (width);
  blend_widths_[static_cast<std::size_t> (segment)] = width;
}

double
SegmentedWarp::getSegmentBlendWidth (int segment) const
{
  requireSegment (segment, "getSegmentBlendWidth");
  return blend_widths_[static_cast<std::size_t> (segment)];
}

void
SegmentedWarp::setRegularization (double lambda)
{
  Spline ().setRegularization (lambda); // validates
  regularization_ = lambda;
}

Eigen::MatrixXd
SegmentedWarp::blendWeights (const TriangleMesh& mesh) const
{
  validateMesh (mesh, "mesh to warp");
  if (mesh.numVertices () != static_cast<Eigen::Index> (labels_.size ()))
    throw InvalidInputError ("SegmentedWarp: the mesh has " + std::to_string (mesh.numVertices ()) +
                             " vertices but there are " + std::to_string (labels_.size ()) + " segment labels");
  Eigen::MatrixXd weights = Eigen::MatrixXd::Zero (mesh.numVertices (), numSegments ());
  for (std::size_t v = 0; v < labels_.size (); ++v)
    weights (static_cast<Eigen::Index> (v), labels_[v]) = 1.0;
  if (getBlendWidth () == 0.0)
    return weights;
  const MeshTopology topology (mesh);
  for (int s = 0; s < numSegments (); ++s) {
    const double width = blend_widths_[static_cast<std::size_t> (s)];
    const std::vector<int> members = verticesWithLabel (labels_, s);
    if (members.empty () || width == 0.0)
      continue;
    const std::vector<double> distance = topology.geodesicDistances (mesh.vertices, members, width);
    for (Eigen::Index v = 0; v < mesh.numVertices (); ++v)
      weights (v, s) = falloff (distance[static_cast<std::size_t> (v)], width);
  }
  // Every vertex is at distance 0 of its own segment, so each row has a weight of 1 before normalising.
  return weights.array ().colwise () / weights.rowwise ().sum ().array ();
}

TriangleMesh
SegmentedWarp::warp (const TriangleMesh& mesh) const
{
  const Eigen::MatrixXd weights = blendWeights (mesh);
  TriangleMesh warped = mesh;
  warped.vertices.setZero ();
  for (int s = 0; s < numSegments (); ++s) {
    std::vector<Eigen::Index> touched;
    for (Eigen::Index v = 0; v < mesh.numVertices (); ++v)
      if (weights (v, s) > 0.0)
        touched.push_back (v);
    if (touched.empty ())
      continue;
    const Spline& spline = segmentSpline (s);
    Eigen::Matrix3Xd positions (3, static_cast<Eigen::Index> (touched.size ()));
    for (std::size_t k = 0; k < touched.size (); ++k)
      positions.col (static_cast<Eigen::Index> (k)) = mesh.vertices.col (touched[k]);
    spline.transformPositions (positions);
    for (std::size_t k = 0; k < touched.size (); ++k)
      warped.vertices.col (touched[k]) += weights (touched[k], s) * positions.col (static_cast<Eigen::Index> (k));
  }
  return warped;
}

void
SegmentedWarp::warp (const pcl::PolygonMesh& input, pcl::PolygonMesh& output) const
{
  output = toPolygonMesh (warp (fromPolygonMesh (input, "mesh to warp")));
}

void
requireSegmentLabels (const std::vector<int>& labels, int num_segments, const std::string& owner)
{
  if (labels.empty ())
    throw InvalidInputError (owner + ": no segment labels");
  for (std::size_t v = 0; v < labels.size (); ++v)
    if (labels[v] < 0 || labels[v] >= num_segments)
      throw InvalidInputError (owner + ": vertex " + std::to_string (v) + " has segment label " +
                               std::to_string (labels[v]) + ", outside [0, " + std::to_string (num_segments) + ")");
}

std::vector<std::vector<int>>
assignLandmarksToSegments (const TriangleMesh& mesh, const std::vector<int>& labels, const Eigen::Matrix3Xd& landmarks,
                           const std::vector<double>& overlap)
{
  validateMesh (mesh, "segmented mesh");
  if (static_cast<Eigen::Index> (labels.size ()) != mesh.numVertices ())
    throw InvalidInputError ("assignLandmarksToSegments: " + std::to_string (labels.size ()) + " labels for " +
                             std::to_string (mesh.numVertices ()) + " vertices");
  const int num_segments = static_cast<int> (overlap.size ());
  for (double o : overlap)
    if (!(o >= 0.0))
      throw InvalidInputError ("assignLandmarksToSegments: overlap must be >= 0 (mm)");
  if (!landmarks.allFinite ())
    throw InvalidInputError ("assignLandmarksToSegments: a landmark is not finite");
  std::vector<std::vector<int>> subsets (overlap.size ());
  for (Eigen::Index i = 0; i < landmarks.cols (); ++i) {
    std::vector<double> nearest (overlap.size (), std::numeric_limits<double>::infinity ());
    for (Eigen::Index v = 0; v < mesh.numVertices (); ++v) {
      const int s = labels[static_cast<std::size_t> (v)];
      if (s < 0 || s >= num_segments)
        throw InvalidInputError ("assignLandmarksToSegments: vertex " + std::to_string (v) + " has label " +
                                 std::to_string (s));
      nearest[s] = std::min (nearest[s], (mesh.vertices.col (v) - landmarks.col (i)).squaredNorm ());
    }
    const double closest = std::sqrt (*std::min_element (nearest.begin (), nearest.end ()));
    for (int s = 0; s < num_segments; ++s)
      if (std::sqrt (nearest[s]) <= closest + overlap[s])
        subsets[s].push_back (static_cast<int> (i));
  }
  return subsets;
}

std::vector<std::vector<int>>
assignLandmarksToSegments (const TriangleMesh& mesh, const std::vector<int>& labels, int num_segments,
                           const Eigen::Matrix3Xd& landmarks, double overlap)
{
  if (num_segments < 1)
    throw InvalidInputError ("assignLandmarksToSegments: the number of segments must be at least 1");
  return assignLandmarksToSegments (mesh, labels, landmarks,
                                    std::vector<double> (static_cast<std::size_t> (num_segments), overlap));
}

} // namespace morphreg

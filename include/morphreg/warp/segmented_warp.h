// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file segmented_warp.h
 *  \brief Thin plate spline warping by segments (one spline per body part) recombined into one mesh, with the seams
 *  blended over a width measured along the mesh.
 */
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/warp/thin_plate_spline.h>

#include <pcl/PolygonMesh.h>

#include <memory>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief Warps a mesh segment by segment: every vertex has a segment label, every segment its own landmark pairs
 *  and its own 3D thin plate spline. The warped mesh keeps its topology. Near a border a vertex takes a weighted
 *  mix of the warps of the segments within the blend width (geodesic, over the mesh being warped); weights fall
 *  smoothly from 1 at a segment to 0 at the blend width from it and are normalised per vertex. A blend width of 0
 *  is the hard segmentation of the seed paper (each vertex follows its own segment only). The width can differ per
 *  segment (how far that segment's warp reaches into its neighbours): a segment that barely moves (the torso of a
 *  body being seated) can reach far into one that bends (the thigh, whose true deformation spreads over a wide zone
 *  below the hip), while the bending segment's warp, extrapolated beyond its landmarks, fades out quickly.
 *
 *  \code
 *  morphreg::SegmentedWarp warp (labels, 4);
 *  warp.setLandmarks (standing, joints_standing, joints_seated, {90.0, 90.0, 90.0, 90.0});   // overlap per segment
 *  warp.setBlendWidth (100.0);
 *  warp.setSegmentBlendWidth (2, 400.0);                                // the upper body reaches into the legs
 *  morphreg::TriangleMesh seated = warp.warp (standing);
 *  \endcode
 */
class SegmentedWarp
{
public:
  using Ptr = std::shared_ptr<SegmentedWarp>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const SegmentedWarp>; ///< shared pointer to const
  using Spline = ThinPlateSpline<double, 3>;             ///< one segment's warp

  /** \brief A warp for meshes whose vertices carry \a labels; no segment has landmarks yet.
   *  \param[in] labels the segment (0 .. num_segments - 1) of each vertex of the meshes this will warp
   *  \param[in] num_segments the number of segments
   */
  SegmentedWarp (std::vector<int> labels, int num_segments);

  /** \brief The number of segments.
   *  \return num_segments as given
   */
  int
  numSegments () const
  {
    return static_cast<int> (splines_.size ());
  }

  /** \brief Fits segment \a segment's spline to the landmark pairs (columns of \a source -> \a target, mm). Errors
   *  from the fit (too few or degenerate landmarks, ...) are rethrown naming the segment.
   *  \param[in] segment the segment index
   *  \param[in] source the source landmarks (3 x n, mm)
   *  \param[in] target the target landmarks (3 x n, mm)
   */
  void
  setSegmentLandmarks (int segment, const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target);

  /** \brief Shares the landmark pairs (columns of \a source -> \a target) out among the segments with
   *  assignLandmarksToSegments (\a overlap[s] mm for segment s, measured on \a mesh) and fits every segment's
   *  spline. Returns the column indices each segment received.
   *  \param[in] mesh the mesh in the source pose, labelled like the warp
   *  \param[in] source the source landmarks (3 x n, mm)
   *  \param[in] target the target landmarks (3 x n, mm)
   *  \param[in] overlap per segment: how much further (mm) than the nearest segment a landmark may be and still join
   *  \return per segment, the landmark columns it fitted on
   */
  std::vector<std::vector<int>>
  setLandmarks (const TriangleMesh& mesh, const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                const std::vector<double>& overlap);

  /** \brief The fitted spline of \a segment (throws InvalidInputError if it has no landmarks yet).
   *  \param[in] segment the segment index
   *  \return its spline
   */
  const Spline&
  segmentSpline (int segment) const;

  /** \brief Blend width in mm along the mesh (>= 0; 0 = hard segmentation), for every segment.
   *  \param[in] width the width (mm)
   */
  void
  setBlendWidth (double width);

  /** \brief The widest blend width of any segment (mm).
   *  \return the width (mm)
   */
  double
  getBlendWidth () const;

  /** \brief How far (mm along the mesh, >= 0) \a segment's warp reaches into the neighbouring segments; 0: not at
   *  all. Overrides setBlendWidth for this segment until setBlendWidth is called again.
   *  \param[in] segment the segment index
   *  \param[in] width the width (mm)
   */
  void
  setSegmentBlendWidth (int segment, double width);

  /** \brief How far \a segment's warp reaches into the neighbouring segments.
   *  \param[in] segment the segment index
   *  \return the width (mm)
   */
  double
  getSegmentBlendWidth (int segment) const;

  /** \brief Regularisation lambda of every segment's spline (see ThinPlateSpline::setRegularization); takes
   *  effect for landmarks set afterwards.
   *  \param[in] lambda the smoothing weight, >= 0
   */
  void
  setRegularization (double lambda);

  /** \brief Per-vertex blend weights (N x numSegments, rows sum to 1) for \a mesh.
   *  \param[in] mesh the mesh to be warped (geodesic distances are measured on it)
   *  \return the weights
   */
  Eigen::MatrixXd
  blendWeights (const TriangleMesh& mesh) const;

  /** \brief \a mesh warped (same triangles). Throws InvalidInputError if its vertex count differs from the labels
   *  or a segment that has vertices has no landmarks.
   *  \param[in] mesh the mesh to warp
   *  \return the warped mesh
   */
  TriangleMesh
  warp (const TriangleMesh& mesh) const;

  /** \brief As warp(TriangleMesh) for a pcl::PolygonMesh of triangles; vertex normals are recomputed.
   *  \param[in] input the mesh to warp
   *  \param[out] output the warped mesh
   */
  void
  warp (const pcl::PolygonMesh& input, pcl::PolygonMesh& output) const;

private:
  void
  requireSegment (int segment, const char* caller) const;

  std::vector<int> labels_;
  std::vector<std::unique_ptr<Spline>> splines_;
  std::vector<double> blend_widths_; ///< per segment (mm)
  double regularization_ = 0.0;
};

/** \brief Throws InvalidInputError naming \a owner if \a labels is empty or a label is outside [0, \a num_segments).
 *  \param[in] labels the segment of each vertex
 *  \param[in] num_segments the number of segments
 *  \param[in] owner who checks, for the message (e.g. "SegmentedWarp")
 */
void
requireSegmentLabels (const std::vector<int>& labels, int num_segments, const std::string& owner);

/** \brief Landmark subsets per segment: landmark i (a column of \a landmarks, e.g. joint centres inside the body)
 *  goes to the segment of its nearest vertex of \a mesh and to every other segment whose nearest vertex is at most
 *  \a overlap mm further away, so subsets overlap across borders. Returns the column indices per segment.
 *  \param[in] mesh the mesh in the landmarks' pose
 *  \param[in] labels the segment of each vertex
 *  \param[in] num_segments the number of segments
 *  \param[in] landmarks the landmarks (3 x n, mm)
 *  \param[in] overlap the extra distance (mm) within which a landmark joins further segments
 *  \return per segment, the landmark columns it takes
 */
std::vector<std::vector<int>>
assignLandmarksToSegments (const TriangleMesh& mesh, const std::vector<int>& labels, int num_segments,
                           const Eigen::Matrix3Xd& landmarks, double overlap);

/** \brief As above with an overlap per segment: landmark i joins segment s when its nearest vertex there is at most
 *  \a overlap[s] mm further away than its nearest vertex overall.
 *  \param[in] mesh the mesh in the landmarks' pose
 *  \param[in] labels the segment of each vertex
 *  \param[in] landmarks the landmarks (3 x n, mm)
 *  \param[in] overlap per segment, the extra distance (mm) within which a landmark joins it
 *  \return per segment, the landmark columns it takes
 */

std::vector<std::vector<int>>
assignLandmarksToSegments (const TriangleMesh& mesh, const std::vector<int>& labels, const Eigen::Matrix3Xd& landmarks,
                           const std::vector<double>& overlap);

} // namespace morphreg

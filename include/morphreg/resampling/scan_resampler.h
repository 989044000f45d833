// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file scan_resampler.h
 *  \brief A raw scan brought into a reference topology (docs/method.md, "Raw scans"): every reference vertex moved
 *  along its normal onto the scan's surface, the misses filled by thin plate splines from the rings around each hole.
 */
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/resampling/resampling_settings.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <memory>
#include <vector>

namespace morphreg
{
class MeshTopology;
namespace detail
{
class ScanSurface;
struct Holes;
} // namespace detail

/** \brief Where a resampled vertex came from. */
enum class ResampledVertex : unsigned char
{
  observed, ///< moved onto the scan along its normal ray
  filled    ///< its ray missed the scan; interpolated from the observed rings around its hole
};

/** \brief One connected set of missed vertices and how it was filled. */
struct ResamplingHole
{
  int vertices = 0;         ///< missed vertices in the hole
  double area = 0.0;        ///< the reference surface it covers (mm^2; a third of each adjacent triangle)
  int ring_vertices = 0;    ///< observed vertices the thin plate spline was fitted to
  double max_fill = 0.0;    ///< largest displacement of a filled vertex (mm)
  int folded_triangles = 0; ///< triangles touching the hole whose normal turned by more than 90 degrees
};

/** \brief The counts a report needs. */
struct ResamplingStatistics
{
  int vertices = 0;                  ///< reference vertices
  int observed = 0;                  ///< vertices moved onto the scan
  int filled = 0;                    ///< vertices filled by the holes' thin plate splines
  double coverage = 0.0;             ///< observed / vertices
  double observed_area = 0.0;        ///< share of the reference's surface area observed (0-1)
  double largest_hole_area = 0.0;    ///< share of the reference's surface area in the largest hole (0-1)
  int folded_triangles = 0;          ///< triangles whose normal turned by more than 90 degrees against the reference
  double median_displacement = 0.0;  ///< median |displacement| of the observed vertices (mm)
  double ray_seconds = 0.0;          ///< time spent casting the rays
  double fill_seconds = 0.0;         ///< time spent filling the holes
  std::vector<ResamplingHole> holes; ///< the holes, largest (by area) first
};

/** \brief The reference in the scan's detail: same vertices and triangles, new positions. */
struct ResamplingResult
{
  TriangleMesh mesh;                  ///< the resampled mesh (the reference's triangles)
  std::vector<ResampledVertex> state; ///< per vertex: observed or filled
  Eigen::Matrix3Xd displacement;      ///< per vertex: resampled minus reference position (mm)
  ResamplingStatistics statistics;    ///< coverage and holes
};

/** \brief Moves each vertex of a reference mesh (in the reference's topology, already close to the scan: a
 *  MorphableICP fit, or a template warped from landmarks) to the intersection of its normal line with the scan's
 *  surface nearest to it, in either direction within setMaxDistance, where the surface's normal agrees with the
 *  vertex's (setNormalAgreement); vertices without one are misses, and so are hits whose displacement breaks away
 *  from their neighbours' (setMaxJump). The misses form holes (connected over the
 *  reference's edges); each hole's displacement is a thin plate spline interpolating the displacements of the
 *  observed vertices in setRingWidth rings around it, so the fill meets its border without a step.
 *
 *  The scan is a triangle mesh (rays cast through Intel Embree) or a point cloud: there the ray meets the
 *  Gaussian-weighted plane of the setNeighbours scan points nearest to it, iterated to the hit, and the hit counts
 *  only within 1.5 local point spacings of the nearest scan point (so rays leaving through a hole miss). Given cloud
 *  normals make the plane's normal and take part in the agreement test; without them the plane's unoriented normal
 *  is used. Hits whose triangle they turn over are misses too.
 *
 *  Bad input is an InvalidInputError, never a mesh with NaN: a scan whose size is far from the reference's (another
 *  unit), no vertex meeting the scan, or a hole covering more than setMaxHoleFraction of the reference's area.
 *  \code
 *  morphreg::ScanResampler resampler;
 *  resampler.setInputReference (fitted);  // the MorphableICP fit, in the scan's frame (mm)
 *  resampler.setInputScan (scan_cloud);   // builds the search structure
 *  resampler.setMaxDistance (5.0);
 *  const morphreg::ResamplingResult result = resampler.resample ();
 *  \endcode
 */
class ScanResampler
{
public:
  using Ptr = std::shared_ptr<ScanResampler>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const ScanResampler>; ///< shared pointer to const

  /** \brief A resampler with the default settings and no inputs. */
  ScanResampler ();

  /** \brief Releases the scan's search structure. */
  ~ScanResampler ();

  ScanResampler (const ScanResampler&) = delete; ///< not copyable (owns the scan's search structure)
  ScanResampler&
  operator= (const ScanResampler&) = delete; ///< not copyable (owns the scan's search structure)

  /** \brief The reference mesh in the scan's frame (validated; mm); its vertex normals are the ray directions.
   *  \param[in] reference the mesh whose topology the result keeps
   */
  void
  setInputReference (const TriangleMesh& reference);

  /** \brief A scan point cloud with normals (non-finite normals count as unknown); NaN points are dropped.
   *  Throws InvalidInputError if fewer than setNeighbours finite points remain.
   *  \param[in] scan the scan (mm)
   */
  void
  setInputScan (const pcl::PointCloud<pcl::PointNormal>& scan);

  /** \brief A scan point cloud without normals; NaN points are dropped.
   *  \param[in] scan the scan (mm)
   */
  void
  setInputScan (const pcl::PointCloud<pcl::PointXYZ>& scan);

  /** \brief A triangulated scan (validated; counter-clockwise triangles face outwards); builds the ray locator.
   *  \param[in] scan the scan mesh (mm)
   */
  void
  setInputScan (const TriangleMesh& scan);

  /** \brief Every setting at once (checked: requireValidSettings); the setters below change one each.
   *  \param[in] settings the settings, by the command line's names
   */
  void
  setSettings (const ResamplingSettings& settings);

  /** \brief The settings.
   *  \return every setting
   */
  const ResamplingSettings&
  getSettings () const
  {
    return settings_;
  }

  /** \brief The farthest a vertex may move along its normal (mm, > 0; default 5).
   *  \param[in] distance the search distance in both directions
   */
  void
  setMaxDistance (double distance);

  /** \brief The search distance along the normals.
   *  \return mm
   */
  double
  getMaxDistance () const
  {
    return settings_.ray_distance;
  }

  /** \brief The largest angle between a vertex normal and the scan's normal at the hit (degrees in (0, 180];
   *  default 60); hits beyond it are skipped (the ray may go on to a farther one).
   *  \param[in] degrees the angle
   */
  void
  setNormalAgreement (double degrees);

  /** \brief The normal agreement angle.
   *  \return degrees
   */
  double
  getNormalAgreement () const
  {
    return settings_.normal_agreement;
  }

  /** \brief Rings of observed vertices around each hole that its thin plate spline interpolates (>= 1; default 3).
   *  \param[in] rings more rings carry the border's slope further into the fill
   */
  void
  setRingWidth (int rings);

  /** \brief The ring width.
   *  \return rings
   */
  int
  getRingWidth () const
  {
    return settings_.ring_width;
  }

  /** \brief The largest share of the reference's surface area one hole may cover (in (0, 1]; default 0.5).
   *  \param[in] fraction beyond it resample() throws: the scan covers too little for a fill to mean anything
   */
  void
  setMaxHoleFraction (double fraction);

  /** \brief The largest hole share.
   *  \return the fraction of the reference's area
   */
  double
  getMaxHoleFraction () const
  {
    return settings_.max_hole_fraction;
  }

  /** \brief Scan points a point cloud's local plane is weighted over (>= 4; default 24; the Gaussian weights' bandwidth
   *  is the local spacing, so the 24th point has almost none); takes effect at the next setInputScan.
   *  \param[in] k the neighbourhood size: fewer cut the weights off sooner, and the planes jump along a ray
   */
  void
  setNeighbours (int k);

  /** \brief The neighbourhood size.
   *  \return k
   */
  int
  getNeighbours () const
  {
    return settings_.neighbours;
  }

  /** \brief The largest difference (mm, > 0; default 1) between a hit's displacement along the normal and the median
   *  of its observed neighbours'; a hit beyond it (a ray that met another surface, or a plane tilted by outliers) is
   *  treated as a miss and filled.
   *  \param[in] jump the largest accepted step of the displacement field between neighbours
   */
  void
  setMaxJump (double jump);

  /** \brief The largest accepted step of the displacement field.
   *  \return mm
   */
  double
  getMaxJump () const
  {
    return settings_.max_jump;
  }

  /** \brief Resampling passes (>= 1; default 3). Each pass after the first starts from the previous one's mesh and
   *  casts rays only from its filled vertices: a fill lies closer to the scan than the reference did and its normal
   *  agrees better with the scan's, so more of it is observed (on the real Lee Perry-Smith scan, 86.5 % of ICT's face
   *  in one pass, 91.8 % in three, with fewer folds).
   *  \param[in] passes 1 resamples the reference once
   */
  void
  setPasses (int passes);

  /** \brief The resampling passes.
   *  \return passes
   */
  int
  getPasses () const
  {
    return settings_.passes;
  }

  /** \brief The smoothing weight of the hole fills' thin plate splines (>= 0, mm; default 1; see
   *  ThinPlateSpline::setRegularization): 0 interpolates the ring's noise exactly.
   *  \param[in] lambda the weight
   */
  void
  setFillRegularization (double lambda);

  /** \brief The fills' smoothing weight.
   *  \return lambda
   */
  double
  getFillRegularization () const
  {
    return settings_.fill_smoothing;
  }

  /** \brief Casts the rays and fills the holes; throws InvalidInputError when an input is missing or bad (see the
   *  class description).
   *  \return the resampled mesh, per-vertex state and displacement, and the statistics
   */
  ResamplingResult
  resample () const;

private:
  /** Observed positions along the rays from \a origins with \a normals, for the vertices marked in \a cast (NaN for
   *  misses); the others keep their origin. */
  Eigen::Matrix3Xd
  castRays (const Eigen::Matrix3Xd& origins, const Eigen::Matrix3Xd& normals, const std::vector<char>& cast) const;

  /** One pass from \a result's mesh: rays from the \a missed vertices, the checks, the fills; updates \a missed and
   *  \a result's mesh and timings.
   *  \return the holes filled */
  detail::Holes
  resamplePass (const MeshTopology& topology, const Eigen::VectorXd& areas, std::vector<char>& missed,
                ResamplingResult& result) const;

  /** Completes \a result's displacement, states and statistics after the last pass. */
  void
  summarise (const std::vector<char>& missed, const Eigen::VectorXd& areas, detail::Holes& holes,
             ResamplingResult& result) const;

  TriangleMesh reference_;
  std::unique_ptr<detail::ScanSurface> surface_;
  ResamplingSettings settings_;
};
} // namespace morphreg

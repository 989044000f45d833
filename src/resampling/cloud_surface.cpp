// SPDX-License-Identifier: BSD-3-Clause
// A point cloud scan as ScanResampler's surface: the ray meets the Gaussian-weighted plane of the scan points nearest
// to it (a point set surface, as in Adamson and Alexa 2003), found through a grid of the points (point_grid.h).
// Measured against triangulating the same scans first (bench/RESULTS.md, "Scan resampling"), the local planes need no
// triangulation step and average the range noise over k points where a mesh's triangles keep it.
#include "point_grid.h"
#include "scan_surface.h"

#include <morphreg/common/order_statistics.h>

#include <pcl/kdtree/kdtree_flann.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace morphreg
{
namespace detail
{
namespace
{
constexpr int kMaxSteps = 20;              ///< plane refits along the ray before giving up
constexpr double kConverged = 0.02;        ///< mm: the hit moved less than this in the last refit
constexpr double kMinIncidence = 0.2;      ///< |cos| between the ray and the plane normal below which the ray misses
constexpr int kSpacingNeighbour = 4;       ///< the local spacing: the distance to a point's 4th nearest other point
constexpr double kSpacingFactor = 1.5;     ///< a hit farther than this many local spacings from every scan point misses
constexpr double kMaxOffCentre = 1.0;      ///< of the bandwidth: a hit farther from the plane's centroid misses
constexpr double kTrim = 3.0;              ///< plane points beyond this many median distances from it are dropped
constexpr double kTrimFloor = 1e-3;        ///< mm, so exactly planar neighbourhoods keep every point
constexpr double kMinNormalLength = 0.5;   ///< the weighted mean of the given normals is kept if at least this long
constexpr double kCoveredBandwidths = 2.0; ///< neighbours are searched again when farther ones could weigh more than
                                           ///< exp(-4) of the nearest
constexpr double kSparsest = 4.0;          ///< rays search up to this many usual k-th neighbour distances beyond their
                                           ///< reach: a scan 4 times sparser than its median still has hits

/** A plane through a weighted centroid; its normal's sign is known when it came from the scan's normals. */
struct OrientedPlane
{
  Eigen::Vector3d centroid;
  Eigen::Vector3d normal;
  bool oriented;
};

/** The scan points around a ray's point, gathered once per search: positions, normals (zero where unknown) and
 *  whether each has one. */
struct Neighbourhood
{
  Eigen::Matrix3Xd points;
  Eigen::Matrix3Xd normals;
  Eigen::VectorXd has_normal;
  Eigen::VectorXd spacing; ///< each point's local spacing
};

class CloudSurface : public ScanSurface
{
public:
  CloudSurface (Eigen::Matrix3Xd points, Eigen::Matrix3Xd normals, int neighbours)
    : points_ (std::move (points)), normals_ (std::move (normals)), neighbours_ (neighbours),
      spacing_ (localSpacings (points_)), usual_kth_ (usualKthDistance (spacing_, neighbours)),
      grid_ (points_, 0.5 * usual_kth_)
  {}

  /** Newton's iteration on the smooth surface the Gaussian-weighted local planes define (a point set surface): the
   *  ray's point moves to where it meets the plane of the points around it, with one bandwidth for the whole ray, so
   *  that the planes change continuously along it and the iteration settles. The neighbours found at one point serve
   *  the next ones while every point within kCoveredBandwidths bandwidths of them is sure to be among them. */
  bool
  intersect (const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double max_distance, double min_cos,
             Eigen::Vector3d& hit) const override
  {
    double t = 0.0, bandwidth = 0.0, reach = 0.0;
    Eigen::Vector3d searched_at;
    Neighbourhood around;
    for (int step = 0; step < kMaxSteps; ++step) {
      const Eigen::Vector3d at = origin + t * direction;
      if (step == 0 || (at - searched_at).norm () > reach) {
        const double kth = gather (at, max_distance + kSparsest * usual_kth_, around);
        if (!std::isfinite (kth))
          return false; // no k scan points near enough for a hit
        if (step == 0)
          bandwidth = median (around.spacing); // the Gaussian weights' bandwidth, one along the ray
        searched_at = at;
        reach = std::sqrt (kth) - kCoveredBandwidths * bandwidth;
      }
      const OrientedPlane plane = localPlane (around, at, bandwidth);
      const double incidence = plane.normal.dot (direction);
      if (std::abs (incidence) < kMinIncidence)
        return false;
      const double next = (plane.centroid - origin).dot (plane.normal) / incidence;
      if (std::abs (next) > max_distance)
        return false;
      const bool converged = std::abs (next - t) < kConverged;
      t = next;
      if (converged)
        return accept (origin + t * direction, around, bandwidth, direction, plane, min_cos, hit);
    }
    return false;
  }

  const Eigen::Matrix3Xd&
  points () const override
  {
    return points_;
  }

  bool
  threadSafe () const override
  {
    return true; // grid searches are const
  }

private:
  /** The k nearest scan points to \a at, if they lie within \a max_radius; returns the k-th's squared distance
   *  (infinity, and \a around untouched, if they do not). */
  double
  gather (const Eigen::Vector3d& at, double max_radius, Neighbourhood& around) const
  {
    thread_local std::vector<int> indices;
    thread_local std::vector<double> distances;
    const double kth = grid_.nearestK (at, neighbours_, max_radius, indices, distances);
    if (indices.empty ())
      return kth;
    const auto k = static_cast<Eigen::Index> (indices.size ());
    around.points.resize (3, k);
    around.normals.resize (3, k);
    around.has_normal.resize (k);
    around.spacing.resize (k);
    for (Eigen::Index j = 0; j < k; ++j) {
      around.points.col (j) = points_.col (indices[j]);
      const bool known = normals_.cols () > 0 && normals_.col (indices[j]).allFinite ();
      around.normals.col (j) = known ? Eigen::Vector3d (normals_.col (indices[j])) : Eigen::Vector3d::Zero ();
      around.has_normal[j] = known ? 1.0 : 0.0;
      around.spacing[j] = spacing_[indices[j]];
    }
    return kth;
  }

  /** The plane of the points \a around weighted by exp(-d^2 / bandwidth^2), d their distance to \a at, refitted
   *  without those farther from it than kTrim times the median distance (outliers, another surface's points). Its
   *  normal is the weighted mean of the scan's normals where they agree, else the weighted covariance's least
   *  direction (unoriented). */
  static OrientedPlane
  localPlane (const Neighbourhood& around, const Eigen::Vector3d& at, double bandwidth)
  {
    const Eigen::ArrayXd squared = (around.points.colwise () - at).colwise ().squaredNorm ().transpose ();
    // relative to the nearest: no underflow far from the scan
    const Eigen::VectorXd weights = (-(squared - squared.minCoeff ()) / (bandwidth * bandwidth)).exp ().matrix ();
    const OrientedPlane plane = weightedPlane (around, weights);
    const Eigen::ArrayXd residuals =
        ((around.points.colwise () - plane.centroid).transpose () * plane.normal).array ().abs ();
    const double limit = kTrim * median (residuals.matrix ()) + kTrimFloor;
    const Eigen::Index count = (residuals <= limit).count ();
    return count >= 4 && count < residuals.size () ? weightedPlane (around, (residuals <= limit).select (weights, 0.0))
                                                   : plane;
  }

  static OrientedPlane
  weightedPlane (const Neighbourhood& around, const Eigen::VectorXd& weights)
  {
    const Eigen::Vector3d centroid = around.points * weights / weights.sum ();
    const Eigen::Vector3d given = around.normals * weights;
    const double given_weight = around.has_normal.dot (weights);
    if (given_weight > 0.0 && given.norm () >= kMinNormalLength * given_weight)
      return {centroid, given.normalized (), true};
    const Eigen::Matrix3Xd centred = around.points.colwise () - centroid;
    const Eigen::Matrix3d covariance = centred * weights.asDiagonal () * centred.transpose ();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (covariance);
    return {centroid, solver.eigenvectors ().col (0), false};
  }

  /** The hit \a point counts if it lies within kSpacingFactor local spacings (\a bandwidth, the median of the
   *  neighbourhood's: one point's own varies twofold on a random sampling) of its nearest scan point among
   *  \a around (no hole between), within \a bandwidth of its plane's centroid along the plane (not beyond a scan
   *  border, on a plane extrapolated from one side) and the plane's normal agrees with the ray's. */
  static bool
  accept (const Eigen::Vector3d& point, const Neighbourhood& around, double bandwidth, const Eigen::Vector3d& direction,
          const OrientedPlane& plane, double min_cos, Eigen::Vector3d& hit)
  {
    const double nearest = std::sqrt ((around.points.colwise () - point).colwise ().squaredNorm ().minCoeff ());
    if (nearest > kSpacingFactor * bandwidth)
      return false;
    const Eigen::Vector3d off_centre = point - plane.centroid;
    if ((off_centre - off_centre.dot (plane.normal) * plane.normal).norm () > kMaxOffCentre * bandwidth)
      return false;
    const double agreement = plane.normal.dot (direction);
    if ((plane.oriented ? agreement : std::abs (agreement)) < min_cos)
      return false;
    hit = point;
    return true;
  }

  Eigen::Matrix3Xd points_;
  Eigen::Matrix3Xd normals_;
  int neighbours_;
  std::vector<double> spacing_; ///< per point: the distance to its kSpacingNeighbour-th nearest other point
  double usual_kth_;            ///< mm: the median spacing's k-th neighbour distance, sqrt(k) / 2 spacings
  PointGrid grid_;
};
} // namespace

// The spacings come from a k-d tree, searched on both cores.
std::vector<double>
localSpacings (const Eigen::Matrix3Xd& points)
{
  auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
  cloud->resize (points.cols ());
  for (Eigen::Index i = 0; i < points.cols (); ++i)
    (*cloud)[i].getVector3fMap () = points.col (i).cast<float> ();
  pcl::KdTreeFLANN<pcl::PointXYZ> tree;
  tree.setInputCloud (cloud);
  std::vector<double> spacing (points.cols ());
#pragma omp parallel for schedule(static)
  for (Eigen::Index i = 0; i < points.cols (); ++i) {
    pcl::Indices indices;
    std::vector<float> distances;
    const int found = tree.nearestKSearch ((*cloud)[i], kSpacingNeighbour + 1, indices, distances);
    spacing[i] = std::sqrt (distances[found - 1]);
  }
  return spacing;
}

double
usualKthDistance (const std::vector<double>& spacings, int neighbours)
{
  return 0.5 * std::sqrt (double (neighbours)) * median (spacings);
}

std::unique_ptr<ScanSurface>
makeCloudSurface (Eigen::Matrix3Xd points, Eigen::Matrix3Xd normals, int neighbours)
{
  return std::make_unique<CloudSurface> (std::move (points), std::move (normals), neighbours);
}
} // namespace detail
} // namespace morphreg

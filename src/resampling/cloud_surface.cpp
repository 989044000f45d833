// A point cloud scan as ScanResampler's surface: the ray meets the Gaussian-weighted plane of the scan points nearest
// to it (a point set surface, as in Adamson and Alexa 2003). Measured against triangulating the same scans first (bench/RESULTS.md, "Scan resampling"), the local planes
// need no triangulation step and average the range noise over k points where a mesh's triangles keep it.
#include "scan_surface.h"

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

/** A plane through a weighted centroid; its normal's sign is known when it came from the scan's normals. */
struct OrientedPlane
{
  Eigen::Vector3d centroid;
  Eigen::Vector3d normal;
  bool oriented;
};

class CloudSurface : public ScanSurface
{
public:
  CloudSurface (Eigen::Matrix3Xd points, Eigen::Matrix3Xd normals, int neighbours)
    : points_ (std::move (points)), normals_ (std::move (normals)), neighbours_ (neighbours)
  {
    auto cloud = pcl::make_shared<pcl::PointCloud<pcl::PointXYZ>> ();
    cloud->resize (points_.cols ());
    for (Eigen::Index i = 0; i < points_.cols (); ++i)
      (*cloud)[i].getVector3fMap () = points_.col (i).cast<float> ();
    tree_.setInputCloud (cloud);
    spacing_.resize (points_.cols ());
#pragma omp parallel for schedule(static)
    for (Eigen::Index i = 0; i < points_.cols (); ++i) {
      pcl::Indices indices;
      std::vector<float> distances;
      const int found = tree_.nearestKSearch ((*cloud)[i], kSpacingNeighbour + 1, indices, distances);
      spacing_[i] = std::sqrt (distances[found - 1]);
    }
  }

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
    pcl::Indices indices;
    std::vector<float> distances;
    for (int step = 0; step < kMaxSteps; ++step) {
      const Eigen::Vector3d at = origin + t * direction;
      if (step == 0 || (at - searched_at).norm () > reach) {
        pcl::PointXYZ query;
        query.getVector3fMap () = at.cast<float> ();
        tree_.nearestKSearch (query, neighbours_, indices, distances);
        if (step == 0)
          bandwidth = medianSpacing (indices);
        searched_at = at;
        reach = std::sqrt (distances.back ()) - kCoveredBandwidths * bandwidth;
      }
      const OrientedPlane plane = localPlane (indices, at, bandwidth);
      const double incidence = plane.normal.dot (direction);
      if (std::abs (incidence) < kMinIncidence)
        return false;
      const double next = (plane.centroid - origin).dot (plane.normal) / incidence;
      if (std::abs (next) > max_distance)
        return false;
      const bool converged = std::abs (next - t) < kConverged;
      t = next;
      if (converged)
        return accept (origin + t * direction, indices, bandwidth, direction, plane, min_cos, hit);
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
    return true; // k-d tree searches are const
  }

private:
  /** The median local spacing of the scan points \a indices: the Gaussian weights' bandwidth along one ray. */
  double
  medianSpacing (const pcl::Indices& indices) const
  {
    std::vector<double> spacings (indices.size ());
    for (std::size_t k = 0; k < indices.size (); ++k)
      spacings[k] = spacing_[indices[k]];
    std::nth_element (spacings.begin (), spacings.begin () + spacings.size () / 2, spacings.end ());
    return spacings[spacings.size () / 2];
  }

  /** The plane of the points \a indices weighted by exp(-d^2 / bandwidth^2), d their distance to \a at, refitted
   *  without those farther from it than kTrim times the median distance (outliers, another surface's points). Its
   *  normal is the weighted mean of the scan's normals where they agree, else the weighted covariance's least
   *  direction (unoriented). */
  OrientedPlane
  localPlane (const pcl::Indices& indices, const Eigen::Vector3d& at, double bandwidth) const
  {
    Eigen::VectorXd squared (indices.size ());
    for (std::size_t k = 0; k < indices.size (); ++k)
      squared[k] = (points_.col (indices[k]) - at).squaredNorm ();
    // relative to the nearest: no underflow far from the scan
    const Eigen::VectorXd weights =
        (-(squared.array () - squared.minCoeff ()) / (bandwidth * bandwidth)).exp ().matrix ();
    OrientedPlane plane = weightedPlane (indices, weights);
    Eigen::VectorXd residuals (indices.size ());
    for (std::size_t k = 0; k < indices.size (); ++k)
      residuals[k] = std::abs ((points_.col (indices[k]) - plane.centroid).dot (plane.normal));
    std::vector<double> sorted (residuals.data (), residuals.data () + residuals.size ());
    std::nth_element (sorted.begin (), sorted.begin () + sorted.size () / 2, sorted.end ());
    const double limit = kTrim * sorted[sorted.size () / 2] + kTrimFloor;
    const Eigen::VectorXd kept = (residuals.array () <= limit).select (weights, 0.0);
    const Eigen::Index count = (residuals.array () <= limit).count ();
    return count >= 4 && count < residuals.size () ? weightedPlane (indices, kept) : plane;
  }

  OrientedPlane
  weightedPlane (const pcl::Indices& indices, const Eigen::VectorXd& weights) const
  {
    Eigen::Vector3d centroid = Eigen::Vector3d::Zero (), given = Eigen::Vector3d::Zero ();
    double given_weight = 0.0;
    for (std::size_t k = 0; k < indices.size (); ++k) {
      centroid += weights[k] * points_.col (indices[k]);
      if (normals_.cols () > 0 && normals_.col (indices[k]).allFinite ()) {
        given += weights[k] * normals_.col (indices[k]);
        given_weight += weights[k];
      }
    }
    centroid /= weights.sum ();
    if (given_weight > 0.0 && given.norm () >= kMinNormalLength * given_weight)
      return {centroid, given.normalized (), true};
    Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero ();
    for (std::size_t k = 0; k < indices.size (); ++k) {
      const Eigen::Vector3d d = points_.col (indices[k]) - centroid;
      covariance += weights[k] * d * d.transpose ();
    }
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver (covariance);
    return {centroid, solver.eigenvectors ().col (0), false};
  }

  /** The hit \a point counts if it lies within kSpacingFactor local spacings (\a bandwidth, the median of the
   *  neighbourhood's: one point's own varies twofold on a random sampling) of its nearest scan point among
   *  \a indices (no hole between), within \a bandwidth of its plane's centroid along the plane (not beyond a scan
   *  border, on a plane extrapolated from one side) and the plane's normal agrees with the ray's. */
  bool
  accept (const Eigen::Vector3d& point, const pcl::Indices& indices, double bandwidth, const Eigen::Vector3d& direction,
          const OrientedPlane& plane, double min_cos, Eigen::Vector3d& hit) const
  {
    double nearest = std::numeric_limits<double>::infinity ();
    for (const int index : indices)
      nearest = std::min (nearest, (point - points_.col (index)).norm ());
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
  pcl::KdTreeFLANN<pcl::PointXYZ> tree_;
  std::vector<double> spacing_;
};
} // namespace

std::unique_ptr<ScanSurface>
makeCloudSurface (Eigen::Matrix3Xd points, Eigen::Matrix3Xd normals, int neighbours)
{
  return std::make_unique<CloudSurface> (std::move (points), std::move (normals), neighbours);
}
} // namespace detail
} // namespace morphreg

// A point cloud scan as ScanResampler's surface: the ray meets the least-squares plane of the scan points nearest to
// it. Measured against triangulating the same scans first (bench/RESULTS.md, "Scan resampling"), the local planes
// need no triangulation step and average the range noise over k points where a mesh's triangles keep it.
#include "scan_surface.h"

#include <morphreg/mesh/mesh_normals.h>

#include <pcl/kdtree/kdtree_flann.h>

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
constexpr int kMaxSteps = 6;           ///< plane refits along the ray before giving up
constexpr double kConverged = 0.01;    ///< mm: the hit moved less than this in the last refit
constexpr double kMinIncidence = 0.2;  ///< |cos| between the ray and the plane normal below which the ray misses
constexpr int kSpacingNeighbour = 4;   ///< the local spacing: the distance to a point's 4th nearest other point
constexpr double kSpacingFactor = 1.5; ///< a hit farther than this many spacings from every scan point misses
constexpr double kMaxOffCentre = 0.4;  ///< of the neighbourhood's radius: farther from its centroid, the hit misses
constexpr double kTrim = 3.0;          ///< plane points beyond this many median distances from it are dropped
constexpr double kTrimFloor = 1e-3;    ///< mm, so exactly planar neighbourhoods keep every point

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

  bool
  intersect (const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double max_distance, double min_cos,
             Eigen::Vector3d& hit) const override
  {
    double t = 0.0;
    pcl::Indices indices;
    std::vector<float> distances;
    for (int step = 0; step < kMaxSteps; ++step) {
      const Eigen::Vector3d at = origin + t * direction;
      pcl::PointXYZ query;
      query.getVector3fMap () = at.cast<float> ();
      tree_.nearestKSearch (query, neighbours_, indices, distances);
      const OrientedPlane plane = localPlane (indices);
      const double incidence = plane.normal.dot (direction);
      if (std::abs (incidence) < kMinIncidence)
        return false;
      const double next = (plane.centroid - origin).dot (plane.normal) / incidence;
      if (std::abs (next) > max_distance)
        return false;
      const bool converged = std::abs (next - t) < kConverged;
      t = next;
      if (converged)
        return accept (origin + t * direction, indices.front (), std::sqrt (distances.back ()), direction, plane,
                       min_cos, hit);
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
  struct OrientedPlane : PointPlane
  {
    bool oriented; ///< the normal's sign comes from the scan's normals (else it is arbitrary)
  };

  /** The least-squares plane of \a points refitted without those farther from it than kTrim times the median
   *  distance (outliers, another surface's points), if at least 4 remain. */
  static PointPlane
  trimmedPlane (const Eigen::Matrix3Xd& points)
  {
    const PointPlane plane = fitPlane (points);
    const Eigen::VectorXd distances = ((points.colwise () - plane.centroid).transpose () * plane.normal).cwiseAbs ();
    std::vector<double> sorted (distances.data (), distances.data () + distances.size ());
    std::nth_element (sorted.begin (), sorted.begin () + sorted.size () / 2, sorted.end ());
    const double limit = kTrim * sorted[sorted.size () / 2] + kTrimFloor;
    Eigen::Matrix3Xd kept (3, points.cols ());
    Eigen::Index count = 0;
    for (Eigen::Index k = 0; k < points.cols (); ++k)
      if (distances[k] <= limit)
        kept.col (count++) = points.col (k);
    return count >= 4 && count < points.cols () ? fitPlane (kept.leftCols (count)) : plane;
  }

  /** The plane of the points \a indices, its normal oriented by the points' given normals where they have any. */
  OrientedPlane
  localPlane (const pcl::Indices& indices) const
  {
    Eigen::Matrix3Xd neighbourhood (3, indices.size ());
    Eigen::Vector3d given = Eigen::Vector3d::Zero ();
    for (std::size_t k = 0; k < indices.size (); ++k) {
      neighbourhood.col (k) = points_.col (indices[k]);
      if (normals_.cols () > 0 && normals_.col (indices[k]).allFinite ())
        given += normals_.col (indices[k]);
    }
    OrientedPlane plane{trimmedPlane (neighbourhood), given.squaredNorm () > 0.0};
    if (plane.oriented && plane.normal.dot (given) < 0.0)
      plane.normal = -plane.normal;
    return plane;
  }

  /** The hit \a point counts if it lies within the local spacing of the scan point \a nearest (no hole between), near
   *  the middle of the neighbourhood of \a radius its plane was fitted to (not beyond a scan border, on a plane
   *  extrapolated from one side) and the plane's normal agrees with the ray's. */
  bool
  accept (const Eigen::Vector3d& point, int nearest, double radius, const Eigen::Vector3d& direction,
          const OrientedPlane& plane, double min_cos, Eigen::Vector3d& hit) const
  {
    if ((point - points_.col (nearest)).norm () > kSpacingFactor * spacing_[nearest])
      return false;
    const Eigen::Vector3d off_centre = point - plane.centroid;
    if ((off_centre - off_centre.dot (plane.normal) * plane.normal).norm () > kMaxOffCentre * radius)
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

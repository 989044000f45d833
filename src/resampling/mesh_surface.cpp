// SPDX-License-Identifier: BSD-3-Clause
// A triangulated scan as ScanResampler's surface. The rays go through Intel Embree's BVH: against VTK's locators on
// the same rays (bench/RESULTS.md, "Scan resampling") it answers them many times faster, and its queries are
// thread-safe, so the vertices' rays run in parallel.
#include "embree_scene.h"
#include "scan_surface.h"

#include <morphreg/mesh/mesh_normals.h>

#include <cmath>
#include <limits>
#include <memory>

namespace morphreg
{
namespace detail
{
namespace
{
/** Hits whose normals disagree are stepped over; a ray crossing more surfaces than this within its reach misses. */
constexpr int kMaxCrossings = 8;

class MeshSurface : public ScanSurface
{
public:
  explicit MeshSurface (const TriangleMesh& scan)
    : points_ (scan.vertices), face_normals_ (faceNormals (scan)), embree_ (scan)
  {}

  bool
  intersect (const Eigen::Vector3d& origin, const Eigen::Vector3d& direction, double max_distance, double min_cos,
             Eigen::Vector3d& hit) const override
  {
    double best = max_distance;
    bool found = false;
    for (const double sign : {1.0, -1.0}) {
      double reach = best;
      if (firstAgreeing (origin, sign * direction, direction, min_cos, reach)) {
        best = reach;
        hit = origin + sign * reach * direction;
        found = true;
      }
    }
    return found;
  }

  const Eigen::Matrix3Xd&
  points () const override
  {
    return points_;
  }

  bool
  threadSafe () const override
  {
    return true; // Embree's queries on a committed scene are
  }

private:
  /** The first surface crossing from \a start along \a ray (unit) within \a reach whose normal agrees with
   *  \a normal; on success \a reach becomes its distance. */
  bool
  firstAgreeing (const Eigen::Vector3d& start, const Eigen::Vector3d& ray, const Eigen::Vector3d& normal,
                 double min_cos, double& reach) const
  {
    RTCIntersectContext context;
    rtcInitIntersectContext (&context);
    float near = 0.0f;
    for (int crossing = 0; crossing < kMaxCrossings; ++crossing) {
      RTCRayHit query = EmbreeScene::query (start, ray, near, static_cast<float> (reach));
      rtcIntersect1 (embree_.scene (), &context, &query);
      if (query.hit.geomID == RTC_INVALID_GEOMETRY_ID)
        return false;
      if (face_normals_.col (query.hit.primID).dot (normal) >= min_cos) {
        reach = query.ray.tfar;
        return true;
      }
      near = std::nextafter (query.ray.tfar, std::numeric_limits<float>::infinity ());
    }
    return false;
  }

  Eigen::Matrix3Xd points_;
  Eigen::Matrix3Xd face_normals_;
  EmbreeScene embree_;
};
} // namespace

std::unique_ptr<ScanSurface>
makeMeshSurface (const TriangleMesh& scan)
{
  return std::make_unique<MeshSurface> (scan);
}
} // namespace detail
} // namespace morphreg

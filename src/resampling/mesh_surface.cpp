// A triangulated scan as ScanResampler's surface. The rays go through Intel Embree's BVH: against VTK's locators on
// the same rays (bench/RESULTS.md, "Scan resampling") it answers them many times faster, and its queries are
// thread-safe, so the vertices' rays run in parallel.
#include "scan_surface.h"

#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_normals.h>

#include <embree3/rtcore.h>

#include <cmath>
#include <limits>
#include <memory>
#include <string>

namespace morphreg
{
namespace detail
{
namespace
{
/** Hits whose normals disagree are stepped over; a ray crossing more surfaces than this within its reach misses. */
constexpr int kMaxCrossings = 8;

/** Embree's error for \a device as an Error naming what was being done. */
void
requireNoDeviceError (RTCDevice device, const char* doing)
{
  const RTCError error = rtcGetDeviceError (device);
  if (error != RTC_ERROR_NONE)
    throw Error (std::string ("ScanResampler: Embree failed ") + doing + " (error " + std::to_string (error) + ")");
}

using Device = std::unique_ptr<RTCDeviceTy, decltype (&rtcReleaseDevice)>;
using Scene = std::unique_ptr<RTCSceneTy, decltype (&rtcReleaseScene)>;

Device
newDevice ()
{
  Device device (rtcNewDevice ("verbose=0"), &rtcReleaseDevice);
  if (!device)
    throw Error ("ScanResampler: cannot create an Embree device (error " +
                 std::to_string (rtcGetDeviceError (nullptr)) + ")");
  return device;
}

class MeshSurface : public ScanSurface
{
public:
  explicit MeshSurface (const TriangleMesh& scan)
    : points_ (scan.vertices), face_normals_ (faceNormals (scan)), device_ (newDevice ()),
      scene_ (rtcNewScene (device_.get ()), &rtcReleaseScene)
  {
    requireNoDeviceError (device_.get (), "to create a scene");
    // watertight: a ray through a vertex or an edge of the scan (a reference vertex above a scan vertex) hits
    rtcSetSceneFlags (scene_.get (), RTC_SCENE_FLAG_ROBUST);
    RTCGeometry geometry = rtcNewGeometry (device_.get (), RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*> (rtcSetNewGeometryBuffer (
        geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof (float), scan.numVertices ()));
    auto* indices = static_cast<unsigned*> (rtcSetNewGeometryBuffer (
        geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof (unsigned), scan.numTriangles ()));
    if (!vertices || !indices) {
      rtcReleaseGeometry (geometry);
      requireNoDeviceError (device_.get (), "to allocate the scan's buffers");
    }
    for (Eigen::Index v = 0; v < scan.numVertices (); ++v)
      for (int k = 0; k < 3; ++k)
        vertices[3 * v + k] = static_cast<float> (scan.vertices (k, v));
    for (Eigen::Index t = 0; t < scan.numTriangles (); ++t)
      for (int k = 0; k < 3; ++k)
        indices[3 * t + k] = static_cast<unsigned> (scan.triangles (k, t));
    rtcCommitGeometry (geometry);
    rtcAttachGeometry (scene_.get (), geometry);
    rtcReleaseGeometry (geometry);
    rtcCommitScene (scene_.get ());
    requireNoDeviceError (device_.get (), "to build the scan's ray-tracing structure");
  }

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
      RTCRayHit query = rayHit (start, ray, near, static_cast<float> (reach));
      rtcIntersect1 (scene_.get (), &context, &query);
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

  static RTCRayHit
  rayHit (const Eigen::Vector3d& start, const Eigen::Vector3d& ray, float near, float far)
  {
    RTCRayHit query{};
    query.ray.org_x = static_cast<float> (start.x ());
    query.ray.org_y = static_cast<float> (start.y ());
    query.ray.org_z = static_cast<float> (start.z ());
    query.ray.dir_x = static_cast<float> (ray.x ());
    query.ray.dir_y = static_cast<float> (ray.y ());
    query.ray.dir_z = static_cast<float> (ray.z ());
    query.ray.tnear = near;
    query.ray.tfar = far;
    query.ray.mask = std::numeric_limits<unsigned>::max ();
    query.hit.geomID = RTC_INVALID_GEOMETRY_ID;
    query.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
    return query;
  }

  Eigen::Matrix3Xd points_;
  Eigen::Matrix3Xd face_normals_;
  Device device_;
  Scene scene_;
};
} // namespace

std::unique_ptr<ScanSurface>
makeMeshSurface (const TriangleMesh& scan)
{
  return std::make_unique<MeshSurface> (scan);
}
} // namespace detail
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include "embree_scene.h"

#include <morphreg/common/error.h>

#include <limits>
#include <string>

namespace morphreg
{
namespace detail
{
namespace
{
/** Embree's error for \a device as an Error naming what was being done. */
void
requireNoDeviceError (RTCDevice device, const char* doing)
{
  const RTCError error = rtcGetDeviceError (device);
  if (error != RTC_ERROR_NONE)
    throw Error (std::string ("ScanResampler: Embree failed ") + doing + " (error " + std::to_string (error) + ")");
}

RTCDevice
newDevice ()
{
  RTCDevice device = rtcNewDevice ("verbose=0");
  if (!device)
    throw Error ("ScanResampler: cannot create an Embree device (error " +
                 std::to_string (rtcGetDeviceError (nullptr)) + ")");
  return device;
}
} // namespace

EmbreeScene::EmbreeScene (const TriangleMesh& mesh)
  : device_ (newDevice (), &rtcReleaseDevice), scene_ (rtcNewScene (device_.get ()), &rtcReleaseScene)
{
  requireNoDeviceError (device_.get (), "to create a scene");
  rtcSetSceneFlags (scene_.get (), RTC_SCENE_FLAG_ROBUST);
  RTCGeometry geometry = rtcNewGeometry (device_.get (), RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*> (rtcSetNewGeometryBuffer (geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3,
                                                                 3 * sizeof (float), mesh.numVertices ()));
  auto* indices = static_cast<unsigned*> (rtcSetNewGeometryBuffer (geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3,
                                                                   3 * sizeof (unsigned), mesh.numTriangles ()));
  if (!vertices || !indices) {
    rtcReleaseGeometry (geometry);
    requireNoDeviceError (device_.get (), "to allocate the mesh's buffers");
  }
  Eigen::Map<Eigen::Matrix3Xf> (vertices, 3, mesh.numVertices ()) = mesh.vertices.cast<float> ();
  Eigen::Map<Eigen::Matrix<unsigned, 3, Eigen::Dynamic>> (indices, 3, mesh.numTriangles ()) =
      mesh.triangles.cast<unsigned> ();
  rtcCommitGeometry (geometry);
  rtcAttachGeometry (scene_.get (), geometry);
  rtcReleaseGeometry (geometry);
  rtcCommitScene (scene_.get ());
  requireNoDeviceError (device_.get (), "to build the mesh's ray-tracing structure");
}

RTCRayHit
EmbreeScene::query (const Eigen::Vector3d& start, const Eigen::Vector3d& ray, float near, float far)
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
} // namespace detail
} // namespace morphreg

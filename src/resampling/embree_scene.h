// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Private to the library: a triangle mesh in Intel Embree, for the resampler's rays (and the bench's baseline runs).
#include <morphreg/mesh/triangle_mesh.h>

#include <embree3/rtcore.h>

#include <memory>

namespace morphreg
{
namespace detail
{
/** A triangle mesh's Embree device and committed scene, built watertight (RTC_SCENE_FLAG_ROBUST): a ray through a
 *  vertex or an edge of the mesh hits. Queries on it are thread-safe. */
class EmbreeScene
{
public:
  /** Builds the scene (float coordinates); Error if Embree fails. */
  explicit EmbreeScene (const TriangleMesh& mesh);

  /** The scene, for rtcIntersect1. */
  RTCScene
  scene () const
  {
    return scene_.get ();
  }

  /** The query for the segment start + t ray, near <= t <= far, with no hit yet. */
  static RTCRayHit
  query (const Eigen::Vector3d& start, const Eigen::Vector3d& ray, float near, float far);

private:
  std::unique_ptr<RTCDeviceTy, decltype (&rtcReleaseDevice)> device_;
  std::unique_ptr<RTCSceneTy, decltype (&rtcReleaseScene)> scene_;
};
} // namespace detail
} // namespace morphreg

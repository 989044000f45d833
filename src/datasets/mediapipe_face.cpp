// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/datasets/mediapipe_face.h>
#include <morphreg/io/mesh_io.h>

namespace morphreg
{
namespace
{
constexpr double kCentimetresToMillimetres = 10.0;
constexpr Eigen::Index kFaceMeshVertices = 468;

/** Project landmark ids and their MediaPipe Face Mesh ids (docs/landmarks.md). */
const std::vector<std::pair<std::string, int>> kMediaPipeLandmarks = {
    {"right_eye_outer", 33}, {"right_eye_inner", 133},   {"left_eye_outer", 263},    {"left_eye_inner", 362},
    {"nose_tip", 4},         {"right_mouth_corner", 61}, {"left_mouth_corner", 291}, {"chin", 152},
    {"forehead", 10}};
} // namespace

MediaPipeFace
loadMediaPipeFace (const std::string& path)
{
  MediaPipeFace face;
  face.mesh = loadTriangleMesh (path);
  if (face.mesh.numVertices () != kFaceMeshVertices)
    throw FormatError (path + ": " + std::to_string (face.mesh.numVertices ()) + " vertices, expected the " +
                       std::to_string (kFaceMeshVertices) + " of MediaPipe's canonical face");
  face.mesh.vertices *= kCentimetresToMillimetres;
  for (const auto& [id, vertex] : kMediaPipeLandmarks)
    face.landmarks[id] = vertex;
  return face;
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/resampling/landmark_reference.h>
#include <morphreg/warp/thin_plate_spline.h>

#include <vector>

namespace morphreg
{
TriangleMesh
landmarkReference (const TriangleMesh& reference_template, const LandmarkVertices& template_landmarks,
                   const LandmarkPositions& scan_landmarks, const std::string& scan_landmarks_name,
                   double regularization)
{
  constexpr int kMinimumShared = 5;
  std::vector<int> vertices;
  std::vector<Eigen::Vector3d> targets;
  for (const auto& [id, vertex] : template_landmarks) {
    const auto found = scan_landmarks.find (id);
    if (found == scan_landmarks.end ())
      continue;
    if (vertex < 0 || vertex >= reference_template.numVertices ())
      throw InvalidInputError ("template landmark " + id + " is vertex " + std::to_string (vertex) + ", outside the " +
                               std::to_string (reference_template.numVertices ()) + "-vertex template");
    vertices.push_back (vertex);
    targets.push_back (found->second);
  }
  if (static_cast<int> (vertices.size ()) < kMinimumShared)
    throw InvalidInputError (scan_landmarks_name + ": " + std::to_string (vertices.size ()) +
                             " of its landmarks are on the template, at least " + std::to_string (kMinimumShared) +
                             " are needed to warp it onto the scan");
  Eigen::Matrix3Xd source (3, vertices.size ()), target (3, vertices.size ());
  for (std::size_t i = 0; i < vertices.size (); ++i) {
    source.col (i) = reference_template.vertices.col (vertices[i]);
    target.col (i) = targets[i];
  }
  ThinPlateSpline<double, 3> spline;
  spline.setRegularization (regularization);
  try {
    spline.fit (source, target);
  }
  catch (const InvalidInputError& e) {
    throw InvalidInputError (scan_landmarks_name +
                             ": the template cannot be warped onto these landmarks: " + e.what ());
  }
  return spline.transformMesh (reference_template);
}

} // namespace morphreg

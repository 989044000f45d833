// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/warp/limb_parts.h>

#include <algorithm>

namespace morphreg
{
std::vector<LimbPartError>
limbPartErrors (const TriangleMesh& source, const Eigen::VectorXd& errors, const Skeleton& skeleton,
                const LandmarkPositions& source_joints)
{
  if (errors.size () != source.numVertices ())
    throw InvalidInputError ("limbPartErrors: " + std::to_string (errors.size ()) + " errors for " +
                             std::to_string (source.numVertices ()) + " vertices");
  std::vector<LimbPartError> parts = {{"thigh", "upperleg"}, {"shin", "lowerleg"}, {"upper_arm", "upperarm"}};
  const std::vector<int> nearest = nearestBones (skeleton, source_joints, source.vertices);
  for (Eigen::Index v = 0; v < source.numVertices (); ++v) {
    const std::string& bone = skeleton.bones ()[static_cast<std::size_t> (nearest[static_cast<std::size_t> (v)])].name;
    for (LimbPartError& part : parts)
      if (bone.rfind (part.bones, 0) == 0) {
        ++part.vertices;
        part.max_error = std::max (part.max_error, errors (v));
      }
  }
  return parts;
}

} // namespace morphreg

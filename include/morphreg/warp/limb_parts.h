// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file limb_parts.h
 *  \brief The largest warp error per limb part, where a rigid bone should keep the limb's shape: thigh, shin and
 *  upper arm.
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/warp/skeleton.h>

#include <string>
#include <vector>

namespace morphreg
{
/** \brief A limb part's vertices and their largest error. */
struct LimbPartError
{
  std::string part;       ///< "thigh", "shin" or "upper_arm"
  std::string bones;      ///< the bone name prefix that defines it: "upperleg", "lowerleg", "upperarm"
  int vertices = 0;       ///< vertices whose nearest bone is one of the part's bones
  double max_error = 0.0; ///< their largest error (mm); 0 without vertices
};

/** \brief Largest error per limb part. A vertex belongs to a part when its nearest bone (distance to the bone's
 *  head-tail segment, in the source posture, over every bone of \a skeleton) has a name that starts with the part's
 *  prefix: thigh = "upperleg" bones, shin = "lowerleg", upper arm = "upperarm" (both sides each).
 *  \param[in] source the mesh before the warp
 *  \param[in] errors one error per vertex (mm), e.g. the distance of the warped vertex to the truth
 *  \param[in] skeleton the bones
 *  \param[in] source_joints the joints in the source posture
 *  \return thigh, shin and upper arm, in this order
 */
std::vector<LimbPartError>
limbPartErrors (const TriangleMesh& source, const Eigen::VectorXd& errors, const Skeleton& skeleton,
                const LandmarkPositions& source_joints);

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/warp/articulated_warp.h>
#include <morphreg/warp/as_rigid_as_possible.h>
#include <morphreg/warp/segmented_warp.h>

#include <algorithm>
#include <cmath>

namespace morphreg
{
namespace
{
/** The data weight of a surface landmark's vertex against 1 for every other vertex: the landmark is all but fixed. */
constexpr double kLandmarkWeight = 1e4;

std::vector<int>
segmentsOfBones (const Skeleton& skeleton, const std::vector<std::string>& segment_names)
{
  std::vector<int> segments;
  for (const Bone& bone : skeleton.bones ()) {
    const auto found = std::find (segment_names.begin (), segment_names.end (), bone.segment);
    if (found == segment_names.end ()) {
      std::string names;
      for (const std::string& name : segment_names)
        names += " " + name;
      throw InvalidInputError ("ArticulatedWarp: bone '" + bone.name + "' carries segment '" + bone.segment +
                               "', which the labels do not have (they have:" + names + ")");
    }
    segments.push_back (static_cast<int> (found - segment_names.begin ()));
  }
  return segments;
}
} // namespace

ArticulatedWarp::ArticulatedWarp (Skeleton skeleton, std::vector<int> labels,
                                  const std::vector<std::string>& segment_names)
  : skeleton_ (std::move (skeleton)), labels_ (std::move (labels)),
    bone_segments_ (segmentsOfBones (skeleton_, segment_names))
{
  requireSegmentLabels (labels_, static_cast<int> (segment_names.size ()), "ArticulatedWarp");
}

void
ArticulatedWarp::setJoints (const LandmarkPositions& source, const LandmarkPositions& target)
{
  transforms_ = estimateBoneTransforms (skeleton_, source, target);
  source_joints_ = source;
}

void
ArticulatedWarp::setSurfaceLandmarks (const std::vector<int>& vertices, const Eigen::Matrix3Xd& targets)
{
  if (targets.cols () != static_cast<Eigen::Index> (vertices.size ()))
    throw InvalidInputError ("ArticulatedWarp: " + std::to_string (vertices.size ()) +
                             " surface landmark vertices but " + std::to_string (targets.cols ()) + " targets");
  if (!targets.allFinite ())
    throw InvalidInputError ("ArticulatedWarp: a surface landmark's target is not finite");
  for (int v : vertices)
    if (v < 0 || v >= static_cast<int> (labels_.size ()))
      throw InvalidInputError ("ArticulatedWarp: surface landmark vertex " + std::to_string (v) +
                               " is not a vertex of the labelled mesh (" + std::to_string (labels_.size ()) +
                               " vertices)");
  std::vector<int> sorted = vertices;
  std::sort (sorted.begin (), sorted.end ());
  const auto repeated = std::adjacent_find (sorted.begin (), sorted.end ());
  if (repeated != sorted.end ())
    throw InvalidInputError ("ArticulatedWarp: two surface landmarks lie on vertex " + std::to_string (*repeated) +
                             "; one vertex can have one target only");
  landmark_vertices_ = vertices;
  landmark_targets_ = targets;
}

void
ArticulatedWarp::setSkinningFalloff (const SkinningFalloff& falloff)
{
  if (!(falloff.width > 0.0) || !(falloff.reach > 0.0) || !std::isfinite (falloff.width * falloff.reach))
    throw InvalidInputError ("ArticulatedWarp: the skinning width and reach must be finite and > 0");
  falloff_ = falloff;
}

void
ArticulatedWarp::setRigidity (double rigidity)
{
  if (!(rigidity >= 0.0) || !std::isfinite (rigidity))
    throw InvalidInputError ("ArticulatedWarp: the rigidity must be a finite number >= 0");
  rigidity_ = rigidity;
}

void
ArticulatedWarp::setIterations (int iterations)
{
  if (iterations < 0)
    throw InvalidInputError ("ArticulatedWarp: the number of iterations must be >= 0");
  iterations_ = iterations;
}

const std::vector<Eigen::Isometry3d>&
ArticulatedWarp::boneTransforms () const
{
  if (transforms_.empty ())
    throw InvalidInputError ("ArticulatedWarp: no joints set (call setJoints first)");
  return transforms_;
}

void
ArticulatedWarp::requireMesh (const TriangleMesh& mesh) const
{
  validateMesh (mesh, "mesh to warp");
  if (mesh.numVertices () != static_cast<Eigen::Index> (labels_.size ()))
    throw InvalidInputError ("ArticulatedWarp: the mesh has " + std::to_string (mesh.numVertices ()) +
                             " vertices but there are " + std::to_string (labels_.size ()) + " segment labels");
  boneTransforms ();
}

Eigen::MatrixXd
ArticulatedWarp::skinningWeights (const TriangleMesh& mesh) const
{
  requireMesh (mesh);
  return geodesicSkinningWeights (mesh, labels_, bone_segments_,
                                  boneDistances (skeleton_, source_joints_, mesh.vertices), falloff_);
}

TriangleMesh
ArticulatedWarp::skin (const TriangleMesh& mesh) const
{
  TriangleMesh skinned = mesh;
  skinned.vertices = linearBlendSkinning (mesh.vertices, skinningWeights (mesh), transforms_);
  return skinned;
}

TriangleMesh
ArticulatedWarp::warp (const TriangleMesh& mesh) const
{
  TriangleMesh warped = skin (mesh);
  if (rigidity_ == 0.0 && landmark_vertices_.empty ())
    return warped;
  Eigen::VectorXd data_weights = Eigen::VectorXd::Ones (mesh.numVertices ());
  Eigen::Matrix3Xd data = warped.vertices;
  for (std::size_t k = 0; k < landmark_vertices_.size (); ++k) {
    const int v = landmark_vertices_[k];
    data_weights (v) += kLandmarkWeight;
    data.col (v) = (data.col (v) + kLandmarkWeight * landmark_targets_.col (static_cast<Eigen::Index> (k))) /
                   (1.0 + kLandmarkWeight);
  }
  const AsRigidAsPossible refinement (mesh, rigidity_, data_weights);
  warped.vertices = refinement.refine (data, std::max (iterations_, 1));
  return warped;
}

void
ArticulatedWarp::warp (const pcl::PolygonMesh& input, pcl::PolygonMesh& output) const
{
  output = toPolygonMesh (warp (fromPolygonMesh (input, "mesh to warp")));
}

} // namespace morphreg

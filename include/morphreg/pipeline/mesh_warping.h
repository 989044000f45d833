// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file mesh_warping.h
 *  \brief A mesh warped from source to target landmarks the way `morphreg warp` does it, for every front end: the
 *  inputs brought to mm, the landmarks paired by name, then a global or segmented thin plate spline, moving least
 *  squares, or rigid bones of a skeleton (ArticulatedWarp), with its report, and optionally the error against the
 *  true target mesh.
 *
 *  \code
 *  morphreg::MeshWarpInput input = morphreg::readMeshWarpInput ({"body.ply", "from.csv", "to.csv"},
 *                                                               morphreg::LengthUnit::decimetre);
 *  morphreg::MeshWarpOutcome warped = morphreg::warpMesh (input, {});
 *  morphreg::evaluateWarpAgainst (input, morphreg::readWarpTruth ("truth.ply", morphreg::LengthUnit::decimetre),
 *                                 {}, warped);
 *  \endcode
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/common/length_unit.h>
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/model/region_segmentation.h>
#include <morphreg/warp/skeleton.h>

#include <nlohmann/json.hpp>

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief The warps of warpMesh. */
enum class WarpMethod
{
  thin_plate_spline,    ///< one spline, or one per segment with blended seams when the input has segments
  moving_least_squares, ///< each point follows the affine motion of its nearest landmarks
  articulated           ///< rigid bones between joint landmarks, skinned by segments, refined as rigid as possible
};

/** \brief Settings of warpMesh: one set of defaults for every front end. */
struct MeshWarpingSettings
{
  WarpMethod method = WarpMethod::thin_plate_spline; ///< the warp
  double regularization = 0.0;                       ///< thin plate spline: lambda (0 = exact interpolation)
  std::vector<double> blend_width{
      100.0};                        ///< segmented: mm each segment reaches into its neighbours (one or per segment)
  std::vector<double> overlap{90.0}; ///< segmented: mm landmarks join a segment beyond it (one or per segment)
  double rigidity = 1.0;             ///< articulated: weight of the as-rigid-as-possible refinement
  double skinning_width = 30.0;      ///< articulated: mm over which a bone's weight falls along the mesh
  double mls_falloff = 1.0;          ///< moving least squares: weights fall as 1 / distance^(2 a)
};

/** \brief The files of a warp (empty: not given). */
struct MeshWarpFiles
{
  std::string mesh;     ///< the mesh to warp
  std::string source;   ///< landmarks on the mesh (loadNamedPoints)
  std::string target;   ///< where they go, by the same names
  std::string segments; ///< segment per vertex (mesh_annotations.h): segmented or articulated warp
  std::string skeleton; ///< articulated: a skeleton file (skeleton_io.h); empty: MakeHuman's major joints
};

/** \brief What warpMesh takes, in mm, each with its name for messages. */
struct MeshWarpInput
{
  TriangleMesh mesh;                    ///< the mesh to warp (mm)
  std::string mesh_name;                ///< its name (its file)
  LandmarkPositions source;             ///< landmarks on the mesh (mm)
  LandmarkPositions target;             ///< where they go, by the same names (pairWarpLandmarks)
  std::string source_name;              ///< the source landmarks' name (their file)
  std::string target_name;              ///< the target landmarks' name (their file)
  std::optional<RegionLabels> segments; ///< a segment per vertex of mesh
  std::string segments_name;            ///< their name (their file)
  std::optional<Skeleton> skeleton;     ///< articulated: none is MakeHuman's major joints
  std::string skeleton_name;            ///< its name (its file)
};

/** \brief The outcome of warpMesh (and of evaluateWarpAgainst). */
struct MeshWarpOutcome
{
  TriangleMesh warped;                        ///< the warped mesh (mm)
  nlohmann::json report;                      ///< status, units, mode, landmarks and the method's figures
  std::optional<Eigen::VectorXd> truth_error; ///< per vertex, mm, after evaluateWarpAgainst
};

/** \brief Checks that \a source and \a target name the same landmarks, each source point with one target.
 *  Throws InvalidInputError naming both and the names not in both.
 *  \param[in] source the landmarks on the mesh
 *  \param[in] target where they go
 *  \param[in] source_name \a source's name (its file)
 *  \param[in] target_name \a target's name (its file) */
void
pairWarpLandmarks (const LandmarkPositions& source, const LandmarkPositions& target, const std::string& source_name,
                   const std::string& target_name);

/** \brief Reads the files of a warp, in \a unit, converted to mm, and pairs the landmarks (pairWarpLandmarks).
 *  Throws IoError or FormatError naming a file that cannot be read, InvalidInputError as pairWarpLandmarks.
 *  \param[in] files the files (mesh, source and target needed)
 *  \param[in] unit the unit of the mesh and landmark files
 *  \return the input in mm */
MeshWarpInput
readMeshWarpInput (const MeshWarpFiles& files, LengthUnit unit);

/** \brief Reads the true target of a warp (same topology as its mesh), converted from \a unit to mm.
 *  \param[in] path the mesh file
 *  \param[in] unit its unit
 *  \return the mesh in mm */
TriangleMesh
readWarpTruth (const std::string& path, LengthUnit unit);

/** \brief Warps input.mesh from input.source to input.target with \a settings. Throws InvalidInputError naming the
 *  landmark files for landmarks the method cannot use (too few, collinear or flat), the segments for values not one
 *  or one per segment, the skeleton when it does not fit the segments, a surface landmark off the mesh, and an
 *  articulated warp without segments.
 *  \param[in] input the mesh and landmarks (mm)
 *  \param[in] settings the method and its settings
 *  \return the warped mesh and the report */
MeshWarpOutcome
warpMesh (const MeshWarpInput& input, const MeshWarpingSettings& settings);

/** \brief Adds the error of \a outcome's warped mesh against \a truth (same topology, mm): truth_error per vertex,
 *  and to the report error_mm (mean, rms, max), the seam and band figures (warp_quality.h), folded triangles and,
 *  for the articulated method, the largest error per limb part. Throws InvalidInputError naming \a truth_name when
 *  the topologies differ.
 *  \param[in] input the warp's input
 *  \param[in] truth the true target mesh (mm)
 *  \param[in] truth_name its name for messages
 *  \param[in] settings the warp's settings
 *  \param[in,out] outcome the warp's outcome */
void
evaluateWarpAgainst (const MeshWarpInput& input, const TriangleMesh& truth, const std::string& truth_name,
                     const MeshWarpingSettings& settings, MeshWarpOutcome& outcome);

/** \brief \a values for each of \a num_segments segments: one value for every segment, or one per segment
 *  (InvalidInputError naming \a what and the counts otherwise).
 *  \param[in] values the values given
 *  \param[in] num_segments the segments
 *  \param[in] what the values' name for messages
 *  \return one value per segment */
std::vector<double>
valuePerSegment (const std::vector<double>& values, int num_segments, const std::string& what);

/** \brief The method named \a name: "tps", "mls" or "articulated"; InvalidInputError listing them otherwise.
 *  \param[in] name the name
 *  \return the method */
WarpMethod
parseWarpMethod (const std::string& name);

} // namespace morphreg

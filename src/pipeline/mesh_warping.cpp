// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/datasets/makehuman_bodies.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/io/mesh_annotations.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/io/skeleton_io.h>
#include <morphreg/pipeline/mesh_warping.h>
#include <morphreg/warp/articulated_warp.h>
#include <morphreg/warp/limb_parts.h>
#include <morphreg/warp/moving_least_squares_warp.h>
#include <morphreg/warp/segmented_warp.h>
#include <morphreg/warp/thin_plate_spline.h>
#include <morphreg/warp/warp_quality.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

namespace morphreg
{
namespace
{
/** A surface landmark of the articulated method must be a vertex of the mesh: within this distance (mm) of one. */
constexpr double kSurfaceLandmarkTolerance = 1.0;

/** The landmark pairs as matching columns. */
std::pair<Eigen::Matrix3Xd, Eigen::Matrix3Xd>
landmarkColumns (const MeshWarpInput& input)
{
  Eigen::Matrix3Xd from (3, static_cast<Eigen::Index> (input.source.size ())), to (3, from.cols ());
  Eigen::Index column = 0;
  for (const auto& [name, position] : input.source) {
    from.col (column) = position;
    to.col (column++) = input.target.at (name);
  }
  return {from, to};
}

/** Runs \a fit (the warp's fit to the landmarks); a configuration it cannot use (too few, collinear or flat
 *  landmarks) is reported with both landmark files. */
template <typename Fit>
auto
fitToLandmarks (const MeshWarpInput& input, Fit fit) -> decltype (fit ())
{
  try {
    return fit ();
  }
  catch (const InvalidInputError& e) {
    throw InvalidInputError ("the landmarks of " + input.source_name + " -> " + input.target_name + ": " + e.what ());
  }
}

/** The segments of \a input; InvalidInputError naming the mesh for \a method without them. */
const RegionLabels&
requireSegments (const MeshWarpInput& input, const std::string& method)
{
  if (!input.segments)
    throw InvalidInputError (input.mesh_name + ": the " + method +
                             " warp needs the segment of each vertex, which the skeleton's bones carry");
  return *input.segments;
}

TriangleMesh
globalWarp (const MeshWarpInput& input, const MeshWarpingSettings& settings, nlohmann::json& report)
{
  const auto [source, target] = landmarkColumns (input);
  ThinPlateSpline<double, 3> spline;
  spline.setRegularization (settings.regularization);
  fitToLandmarks (input, [&] { spline.fit (source, target); });
  report["mode"] = "global";
  report["bending_energy"] = spline.bendingEnergy ();
  report["merged_landmarks"] = spline.mergedLandmarks ();
  return spline.transformMesh (input.mesh);
}

TriangleMesh
segmentedWarp (const MeshWarpInput& input, const MeshWarpingSettings& settings, nlohmann::json& report)
{
  const auto [source, target] = landmarkColumns (input);
  const RegionLabels& segments = *input.segments;
  const int num_segments = static_cast<int> (segments.names.size ());
  SegmentedWarp warp (segments.labels, num_segments);
  warp.setRegularization (settings.regularization);
  const std::vector<double> blend = valuePerSegment (settings.blend_width, num_segments, "the blend width");
  for (int s = 0; s < num_segments; ++s)
    warp.setSegmentBlendWidth (s, blend[static_cast<std::size_t> (s)]);
  const std::vector<double> overlap = valuePerSegment (settings.overlap, num_segments, "the overlap");
  const auto subsets = fitToLandmarks (input, [&] { return warp.setLandmarks (input.mesh, source, target, overlap); });
  for (const auto& subset : subsets)
    report["segment_landmarks"].push_back (subset.size ());
  report["mode"] = "segmented";
  report["blend_width_mm"] = blend;
  for (double o : overlap) // an infinite overlap (JSON has no infinity): the segment takes every landmark
    report["overlap_mm"].push_back (std::isinf (o) ? nlohmann::json ("all") : nlohmann::json (o));
  return warp.warp (input.mesh);
}

TriangleMesh
movingLeastSquaresWarp (const MeshWarpInput& input, const MeshWarpingSettings& settings, nlohmann::json& report)
{
  const auto [source, target] = landmarkColumns (input);
  MovingLeastSquaresWarp warp;
  warp.setFalloff (settings.mls_falloff);
  fitToLandmarks (input, [&] { warp.setLandmarks (source, target); });
  report["mode"] = "moving_least_squares";
  report["falloff_exponent"] = settings.mls_falloff;
  report["merged_landmarks"] = warp.mergedLandmarks ();
  return warp.warp (input.mesh);
}

/** The skeleton of \a input, MakeHuman's when it has none. */
Skeleton
chosenSkeleton (const MeshWarpInput& input)
{
  return input.skeleton ? *input.skeleton : makeHumanSkeleton ();
}

std::string
skeletonName (const MeshWarpInput& input)
{
  return input.skeleton ? input.skeleton_name : "makehuman (built in)";
}

/** Every landmark that names no joint of the skeleton pins the vertex it lies on; one off the mesh is an error. */
void
setSurfaceLandmarks (ArticulatedWarp& warp, const MeshWarpInput& input, nlohmann::json& report)
{
  const std::vector<std::string> joints = warp.skeleton ().jointNames ();
  std::vector<int> vertices;
  std::vector<Eigen::Vector3d> targets;
  for (const auto& [name, position] : input.source) {
    if (std::binary_search (joints.begin (), joints.end (), name))
      continue;
    Eigen::Index vertex = 0;
    const double distance =
        std::sqrt ((input.mesh.vertices.colwise () - position).colwise ().squaredNorm ().minCoeff (&vertex));
    if (distance > kSurfaceLandmarkTolerance)
      throw InvalidInputError ("landmark '" + name + "' of " + input.source_name +
                               " is no joint of the skeleton and not on the mesh (" + std::to_string (distance) +
                               " mm from its nearest vertex of " + input.mesh_name +
                               "); surface landmarks must lie on vertices");
    vertices.push_back (static_cast<int> (vertex));
    targets.push_back (input.target.at (name));
  }
  Eigen::Matrix3Xd target_columns (3, static_cast<Eigen::Index> (targets.size ()));
  for (std::size_t k = 0; k < targets.size (); ++k)
    target_columns.col (static_cast<Eigen::Index> (k)) = targets[k];
  warp.setSurfaceLandmarks (vertices, target_columns);
  report["surface_landmarks"] = vertices.size ();
}

TriangleMesh
articulatedWarp (const MeshWarpInput& input, const MeshWarpingSettings& settings, nlohmann::json& report)
{
  const RegionLabels& segments = requireSegments (input, "articulated");
  std::unique_ptr<ArticulatedWarp> warp;
  try {
    warp = std::make_unique<ArticulatedWarp> (chosenSkeleton (input), segments.labels, segments.names);
  }
  catch (const InvalidInputError& e) {
    throw InvalidInputError ("the skeleton " + skeletonName (input) + " does not fit the labels " +
                             input.segments_name + ": " + e.what ());
  }
  warp->setSkinningFalloff ({settings.skinning_width, SkinningFalloff ().reach});
  warp->setRigidity (settings.rigidity);
  fitToLandmarks (input, [&] { warp->setJoints (input.source, input.target); });
  setSurfaceLandmarks (*warp, input, report);
  report["mode"] = "articulated";
  report["skeleton"] = skeletonName (input);
  report["bones"] = warp->skeleton ().numBones ();
  report["joints"] = warp->skeleton ().boneJointNames ().size ();
  report["rigidity"] = settings.rigidity;
  report["skinning_width_mm"] = settings.skinning_width;
  return warp->warp (input.mesh);
}

/** A mesh file in \a unit, in mm. */
TriangleMesh
loadMeshIn (const std::string& path, LengthUnit unit)
{
  TriangleMesh mesh = loadTriangleMesh (path);
  mesh.vertices *= millimetresPer (unit);
  return mesh;
}

/** A landmark file in \a unit, in mm. */
LandmarkPositions
loadLandmarksIn (const std::string& path, LengthUnit unit)
{
  LandmarkPositions points = loadNamedPoints (path);
  for (auto& entry : points)
    entry.second *= millimetresPer (unit);
  return points;
}
} // namespace

std::vector<double>
valuePerSegment (const std::vector<double>& values, int num_segments, const std::string& what)
{
  if (values.size () == 1)
    return std::vector<double> (static_cast<std::size_t> (num_segments), values.front ());
  if (values.size () != static_cast<std::size_t> (num_segments))
    throw InvalidInputError (what + " has " + std::to_string (values.size ()) + " values for " +
                             std::to_string (num_segments) + " segments; give one value or one per segment");
  return values;
}

void
pairWarpLandmarks (const LandmarkPositions& source, const LandmarkPositions& target, const std::string& source_name,
                   const std::string& target_name)
{
  std::string missing;
  for (const auto& entry : source)
    if (!target.count (entry.first))
      missing += " " + entry.first;
  for (const auto& entry : target)
    if (!source.count (entry.first))
      missing += " " + entry.first;
  if (!missing.empty ())
    throw InvalidInputError ("the landmark files " + source_name + " and " + target_name +
                             " must name the same landmarks; not in both:" + missing);
  requireOneTargetPerPoint (source, target, source_name, target_name);
}

MeshWarpInput
readMeshWarpInput (const MeshWarpFiles& files, LengthUnit unit)
{
  MeshWarpInput input;
  input.mesh = loadMeshIn (files.mesh, unit);
  input.mesh_name = files.mesh;
  input.source = loadLandmarksIn (files.source, unit);
  input.target = loadLandmarksIn (files.target, unit);
  input.source_name = files.source;
  input.target_name = files.target;
  pairWarpLandmarks (input.source, input.target, files.source, files.target);
  if (!files.segments.empty ())
    input.segments = loadRegionLabels (files.segments, input.mesh.numVertices ());
  input.segments_name = files.segments;
  if (!files.skeleton.empty ())
    input.skeleton = loadSkeleton (files.skeleton);
  input.skeleton_name = files.skeleton;
  return input;
}

TriangleMesh
readWarpTruth (const std::string& path, LengthUnit unit)
{
  return loadMeshIn (path, unit);
}

MeshWarpOutcome
warpMesh (const MeshWarpInput& input, const MeshWarpingSettings& settings)
{
  pairWarpLandmarks (input.source, input.target, input.source_name, input.target_name);
  MeshWarpOutcome outcome;
  outcome.report = {{"status", "ok"}, {"units", "mm"}, {"landmarks", input.source.size ()}};
  switch (settings.method) {
  case WarpMethod::articulated:
    outcome.warped = articulatedWarp (input, settings, outcome.report);
    break;
  case WarpMethod::moving_least_squares:
    outcome.warped = movingLeastSquaresWarp (input, settings, outcome.report);
    break;
  case WarpMethod::thin_plate_spline:
    outcome.warped =
        input.segments ? segmentedWarp (input, settings, outcome.report) : globalWarp (input, settings, outcome.report);
    break;
  }
  return outcome;
}

void
evaluateWarpAgainst (const MeshWarpInput& input, const TriangleMesh& truth, const std::string& truth_name,
                     const MeshWarpingSettings& settings, MeshWarpOutcome& outcome)
{
  requireSameTopology (input.mesh, truth, truth_name);
  const TriangleMesh& warped = outcome.warped;
  const Eigen::VectorXd errors = (warped.vertices - truth.vertices).colwise ().norm ().transpose ();
  const std::vector<int> labels = input.segments
                                      ? input.segments->labels
                                      : std::vector<int> (static_cast<std::size_t> (input.mesh.numVertices ()), 0);
  const WarpQuality quality = evaluateWarp (warped, truth, labels, 100.0, &input.mesh);
  nlohmann::json& report = outcome.report;
  report["error_mm"] = {{"mean", quality.mean_error}, {"rms", quality.rms_error}, {"max", quality.max_error}};
  report["seam"] = quality.seam;
  report["band"] = quality.band;
  report["folded_in_band"] = quality.folded_in_band;
  report["folded_triangles"] = {{"warped", countFoldedTriangles (warped)}, {"truth", countFoldedTriangles (truth)}};
  if (settings.method == WarpMethod::articulated)
    for (const LimbPartError& part : limbPartErrors (input.mesh, errors, chosenSkeleton (input), input.source))
      report["limb_parts"][part.part] = {
          {"bones", part.bones + "*"}, {"vertices", part.vertices}, {"max_error_mm", part.max_error}};
  outcome.truth_error = errors;
}

WarpMethod
parseWarpMethod (const std::string& name)
{
  if (name == "tps")
    return WarpMethod::thin_plate_spline;
  if (name == "mls")
    return WarpMethod::moving_least_squares;
  if (name == "articulated")
    return WarpMethod::articulated;
  throw InvalidInputError ("warp method '" + name + "': expected tps, mls or articulated");
}

} // namespace morphreg

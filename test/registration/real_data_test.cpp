// SPDX-License-Identifier: BSD-3-Clause
// MorphableICP with the ICT-FaceKit model (30 components) on real surfaces, landmark-initialised: MNE's fsaverage
// scalp and MediaPipe's canonical face. Distance as surfaceDistance defines it: target samples (one per 4 mm^2) to the
// closest point of the fitted surface, without samples that reach it at its boundary (and, for fsaverage, without
// the flat cap that closes the MRI scalp below the head).
#include "ict_data.h"

#include <morphreg/datasets/fsaverage_head.h>
#include <morphreg/datasets/mediapipe_face.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/mesh/planar_cap.h>
#include <morphreg/mesh/surface_sampling.h>
#include <morphreg/registration/initial_alignment.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/registration/surface_distance.h>

#include <pcl/registration/correspondence_rejection_one_to_one.h>

#include "support/accuracy_bound.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace
{
using morphreg::MorphableModel;
using morphreg::TriangleMesh;
using Icp = morphreg::MorphableICP<pcl::PointNormal>;

constexpr int kFittedComponents = 30;
constexpr double kTargetPoints = 40000; ///< points of the registration target (as many as the protocol's scans)

#define REQUIRE_DATA(relative)                                                                                         \
  if (!morphreg::test::ictAvailable () || !std::filesystem::exists (morphreg::test::sharedDataPath (relative)))        \
  GTEST_SKIP () << "ICT-FaceKit or " << relative << " not found in " << MORPHREG_SHARED_DATA_DIR                       \
                << " (../shared/data is absent)"

/** The registration target: about kTargetPoints area-uniform points of \a mesh (without the \a excluded triangles)
 *  with the normal of the triangle each lies on.
 */
pcl::PointCloud<pcl::PointNormal>::Ptr
targetCloud (const TriangleMesh& mesh, const std::vector<bool>& excluded)
{
  const double area_per_point = morphreg::triangleAreas (mesh).sum () / kTargetPoints;
  const auto samples = morphreg::sampleSurfaceUniformly (mesh, area_per_point, 5, excluded);
  const Eigen::Matrix3Xd normals = morphreg::faceNormals (mesh);
  pcl::PointCloud<pcl::PointNormal>::Ptr cloud (new pcl::PointCloud<pcl::PointNormal>);
  for (Eigen::Index i = 0; i < samples.points.cols (); ++i) {
    pcl::PointNormal point;
    point.getVector3fMap () = samples.points.col (i).cast<float> ();
    point.getNormalVector3fMap () = normals.col (samples.triangles[static_cast<size_t> (i)]).cast<float> ();
    cloud->push_back (point);
  }
  return cloud;
}

/** Registers the ICT model (first 30 components, point-to-plane) to \a target from \a landmarks; returns the fit.
 *  Settings for a clean real surface, as a user would pick them (the library defaults are tuned on noisy synthetic
 *  scans with outliers); in brackets the fsaverage median / 95th percentile and the MediaPipe median with each
 *  setting and those above it, against the defaults' 0.996 / 3.42 and 0.373 mm:
 *  - area weighting: ICT's vertices are dense on the face and sparse on the skull, so unweighted correspondences
 *    fit the face and leave the scalp loose, while the evaluation is uniform by target area (0.714 / 2.48, 0.325);
 *  - a one-to-one rejector: model vertices beyond the target's extent (the neck below fsaverage's cap, the back of
 *    the head behind MediaPipe's face) otherwise pile onto the same target points near its edge (0.672 / 2.31,
 *    0.322);
 *  - landmark weight 1 (one correspondence each): the target landmarks are not exactly ICT's points (fsaverage's
 *    LPA/RPA are not the tragus vertices) (0.652 / 2.28, 0.304);
 *  - a weaker shape prior (1.5) and a larger tangential weight (0.1) (0.642 / 2.23, 0.282).
 *  The divergence guard stays on: on fsaverage the shape stage's cost really rises after ~7 iterations and the fit
 *  gets worse (without the guard, 50 iterations end at 0.704 / 2.64); the guard returns the best state.
 */
TriangleMesh
registerIct (const pcl::PointCloud<pcl::PointNormal>::Ptr& target, const morphreg::LandmarkPositions& landmarks)
{
  const MorphableModel::ConstPtr& model = morphreg::test::ictModel ();
  Icp icp;
  icp.setModel (model);
  icp.setComponentSelection (model->firstComponents (kFittedComponents));
  icp.setMaximumIterations (50);
  icp.setSimilarityIterations (20);
  icp.setPointToPlane (true, 0.1);
  icp.setShapePriorWeight (1.5);
  icp.setAreaWeighting (true);
  icp.addCorrespondenceRejector (icp.getTargetBoundaryRejector ()); // kept in front of the chain
  icp.addCorrespondenceRejector (std::make_shared<pcl::registration::CorrespondenceRejectorOneToOne> ());
  icp.setTargetLandmarks (landmarks, 1.0);
  icp.setInitialAlignment (morphreg::makeInitialAlignment ("landmarks"));
  icp.setInputTarget (target);
  pcl::PointCloud<pcl::PointNormal> output;
  icp.align (output);
  const auto& report = icp.getRegistrationReport ();
  std::printf ("[ real data ] %d points, %zu iterations, %s%s%s; fitness median %.3f mm\n",
               static_cast<int> (target->size ()), report.history.size (),
               morphreg::toString (report.termination).c_str (), report.message.empty () ? "" : ": ",
               report.message.c_str (), report.fitness_median);
  TriangleMesh fitted;
  fitted.vertices = icp.getFittedVertices ();
  fitted.triangles = model->triangles ();
  return fitted;
}

/** The no-op of these fits: the ICT mean placed on \a landmarks by their similarity alone (the fits' start). */
TriangleMesh
landmarkAlignedMean (const morphreg::LandmarkPositions& landmarks)
{
  const MorphableModel& model = *morphreg::test::ictModel ();
  Eigen::Matrix3Xd from (3, landmarks.size ()), to (3, landmarks.size ());
  int k = 0;
  for (const auto& [name, position] : landmarks) {
    from.col (k) = model.meanVertex (model.landmarkVertex (name));
    to.col (k++) = position;
  }
  const Eigen::Matrix4d pose = morphreg::similarityFromLandmarks (from, to);
  const Eigen::Map<const Eigen::Matrix3Xd> mean (model.mean ().data (), 3, model.numVertices ());
  return TriangleMesh{(pose.topLeftCorner<3, 3> () * mean).colwise () + pose.topRightCorner<3, 1> (),
                      model.triangles ()};
}

void
printDistance (const char* name, const morphreg::SurfaceDistance& distance)
{
  std::printf ("[ real data ] %s: %d samples, %d dropped on the model boundary; median %.3f mm, 95th percentile "
               "%.3f mm, mean %.3f mm, RMS %.3f mm, max %.2f mm\n",
               name, distance.samples, distance.dropped_on_boundary, distance.median, distance.percentile95,
               distance.mean, distance.rms, distance.max);
}

TEST (RealDataIcpTest, IctFitsTheFsaverageScalp)
{
  REQUIRE_DATA ("mne_fsaverage_head/fsaverage_head.ply");
  const auto head = morphreg::loadFsaverageHead (morphreg::test::sharedDataPath ("mne_fsaverage_head"));
  // The flat cap below the head, seeded with the triangles facing down (-z in RAS).
  const std::vector<bool> cap = morphreg::findPlanarCap (head.mesh);
  const Eigen::VectorXd areas = morphreg::triangleAreas (head.mesh);
  double cap_area = 0.0;
  for (size_t t = 0; t < cap.size (); ++t)
    cap_area += cap[t] ? areas[static_cast<Eigen::Index> (t)] : 0.0;
  const double cap_fraction = cap_area / areas.sum ();
  std::printf ("[ real data ] fsaverage: the closing cap is %.2f %% of the area\n", 100.0 * cap_fraction);
  EXPECT_NEAR (cap_fraction, 0.056, 0.01) << "fsaverage's closing cap is about 5.6 % of the area";

  const TriangleMesh fitted = registerIct (targetCloud (head.mesh, cap), head.landmarks);
  const auto distance = morphreg::surfaceDistance (head.mesh, fitted, cap);
  printDistance ("fsaverage", distance);
  // Required: at least as close as the point-to-point reference (0.68 / 2.4 mm). These settings reach a median of
  // 0.642 mm and a 95th percentile of 2.23 mm (the default settings: 1.00 / 3.42 mm).
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, distance.median, 0.65);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, distance.percentile95, 2.3);
  EXPECT_GT (distance.samples - distance.dropped_on_boundary, 30000) << "the samples scored (36,261)";
  const auto no_op = morphreg::surfaceDistance (head.mesh, landmarkAlignedMean (head.landmarks), cap);
  printDistance ("fsaverage, the landmark-aligned mean (no fit)", no_op);
  EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, no_op.median, 0.65);
}

TEST (RealDataIcpTest, IctFitsTheMediaPipeCanonicalFace)
{
  REQUIRE_DATA ("mediapipe_canonical_face/canonical_face_model.obj");
  const auto face = morphreg::loadMediaPipeFace (
      morphreg::test::sharedDataPath ("mediapipe_canonical_face/canonical_face_model.obj"));
  morphreg::LandmarkPositions landmarks;
  for (const char* name : {"right_eye_outer", "right_eye_inner", "left_eye_inner", "left_eye_outer", "nose_tip",
                           "right_mouth_corner", "left_mouth_corner", "chin"})
    landmarks[name] = face.mesh.vertices.col (face.landmarks.at (name));

  const TriangleMesh fitted = registerIct (targetCloud (face.mesh, {}), landmarks);
  const auto distance = morphreg::surfaceDistance (face.mesh, fitted);
  printDistance ("MediaPipe", distance);
  // Required: at least as close as the point-to-point reference (0.31-0.36 mm). These settings reach a median of
  // 0.281 mm and a 95th percentile of 1.04 mm (the default settings: 0.373 / 1.20 mm); the 95th percentile is held
  // within 1.3x.
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, distance.median, 0.30);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, distance.percentile95, 1.3);
  EXPECT_GT (distance.samples - distance.dropped_on_boundary, 8000) << "the samples scored (8,989)";
  const auto no_op = morphreg::surfaceDistance (face.mesh, landmarkAlignedMean (landmarks));
  printDistance ("MediaPipe, the landmark-aligned mean (no fit)", no_op);
  EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, no_op.median, 0.30);
}

} // namespace

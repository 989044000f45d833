// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/datasets/makehuman_bodies.h>
#include <morphreg/warp/articulated_warp.h>
#include <morphreg/warp/as_rigid_as_possible.h>
#include <morphreg/warp/limb_parts.h>
#include <morphreg/warp/warp_quality.h>

#include "support/accuracy_bound.h"
#include "support/expect_error.h"
#include "support/makehuman_data.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <limits>

using morphreg::ArticulatedWarp;
using morphreg::Bone;
using morphreg::LandmarkPositions;
using morphreg::Skeleton;
using morphreg::TriangleMesh;
using morphreg::test::bodiesDirectory;
using morphreg::test::expectErrorContaining;

namespace
{
/** An open tube along -y (radius 40 mm, 400 mm long, rings every 10 mm): a leg of two bones, hip at the origin. */
TriangleMesh
makeLeg ()
{
  const int around = 24, rings = 41;
  TriangleMesh mesh;
  mesh.vertices.resize (3, around * rings);
  for (int r = 0; r < rings; ++r)
    for (int k = 0; k < around; ++k) {
      const double angle = 2.0 * M_PI * k / around;
      mesh.vertices.col (r * around + k) << 40.0 * std::cos (angle), -10.0 * r, 40.0 * std::sin (angle);
    }
  mesh.triangles.resize (3, 2 * around * (rings - 1));
  for (int r = 0; r + 1 < rings; ++r)
    for (int k = 0; k < around; ++k) {
      const int a = r * around + k, b = r * around + (k + 1) % around, c = a + around, d = b + around;
      mesh.triangles.col (2 * (r * around + k)) << a, c, b;
      mesh.triangles.col (2 * (r * around + k) + 1) << b, c, d;
    }
  return mesh;
}

Skeleton
makeLegSkeleton ()
{
  return Skeleton (
      {{"upperleg", "hip", "knee", "leg", "hip.R", "hip"}, {"lowerleg", "knee", "ankle", "leg", "hip.R", "hip"}});
}

LandmarkPositions
legJoints ()
{
  return {{"hip", {0, 0, 0}}, {"hip.R", {-100, 0, 0}}, {"knee", {0, -200, 0}}, {"ankle", {0, -400, 0}}};
}

/** The leg seated: the thigh turned forward by 90 degrees about x at the hip, the shin hanging down again. */
LandmarkPositions
seatedLegJoints ()
{
  return {{"hip", {0, 0, 0}}, {"hip.R", {-100, 0, 0}}, {"knee", {0, 0, 200}}, {"ankle", {0, -200, 200}}};
}

Eigen::Isometry3d
randomMotion (int seed)
{
  std::srand (static_cast<unsigned> (seed));
  Eigen::Isometry3d motion = Eigen::Isometry3d::Identity ();
  motion.linear () = Eigen::Quaterniond (Eigen::Vector4d::Random ().normalized ()).toRotationMatrix ();
  motion.translation () = 100.0 * Eigen::Vector3d::Random ();
  return motion;
}
} // namespace

TEST (SkeletonTest, BoneTransformsRecoverARigidMotionWithItsTwist)
{
  const Skeleton skeleton = makeLegSkeleton ();
  for (int seed = 1; seed <= 5; ++seed) {
    const Eigen::Isometry3d motion = randomMotion (seed);
    LandmarkPositions moved;
    for (const auto& [name, position] : legJoints ())
      moved[name] = motion * position;
    for (const Eigen::Isometry3d& transform : morphreg::estimateBoneTransforms (skeleton, legJoints (), moved))
      EXPECT_LT ((transform.matrix () - motion.matrix ()).norm (), 1e-9) << "seed " << seed;
  }
}

TEST (SkeletonTest, TheTwistPairTurnsTheBoneAboutItsAxis)
{
  // The thigh turns forward about x: its shortest rotation alone would be the same here, so tilt the leg outwards
  // (its direction then has an x part) and compare with and without the hips as twist pair.
  LandmarkPositions standing = legJoints (), seated = seatedLegJoints ();
  standing["knee"] = {30, -200, 0};
  const Eigen::AngleAxisd forward (-M_PI / 2, Eigen::Vector3d::UnitX ());
  seated["knee"] = forward * standing["knee"];
  const auto with_twist = morphreg::estimateBoneTransforms (makeLegSkeleton (), standing, seated);
  EXPECT_LT ((with_twist[0].linear () - forward.toRotationMatrix ()).norm (), 1e-9);
  const Skeleton untwisted ({{"upperleg", "hip", "knee", "leg", "", ""}});
  const auto shortest = morphreg::estimateBoneTransforms (untwisted, standing, seated);
  EXPECT_GT ((shortest[0].linear () - forward.toRotationMatrix ()).norm (), 0.05);
  EXPECT_LT ((shortest[0] * standing["knee"] - seated["knee"]).norm (), 1e-9) << "both carry the tail";
}

TEST (SkeletonTest, BadSkeletonsAndJointsAreNamed)
{
  using morphreg::InvalidInputError;
  expectErrorContaining<InvalidInputError> ([] { Skeleton ({}); }, "no bones");
  expectErrorContaining<InvalidInputError> (
      [] {
        Skeleton ({{"a", "hip", "knee", "leg", "", ""}, {"a", "knee", "ankle", "leg", "", ""}});
      },
      "two bones are named 'a'");
  expectErrorContaining<InvalidInputError> (
      [] {
        Skeleton ({{"a", "hip", "hip", "leg", "", ""}});
      },
      "bone 'a': head and tail are the same joint 'hip'");
  expectErrorContaining<InvalidInputError> (
      [] {
        Skeleton ({{"a", "hip", "knee", "leg", "hip.R", ""}});
      },
      "bone 'a': give both twist joints or neither");
  const Skeleton skeleton = makeLegSkeleton ();
  LandmarkPositions missing = seatedLegJoints ();
  missing.erase ("ankle");
  expectErrorContaining<InvalidInputError> ([&] { morphreg::estimateBoneTransforms (skeleton, legJoints (), missing); },
                                            "the target joints lack joints the skeleton's bones need: ankle");
  LandmarkPositions coincident = legJoints ();
  coincident["knee"] = coincident["hip"];
  expectErrorContaining<InvalidInputError> (
      [&] { morphreg::estimateBoneTransforms (skeleton, coincident, seatedLegJoints ()); },
      "bone 'upperleg' in the source joints: joints 'hip' and 'knee' coincide");
  LandmarkPositions twist = seatedLegJoints ();
  twist["hip.R"] = twist["hip"];
  expectErrorContaining<InvalidInputError> (
      [&] { morphreg::estimateBoneTransforms (skeleton, legJoints (), twist); },
      "bone 'upperleg' (twist) in the target joints: joints 'hip.R' and 'hip' coincide");
  LandmarkPositions not_finite = legJoints ();
  not_finite["ankle"].x () = std::nan ("");
  expectErrorContaining<InvalidInputError> (
      [&] { morphreg::estimateBoneTransforms (skeleton, not_finite, seatedLegJoints ()); },
      "the source joints: joint 'ankle' is not finite");
}

TEST (SkinningWeightsTest, WeightsArePartitionOfUnityAndFollowTheNearerBone)
{
  const TriangleMesh leg = makeLeg ();
  const ArticulatedWarp warp (makeLegSkeleton (), std::vector<int> (leg.numVertices (), 0), {"leg"});
  ArticulatedWarp posed = warp;
  posed.setJoints (legJoints (), seatedLegJoints ());
  const Eigen::MatrixXd weights = posed.skinningWeights (leg);
  for (Eigen::Index v = 0; v < leg.numVertices (); ++v) {
    EXPECT_NEAR (weights.row (v).sum (), 1.0, 1e-12);
    const double y = leg.vertices (1, v);
    const double thigh = weights (v, 0);
    if (y > -20.0) {
      EXPECT_GT (thigh, 0.99) << "the hip end follows the thigh";
    }
    if (y < -380.0) {
      EXPECT_LT (thigh, 0.01) << "the ankle end follows the shin";
    }
    if (std::abs (y + 200.0) < 1.0) {
      EXPECT_NEAR (thigh, 0.5, 0.2) << "both bones count at the knee";
    }
  }
}

TEST (ArticulatedWarpTest, RigidPartsFollowTheirBonesAndLandmarksArePinned)
{
  const TriangleMesh leg = makeLeg ();
  ArticulatedWarp warp (makeLegSkeleton (), std::vector<int> (leg.numVertices (), 0), {"leg"});
  warp.setJoints (legJoints (), seatedLegJoints ());
  warp.setRigidity (0.0);
  const TriangleMesh skinned = warp.warp (leg);
  EXPECT_EQ (skinned.vertices, warp.skin (leg).vertices) << "rigidity 0 is skinning alone";
  const Eigen::AngleAxisd forward (-M_PI / 2, Eigen::Vector3d::UnitX ());
  const Eigen::Vector3d down_again (0, 200, 200); // the shin's translation
  for (Eigen::Index v = 0; v < leg.numVertices (); ++v) {
    const Eigen::Vector3d p = leg.vertices.col (v);
    if (p.y () > -20.0) {
      EXPECT_LT ((skinned.vertices.col (v) - forward * p).norm (), 3.0);
    }
    if (p.y () < -380.0) {
      EXPECT_LT ((skinned.vertices.col (v) - (p + down_again)).norm (), 3.0);
    }
  }
  warp.setRigidity (1.0);
  const std::vector<int> pinned = {0, 500};
  Eigen::Matrix3Xd targets (3, 2);
  targets.col (0) = forward * leg.vertices.col (0) + Eigen::Vector3d (0, 0, 5);
  targets.col (1) = skinned.vertices.col (500) + Eigen::Vector3d (3, 0, 0);
  warp.setSurfaceLandmarks (pinned, targets);
  const TriangleMesh refined = warp.warp (leg);
  for (int k = 0; k < 2; ++k)
    EXPECT_LT ((refined.vertices.col (pinned[k]) - targets.col (k)).norm (), 0.05);
  EXPECT_EQ (refined.triangles, leg.triangles);
}

TEST (ArticulatedWarpTest, RefinementKeepsARigidMotionAndReducesDistortion)
{
  const TriangleMesh leg = makeLeg ();
  const Eigen::Isometry3d motion = randomMotion (7);
  const morphreg::AsRigidAsPossible refinement (leg, 10.0, Eigen::VectorXd::Ones (leg.numVertices ()));
  const Eigen::Matrix3Xd moved = motion * leg.vertices;
  EXPECT_LT ((refinement.refine (moved, 5) - moved).cwiseAbs ().maxCoeff (), 1e-6) << "a rigid copy stays";
  // A squashed copy: the refinement brings the edge lengths back towards the rest shape's.
  Eigen::Matrix3Xd squashed = leg.vertices;
  squashed.row (0) *= 0.5;
  const Eigen::Matrix3Xd refined = refinement.refine (squashed, 10);
  auto edge_error = [&] (const Eigen::Matrix3Xd& positions) {
    double error = 0.0;
    for (Eigen::Index t = 0; t < leg.numTriangles (); ++t)
      for (int k = 0; k < 3; ++k) {
        const int a = leg.triangles (k, t), b = leg.triangles ((k + 1) % 3, t);
        error += std::abs ((positions.col (a) - positions.col (b)).norm () -
                           (leg.vertices.col (a) - leg.vertices.col (b)).norm ());
      }
    return error;
  };
  EXPECT_LT (edge_error (refined), 0.7 * edge_error (squashed));
}

TEST (ArticulatedWarpTest, BadInputIsNamed)
{
  using morphreg::InvalidInputError;
  const TriangleMesh leg = makeLeg ();
  const std::vector<int> labels (leg.numVertices (), 0);
  expectErrorContaining<InvalidInputError> ([&] { ArticulatedWarp (makeLegSkeleton (), labels, {"arm"}); },
                                            "bone 'upperleg' carries segment 'leg', which the labels do not have "
                                            "(they have: arm)");
  expectErrorContaining<InvalidInputError> (
      [&] { ArticulatedWarp (makeLegSkeleton (), std::vector<int> (leg.numVertices (), 2), {"leg"}); },
      "vertex 0 has segment label 2, outside [0, 1)");
  ArticulatedWarp warp (makeLegSkeleton (), labels, {"leg"});
  expectErrorContaining<InvalidInputError> ([&] { warp.warp (leg); }, "no joints set");
  warp.setJoints (legJoints (), seatedLegJoints ());
  TriangleMesh smaller = leg;
  smaller.vertices.conservativeResize (3, 100);
  smaller.triangles.resize (3, 0);
  expectErrorContaining<InvalidInputError> ([&] { warp.skin (smaller); }, "mesh");
  expectErrorContaining<InvalidInputError> ([&] { warp.setSurfaceLandmarks ({5000}, Eigen::Matrix3Xd::Zero (3, 1)); },
                                            "surface landmark vertex 5000 is not a vertex");
  expectErrorContaining<InvalidInputError> (
      [&] {
        warp.setSurfaceLandmarks ({7, 7}, Eigen::Matrix3Xd::Zero (3, 2));
      },
      "two surface landmarks lie on vertex 7");
  expectErrorContaining<InvalidInputError> ([&] { warp.setRigidity (-1.0); }, "rigidity");
  expectErrorContaining<InvalidInputError> ([&] { warp.setSkinningFalloff ({0.0, 8.0}); }, "width");
  // Two segments, the second without a bone.
  std::vector<int> two = labels;
  two.back () = 1;
  ArticulatedWarp boneless (makeLegSkeleton (), two, {"leg", "arm"});
  boneless.setJoints (legJoints (), seatedLegJoints ());
  expectErrorContaining<InvalidInputError> ([&] { boneless.warp (leg); }, "segment 1 (of vertex");
}

// --- The seed paper's re-posturing on the MakeHuman bodies (../shared/data/makehuman_bodies), in millimetres. ------

namespace
{
void
report (const std::string& name, const morphreg::WarpQuality& q, const std::vector<morphreg::LimbPartError>& parts)
{
  std::cout << "  " << name << ": mean " << q.mean_error << " mm, max " << q.max_error << " mm, seam " << q.seam
            << ", folded " << q.folded << " (truth collapsed " << q.collapsed << ")";
  for (const auto& part : parts)
    std::cout << ", " << part.part << " max " << part.max_error << " mm (" << part.vertices << " vertices)";
  std::cout << "\n";
}
} // namespace

namespace
{
/** The thigh, shin and upper-arm maxima of \a warped against \a truth. */
std::vector<morphreg::LimbPartError>
limbErrors (const TriangleMesh& source, const TriangleMesh& warped, const TriangleMesh& truth, const Skeleton& skeleton,
            const LandmarkPositions& joints)
{
  const Eigen::VectorXd errors = (warped.vertices - truth.vertices).colwise ().norm ().transpose ();
  return morphreg::limbPartErrors (source, errors, skeleton, joints);
}
} // namespace

// Standing to seated with the 51 major joints, the largest over the three bodies. Measured: mean 0.745 mm (0.656 and
// 0.690 for the others), seam 0.066, shin 25.4 mm, upper arm 0.012 mm, thigh 40.1 mm. The identity warp (the
// standing body as it is) lies 118.8-134.1 mm from the seated truth on average (thigh 538-608 mm, shin 562-633 mm). The upper arm stays still in the seated
// truth: its bound guards the refinement against moving it, which the identity warp also meets.
constexpr double kSeatedMean = 0.85, kSeatedSeam = 0.075, kSeatedShin = 30.0, kSeatedUpperArm = 0.015;
// The issue's target for the thigh is 30 mm; the buttock and crotch vertices nearest the thigh bones stay at 26 to 40
// mm, against 120 to 150 mm for TPS. The seated truth is linear blend skinning with MakeHuman's painted weights, which
// keep the buttocks with the pelvis and the groin with the thigh: at the same geodesic distances the true thigh weight
// runs from 0.38 to 0.83, so no weight derived from them gets the base body under 37.6 mm.
constexpr double kSeatedThigh = 42.0;

TEST (ArticulatedWarpTest, RepostureStandingToSeatedWithMajorJoints)
{
  REQUIRE_BODIES ();
  const morphreg::MakeHumanBodies bodies (bodiesDirectory ());
  const Skeleton skeleton = morphreg::makeHumanSkeleton ();
  double mean = 0.0, seam = 0.0, thigh = 0.0, shin = 0.0, upper_arm = 0.0; // the largest over the bodies
  for (const auto& subject : bodies.subjects ()) {
    const TriangleMesh standing = bodies.loadMesh (subject, morphreg::BodyPose::standing);
    const TriangleMesh seated = bodies.loadMesh (subject, morphreg::BodyPose::seated);
    const LandmarkPositions source = bodies.namedJoints (subject, morphreg::BodyPose::standing, bodies.majorJoints ());
    ArticulatedWarp warp (skeleton, bodies.segmentLabels (), bodies.segmentNames ());
    warp.setJoints (source, bodies.namedJoints (subject, morphreg::BodyPose::seated, bodies.majorJoints ()));
    const TriangleMesh skinned = warp.skin (standing), refined = warp.warp (standing);
    const auto labels = bodies.segmentLabels ();
    const auto q_skinned = morphreg::evaluateWarp (skinned, seated, labels, 100.0, &standing);
    const auto q = morphreg::evaluateWarp (refined, seated, labels, 100.0, &standing);
    const auto parts = limbErrors (standing, refined, seated, skeleton, source);
    std::cout << subject << " standing -> seated (51 major joints):\n";
    report ("skinned", q_skinned, limbErrors (standing, skinned, seated, skeleton, source));
    report ("refined", q, parts);
    const int truth_folds = morphreg::countFoldedTriangles (seated);
    std::cout << "  folded triangles: standing " << morphreg::countFoldedTriangles (standing) << ", seated truth "
              << truth_folds << ", skinned " << morphreg::countFoldedTriangles (skinned) << ", refined "
              << morphreg::countFoldedTriangles (refined) << "\n";
    EXPECT_LE (morphreg::countFoldedTriangles (refined), truth_folds) << subject;
    EXPECT_LT (parts[0].max_error, limbErrors (standing, skinned, seated, skeleton, source)[0].max_error + 1e-9)
        << subject << ": the refinement does not make the thigh worse";
    mean = std::max (mean, q.mean_error);
    seam = std::max (seam, q.seam);
    thigh = std::max (thigh, parts[0].max_error);
    shin = std::max (shin, parts[1].max_error);
    upper_arm = std::max (upper_arm, parts[2].max_error);
  }
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, mean, kSeatedMean);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, seam, kSeatedSeam);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, thigh, kSeatedThigh);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, shin, kSeatedShin);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, upper_arm, kSeatedUpperArm);
}

TEST (ArticulatedWarpTest, IdentityWarpFailsTheRepostureBounds)
{
  REQUIRE_BODIES ();
  const morphreg::MakeHumanBodies bodies (bodiesDirectory ());
  const Skeleton skeleton = morphreg::makeHumanSkeleton ();
  for (const auto& subject : bodies.subjects ()) {
    const TriangleMesh standing = bodies.loadMesh (subject, morphreg::BodyPose::standing);
    const TriangleMesh seated = bodies.loadMesh (subject, morphreg::BodyPose::seated);
    const LandmarkPositions source = bodies.namedJoints (subject, morphreg::BodyPose::standing, bodies.majorJoints ());
    const auto q = morphreg::evaluateWarp (standing, seated, bodies.segmentLabels (), 100.0, &standing);
    const auto parts = limbErrors (standing, standing, seated, skeleton, source);
    std::cout << subject << " standing as it is, against seated:\n";
    report ("identity", q, parts);
    EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, q.mean_error, kSeatedMean) << subject;
    EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, parts[0].max_error, kSeatedThigh) << subject;
    EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, parts[1].max_error, kSeatedShin) << subject;
  }
}

TEST (ArticulatedWarpTest, BetweenSubjectsWithJointsAndSurfaceLandmarks)
{
  REQUIRE_BODIES ();
  const morphreg::MakeHumanBodies bodies (bodiesDirectory ());
  const TriangleMesh base = bodies.loadMesh ("base", morphreg::BodyPose::standing);
  const LandmarkPositions source = bodies.namedJoints ("base", morphreg::BodyPose::standing, bodies.majorJoints ());
  const std::vector<int>& surface = bodies.surfaceVertices ();
  double mean = 0.0, landmarks = 0.0;                              // the worst fit
  double identity_mean = std::numeric_limits<double>::infinity (); // the best identity
  for (const auto& subject : bodies.subjects ()) {
    if (subject == "base")
      continue;
    const TriangleMesh truth = bodies.loadMesh (subject, morphreg::BodyPose::standing);
    ArticulatedWarp warp (morphreg::makeHumanSkeleton (), bodies.segmentLabels (), bodies.segmentNames ());
    warp.setJoints (source, bodies.namedJoints (subject, morphreg::BodyPose::standing, bodies.majorJoints ()));
    Eigen::Matrix3Xd targets (3, static_cast<Eigen::Index> (surface.size ()));
    for (std::size_t k = 0; k < surface.size (); ++k)
      targets.col (static_cast<Eigen::Index> (k)) = truth.vertices.col (surface[k]);
    warp.setSurfaceLandmarks (surface, targets);
    const TriangleMesh warped = warp.warp (base);
    const auto q = morphreg::evaluateWarp (warped, truth, bodies.segmentLabels (), 100.0, &base);
    std::cout << "base -> " << subject << " (51 joints + 16 surface landmarks):\n";
    report ("articulated", q, {});
    double landmark = 0.0;
    for (std::size_t k = 0; k < surface.size (); ++k)
      landmark =
          std::max (landmark, (warped.vertices.col (surface[k]) - targets.col (static_cast<Eigen::Index> (k))).norm ());
    const auto identity = morphreg::evaluateWarp (base, truth, bodies.segmentLabels (), 100.0, &base);
    std::cout << "  surface landmarks within " << landmark << " mm; the base body as it is: mean "
              << identity.mean_error << " mm\n";
    landmarks = std::max (landmarks, landmark);
    mean = std::max (mean, q.mean_error);
    identity_mean = std::min (identity_mean, identity.mean_error);
  }
  // Rigid bones cannot change the body's girth or the length of a bone: between subjects the mean stays far above the
  // issue's 8 mm (with the same landmarks a TPS reaches 9.4-9.7 mm and the moving least squares warp 8.6-8.7 mm,
  // MovingLeastSquaresWarpTest); the landmarks are followed. Measured: mean 20.3 and 27.6 mm, landmarks within
  // 0.014 mm; the base body as it is 59.2 and 73.1 mm.
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, mean, 30.0);
  EXPECT_PRED_FORMAT2 (morphreg::test::tightUpperBound, landmarks, 0.017);
  EXPECT_PRED_FORMAT2 (morphreg::test::noOpFailsUpperBound, identity_mean, 30.0);
}

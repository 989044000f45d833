// SPDX-License-Identifier: BSD-3-Clause
// The starts of a fit as objects (initial_alignment_strategy.h): each finds a known similarity of the model's mean
// head, the automatic start chooses as documented, a start of the user's own is what MorphableICP starts from and
// reports, and names and null starts are refused clearly.
#include "scan_protocol.h"
#include "support/expect_error.h"
#include "support/synthetic_heads.h"

#include <morphreg/common/cloud_matrix.h>
#include <morphreg/common/error.h>
#include <morphreg/model/model_builder.h>
#include <morphreg/registration/initial_alignment_strategy.h>
#include <morphreg/registration/morphable_icp.h>
#include <morphreg/registration/registration_settings.h>
#include <morphreg/synthetic/head_generator.h>

#include <pcl/kdtree/kdtree_flann.h>

#include <gtest/gtest.h>

namespace
{
using morphreg::InvalidInputError;
using morphreg::StartEstimate;
using morphreg::StartInputs;
using morphreg::test::expectErrorContaining;

constexpr int kResolution = 24;

const morphreg::MorphableModel::ConstPtr&
smallModel ()
{
  static const morphreg::MorphableModel::ConstPtr model = [] {
    const auto& generator = morphreg::test::headGenerator (kResolution);
    std::vector<morphreg::TriangleMesh> meshes;
    for (auto& head : generator.population (30, 1000))
      meshes.push_back (std::move (head.mesh));
    morphreg::ModelBuilderSettings settings;
    settings.max_components = 5;
    auto built = morphreg::ModelBuilder (settings).build (meshes, generator.regions ());
    built->setLandmarks (generator.landmarks ());
    return morphreg::MorphableModel::ConstPtr (built);
  }();
  return model;
}

morphreg::TriangleMesh
meanHead ()
{
  const auto& model = *smallModel ();
  return {Eigen::Map<const Eigen::Matrix3Xd> (model.mean ().data (), 3, model.numVertices ()), model.triangles ()};
}

/** The mean head scanned in a known pose (without noise or outliers, landmarks exact). */
morphreg::test::ProtocolScan
posedMeanHead ()
{
  morphreg::test::ProtocolSettings settings;
  settings.points = 8000;
  settings.noise_sigma = 0.0;
  settings.outlier_fraction = 0.0;
  settings.landmark_sigma = 0.0;
  return morphreg::test::simulateProtocolScan (meanHead (), smallModel ()->landmarks (), 7, settings);
}

/** What MorphableICP gives a start for \a scan, with the landmarks when \a with_landmarks. */
struct StartFixture
{
  morphreg::test::ProtocolScan scan = posedMeanHead ();
  pcl::KdTreeFLANN<pcl::PointNormal> tree;
  StartInputs inputs;

  explicit StartFixture (bool with_landmarks)
  {
    const auto& model = *smallModel ();
    inputs.model_mean = meanHead ();
    inputs.target = morphreg::pointsOf (*scan.cloud);
    inputs.target_normals = morphreg::normalsOf (*scan.cloud);
    tree.setInputCloud (scan.cloud);
    inputs.target_neighbours = [this] (Eigen::Index i, int k, pcl::Indices& indices, std::vector<float>& squared) {
      tree.nearestKSearch ((*scan.cloud)[i], k, indices, squared);
    };
    if (!with_landmarks)
      return;
    inputs.model_landmarks.resize (3, static_cast<Eigen::Index> (scan.landmarks.size ()));
    inputs.target_landmarks.resize (3, static_cast<Eigen::Index> (scan.landmarks.size ()));
    Eigen::Index k = 0;
    for (const auto& [name, position] : scan.landmarks) {
      inputs.model_landmarks.col (k) = model.meanVertex (model.landmarkVertex (name));
      inputs.target_landmarks.col (k++) = position;
    }
  }

  /** RMS distance (mm) of the mean head mapped by \a similarity from where the scan's pose puts it. */
  double
  error (const Eigen::Matrix4d& similarity) const
  {
    const Eigen::Affine3d mapped (similarity);
    return morphreg::test::vertexRms (mapped * inputs.model_mean.vertices, scan.truth);
  }
};

TEST (InitialAlignmentStrategyTest, EveryStartIsRegisteredByName)
{
  const std::vector<std::string> expected = {"auto", "guess", "landmarks", "coarse", "global"};
  EXPECT_EQ (morphreg::initialAlignmentNames (), expected);
  for (const std::string& name : expected)
    EXPECT_EQ (morphreg::makeInitialAlignment (name)->name (), name);
  expectErrorContaining<InvalidInputError> ([] { morphreg::makeInitialAlignment ("somewhere"); },
                                            "initial alignment \"somewhere\" is none of auto, guess, landmarks");
  morphreg::RegistrationSettings settings;
  settings.start = "somewhere";
  expectErrorContaining<InvalidInputError> ([&] { morphreg::requireValidSettings (settings); }, "start");
}

TEST (InitialAlignmentStrategyTest, EachStartFindsAKnownPose)
{
  StartFixture fixture (true);
  const StartEstimate landmarks = morphreg::makeInitialAlignment ("landmarks")->estimate (fixture.inputs);
  EXPECT_EQ (landmarks.method, "landmarks");
  EXPECT_LT (fixture.error (landmarks.similarity), 1e-6) << "exact landmarks give the pose exactly";
  fixture.inputs.guess = fixture.scan.pose;
  const StartEstimate guess = morphreg::makeInitialAlignment ("guess")->estimate (fixture.inputs);
  EXPECT_EQ (guess.similarity, fixture.scan.pose);
  fixture.inputs.guess.setIdentity ();
  for (const std::string name : {"coarse", "global"}) {
    const StartEstimate found = morphreg::makeInitialAlignment (name)->estimate (fixture.inputs);
    std::cout << name << " start: " << fixture.error (found.similarity) << " mm vertex RMS from the pose\n";
    EXPECT_EQ (found.method, name);
    EXPECT_LT (fixture.error (found.similarity), 1.0) << name;
  }
  const StartEstimate global = morphreg::makeInitialAlignment ("global")->estimate (fixture.inputs);
  EXPECT_FALSE (global.detail.empty ());
  EXPECT_GT (global.head_points, 0);
}

TEST (InitialAlignmentStrategyTest, TheAutomaticStartChoosesGuessThenLandmarksThenGlobal)
{
  const auto automatic = morphreg::makeInitialAlignment ("auto");
  StartFixture with_landmarks (true);
  EXPECT_EQ (automatic->estimate (with_landmarks.inputs).method, "landmarks");
  with_landmarks.inputs.guess = with_landmarks.scan.pose;
  EXPECT_EQ (automatic->estimate (with_landmarks.inputs).method, "guess");
  StartFixture without (false);
  EXPECT_EQ (automatic->estimate (without.inputs).method, "global");
  expectErrorContaining<InvalidInputError> (
      [&] { morphreg::makeInitialAlignment ("landmarks")->estimate (without.inputs); }, "needs >= 3 target landmarks");
}

/** A start of the user's own: the pose the test knows. */
class KnownPoseStart : public morphreg::InitialAlignmentStrategy
{
public:
  explicit KnownPoseStart (const Eigen::Matrix4d& pose) : pose_ (pose) {}

  std::string
  name () const override
  {
    return "known pose";
  }

  StartEstimate
  estimate (const StartInputs& inputs) const override
  {
    EXPECT_GT (inputs.target.cols (), 0);
    StartEstimate found;
    found.similarity = pose_;
    found.method = name ();
    return found;
  }

private:
  Eigen::Matrix4d pose_;
};

TEST (InitialAlignmentStrategyTest, MorphableIcpStartsFromAStartOfTheUsersOwnAndReportsIt)
{
  const morphreg::test::ProtocolScan scan = posedMeanHead ();
  morphreg::MorphableICP<pcl::PointNormal> icp;
  icp.setModel (smallModel ());
  expectErrorContaining<InvalidInputError> ([&] { icp.setInitialAlignment (nullptr); }, "no start");
  icp.setInitialAlignment (std::make_shared<KnownPoseStart> (scan.pose));
  EXPECT_EQ (icp.getInitialAlignment ()->name (), "known pose");
  icp.setMaximumIterations (3);
  icp.setSimilarityIterations (3);
  icp.setInputTarget (scan.cloud);
  pcl::PointCloud<pcl::PointNormal> output;
  icp.align (output);
  EXPECT_EQ (icp.getRegistrationReport ().initialisation, "known pose");
  const Eigen::Affine3d found (icp.getFinalTransformation ().cast<double> ());
  EXPECT_LT (morphreg::test::vertexRms (found * meanHead ().vertices, scan.truth), 1.0);
}
} // namespace

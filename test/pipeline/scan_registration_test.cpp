// SPDX-License-Identifier: BSD-3-Clause
// The library's scan registration (pipeline/scan_registration.h), the sequence `morphreg register` and
// morphreg.register run: units given, guessed and estimated, landmarks in either unit, lost fits reported, bad input
// named.
#include "registration/scan_protocol.h"
#include "support/expect_error.h"
#include "support/synthetic_heads.h"

#include <morphreg/common/error.h>
#include <morphreg/pipeline/scan_input.h>
#include <morphreg/pipeline/scan_registration.h>

#include <nlohmann/json.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace
{
using morphreg::LandmarkPositions;
using morphreg::LandmarkUnit;
using morphreg::MorphableModel;
using morphreg::ScanInput;
using morphreg::ScanRegistration;
using morphreg::ScanRegistrationOutcome;
using morphreg::test::expectErrorContaining;

constexpr int kTrainingHeads = 40;

/** Everything a registration told, in order. */
class RecordingObserver : public morphreg::RegistrationObserver
{
public:
  void
  fitStarted (const std::string& scan_name, int max_iterations) override
  {
    events.push_back ("start " + scan_name + " " + std::to_string (max_iterations));
  }
  void
  iterationDone (int, std::size_t, double rms) override
  {
    ++iterations;
    EXPECT_TRUE (std::isfinite (rms));
  }
  void
  fitFinished (int done) override
  {
    events.push_back ("finish " + std::to_string (done));
  }
  void
  message (const std::string& text) override
  {
    events.push_back (text);
  }
  void
  warning (const std::string& text) override
  {
    events.push_back ("warning " + text);
  }

  std::vector<std::string> events;
  int iterations = 0;
};

class ScanRegistrationTest : public ::testing::Test
{
protected:
  static void
  SetUpTestSuite ()
  {
    model_ = new MorphableModel::ConstPtr (morphreg::test::headModel (kTrainingHeads, 10));
  }

  static void
  TearDownTestSuite ()
  {
    delete model_;
  }

  /** A head of the model's kind, scanned by the accuracy tests' protocol at \a scale (1 when \a min_scale equals
   *  \a max_scale). */
  static morphreg::test::ProtocolScan
  protocolScan (std::uint64_t seed, double min_scale = 0.8, double max_scale = 1.2)
  {
    const MorphableModel& model = **model_;
    std::mt19937_64 rng (seed);
    const auto selection = model.firstComponents (10);
    const morphreg::TriangleMesh head = model.generateMesh (model.sampleCoefficients (rng, selection), selection);
    morphreg::test::ProtocolSettings settings;
    settings.min_scale = min_scale;
    settings.max_scale = max_scale;
    return morphreg::test::simulateProtocolScan (head, model.landmarks (), seed, settings);
  }

  /** \a scan's points times \a factor, as a scan named \a name. */
  static ScanInput
  scaled (const morphreg::test::ProtocolScan& scan, double factor, const std::string& name)
  {
    pcl::PointCloud<pcl::PointNormal> cloud = *scan.cloud;
    for (auto& point : cloud)
      point.getVector3fMap () *= static_cast<float> (factor);
    return morphreg::makeScanInput (cloud, name);
  }

  static LandmarkPositions
  scaledLandmarks (const LandmarkPositions& landmarks, double factor)
  {
    LandmarkPositions scaled = landmarks;
    for (auto& entry : scaled)
      entry.second *= factor;
    return scaled;
  }

  static double
  vertexRms (const ScanRegistrationOutcome& fit, const Eigen::Matrix3Xd& truth)
  {
    return morphreg::test::vertexRms (fit.fittedMesh ().vertices, truth);
  }

  static MorphableModel::ConstPtr* model_;
};

MorphableModel::ConstPtr* ScanRegistrationTest::model_ = nullptr;

TEST_F (ScanRegistrationTest, AScanInMetresIsFittedInMillimetresAndSaysSo)
{
  const auto scan = protocolScan (11);
  RecordingObserver observer;
  ScanRegistration registration (*model_);
  registration.setObserver (&observer);
  registration.setLandmarks (scaledLandmarks (scan.landmarks, 1e-3), "metre landmarks", LandmarkUnit::scan);
  const ScanRegistrationOutcome in_metres = registration.registerScan (scaled (scan, 1e-3, "head.pcd"));
  ASSERT_FALSE (in_metres.lostScan ()) << in_metres.lost;
  EXPECT_EQ (in_metres.unit.unit, morphreg::LengthUnit::metre);
  const double rms = vertexRms (in_metres, scan.truth);
  std::printf ("[ pipeline ] a scan in metres: vertex RMS %.3f mm against the truth, %d iterations\n", rms,
               observer.iterations);
  EXPECT_LT (rms, 1.0);
  ASSERT_GE (observer.events.size (), 3u);
  EXPECT_NE (observer.events[0].find ("units: the scan's unit is m ("), std::string::npos) << observer.events[0];
  EXPECT_EQ (observer.events[1], "start head.pcd 100");
  EXPECT_EQ (observer.events[2], "finish " + std::to_string (observer.iterations));

  const nlohmann::json report = registration.report (in_metres);
  EXPECT_EQ (report["status"], "ok");
  EXPECT_EQ (report["scan"]["units"], "m");
  EXPECT_EQ (report["scan"]["scale_to_mm"], 1000.0);
  EXPECT_EQ (report["settings"]["iterations"], 100);
  EXPECT_EQ (report["model"]["vertices"], (*model_)->numVertices ());

  // the same head in mm, its landmarks from a file (mm), fits to the same vertices
  ScanRegistration in_mm_registration (*model_);
  in_mm_registration.setLandmarks (scan.landmarks, "mm landmarks", LandmarkUnit::millimetre);
  const ScanRegistrationOutcome in_mm = in_mm_registration.registerScan (scaled (scan, 1.0, "head_mm.pcd"));
  ASSERT_FALSE (in_mm.lostScan ());
  EXPECT_LT (morphreg::test::vertexRms (in_mm.fittedMesh ().vertices, in_metres.fittedMesh ().vertices), 0.05);
}

TEST_F (ScanRegistrationTest, LandmarksAreTakenInTheUnitTheyAreSaidToBeIn)
{
  const auto scan = protocolScan (12);
  ScanRegistration registration (*model_);
  // metre values said to be mm lie in a speck inside a scan read as metres and converted: refused, naming them
  registration.setLandmarks (scaledLandmarks (scan.landmarks, 1e-3), "picked.pp", LandmarkUnit::millimetre);
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] { registration.registerScan (scaled (scan, 1e-3, "head.pcd")); }, "picked.pp");
}

TEST_F (ScanRegistrationTest, AScanInNoUnitGetsItsScaleFromTheHead)
{
  const auto scan = protocolScan (13, 1.0, 1.0); // the model's own size
  constexpr double kMillimetresPerUnit = 93.0;   // a photogrammetry export whose unit is nobody's
  RecordingObserver observer;
  ScanRegistration registration (*model_);
  registration.setObserver (&observer);
  const ScanRegistrationOutcome fit = registration.registerScan (scaled (scan, 1.0 / kMillimetresPerUnit, "a.glb"));
  ASSERT_FALSE (fit.lostScan ()) << fit.lost;
  EXPECT_TRUE (fit.unit.estimated);
  const auto fits = std::count_if (observer.events.begin (), observer.events.end (),
                                   [] (const std::string& event) { return event.rfind ("start ", 0) == 0; });
  std::printf ("[ pipeline ] a scan in no unit: estimated %.2f mm per unit (true %.0f), %d fits\n",
               fit.unit.scale_to_mm, kMillimetresPerUnit, static_cast<int> (fits));
  EXPECT_NEAR (fit.unit.scale_to_mm / kMillimetresPerUnit, 1.0, 0.1);
  EXPECT_EQ (registration.report (fit)["scan"]["units"], "estimated");
  EXPECT_LT (vertexRms (fit, scan.truth * (fit.unit.scale_to_mm / kMillimetresPerUnit)), 1.5);
}

TEST_F (ScanRegistrationTest, ALostScanIsReportedWithItsReason)
{
  const auto scan = protocolScan (14);
  morphreg::RegistrationSettings settings;
  settings.max_distance = 0.01; // no scan point that close
  settings.units = "mm";
  ScanRegistration registration (*model_, settings);
  const ScanRegistrationOutcome fit = registration.registerScan (scaled (scan, 1.0, "far.pcd"));
  ASSERT_TRUE (fit.lostScan ());
  EXPECT_FALSE (fit.lost.empty ());
  const nlohmann::json report = registration.report (fit);
  EXPECT_EQ (report["status"], "failed");
  EXPECT_EQ (report["checks"]["failures"][0], fit.lost);
  expectErrorContaining<morphreg::InvalidInputError> ([&] { fit.fittedMesh (); }, "far.pcd: the fit lost the scan");
}

TEST_F (ScanRegistrationTest, BadInputIsNamed)
{
  expectErrorContaining<morphreg::InvalidInputError> ([] { ScanRegistration (nullptr); }, "no model");
  morphreg::RegistrationSettings settings;
  settings.iterations = 0;
  expectErrorContaining<morphreg::InvalidInputError> ([&] { ScanRegistration (*model_, settings); },
                                                      "iterations = 0 is out of range");
  ScanRegistration registration (*model_);
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] {
        registration.registerScan (ScanInput{nullptr, std::nullopt, "null.pcd", std::nullopt});
      },
      "null.pcd");
  LandmarkPositions unknown_to_model{{"ibug68_30", Eigen::Vector3d::Zero ()}};
  expectErrorContaining<morphreg::InvalidInputError> (
      [&] { registration.setLandmarks (unknown_to_model, "marks.json", LandmarkUnit::millimetre); },
      "marks.json: none of its landmarks is on the model");

  pcl::PointCloud<pcl::PointNormal> empty;
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::makeScanInput (empty, "empty.ply"); },
                                                "empty.ply: the scan has no valid");
  pcl::PointCloud<pcl::PointNormal> missing (10, 10);
  for (auto& point : missing)
    point.x = point.y = point.z = std::numeric_limits<float>::quiet_NaN ();
  expectErrorContaining<morphreg::FormatError> ([&] { morphreg::makeScanInput (missing, "frame.pcd"); },
                                                "frame.pcd: the scan has no valid");
}

TEST_F (ScanRegistrationTest, AnOrganisedCloudIsOneViewWithoutItsMissingPoints)
{
  const auto scan = protocolScan (15);
  pcl::PointCloud<pcl::PointNormal> organised = *scan.cloud;
  organised.resize (organised.size () / 100 * 100);
  organised.width = 100;
  organised.height = static_cast<std::uint32_t> (organised.size () / 100);
  organised[7].x = std::numeric_limits<float>::quiet_NaN ();
  organised.sensor_origin_ = Eigen::Vector4f (10.0f, 20.0f, 30.0f, 1.0f);
  const ScanInput input = morphreg::makeScanInput (organised, "frame.pcd");
  ASSERT_TRUE (input.viewpoint.has_value ());
  EXPECT_EQ (*input.viewpoint, Eigen::Vector3d (10.0, 20.0, 30.0));
  EXPECT_EQ (input.cloud->size (), organised.size () - 1);
  EXPECT_TRUE (input.cloud->is_dense);
}

} // namespace

// SPDX-License-Identifier: BSD-3-Clause
// MorphableICP's defaults are the command line's: a PCL-tutorial program (a new MorphableICP, setModel,
// setInputTarget, align) fits the real Lee Perry-Smith scan as `morphreg register` does at its defaults (the library
// path it takes: configureRegistration with RegistrationSettings{}), through the class and a pcl::Registration pointer.
#include "real_scan_support.h"

#include <morphreg/registration/registration_settings.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>

namespace
{
using namespace morphreg::test;
using Icp = morphreg::MorphableICP<pcl::PointNormal>;

TEST (RealScanDefaultsTest, TutorialProgramFitsTheLeeScanAsTheCommandLine)
{
  MORPHREG_REQUIRE_REAL_SCANS ();
  const auto scan = leeScan82k ();
  // The tutorial program, through a pcl::Registration pointer as PCL's tutorials hold their registrations.
  auto tutorial = std::make_shared<Icp> ();
  tutorial->setModel (ictModel30 ());
  const pcl::Registration<pcl::PointNormal, pcl::PointNormal>::Ptr registration = tutorial;
  registration->setInputTarget (scan);
  pcl::PointCloud<pcl::PointNormal> output;
  registration->align (output);

  Icp cli;
  morphreg::configureRegistration (cli, morphreg::RegistrationSettings (), ictModel30 ());
  cli.setInputTarget (scan);
  cli.align (output);

  const morphreg::IcpReport& ours = tutorial->getRegistrationReport ();
  const morphreg::IcpReport& theirs = cli.getRegistrationReport ();
  const FaceScore tutorial_face = faceScore (fitInScanFrame (*tutorial, Eigen::Matrix4d::Identity ()));
  const FaceScore cli_face = faceScore (fitInScanFrame (cli, Eigen::Matrix4d::Identity ()));
  std::printf ("[ defaults ] tutorial program: RMS %.4f mm, fitness score %.4f mm^2, %zu iterations, face median %.3f "
               "mm; command line's configuration: RMS %.4f mm, %zu iterations, face median %.3f mm\n",
               ours.fitness_rms, registration->getFitnessScore (), ours.history.size (), tutorial_face.face.median,
               theirs.fitness_rms, theirs.history.size (), cli_face.face.median);
  EXPECT_NEAR (ours.fitness_rms, theirs.fitness_rms, 0.01 * theirs.fitness_rms);
  EXPECT_NEAR (registration->getFitnessScore (), ours.fitness_rms * ours.fitness_rms,
               1e-4 * ours.fitness_rms * ours.fitness_rms);
  EXPECT_TRUE (registration->hasConverged ());
}

} // namespace

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/common/colour_map.h>
#include <morphreg/visualization/convergence_plot.h>
#include <morphreg/visualization/layer_toggles.h>
#include <morphreg/visualization/registration_visualizer.h>

#include "support/temp_directory.h"

#include <pcl/common/transforms.h>
#include <pcl/registration/icp.h>
#include <pcl/visualization/pcl_visualizer.h>

#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include "support/synthetic_heads.h"

#include <gtest/gtest.h>

#include <cstdlib>

using morphreg::RegistrationVisualizer;

namespace
{
const morphreg::synthetic::HeadGenerator&
generator ()
{
  return morphreg::test::headGenerator (24);
}

/** A PNG read back: size and the fraction of pixels, in the columns [x_from, x_to), that differ from the corner. */
struct Picture
{
  int width = 0, height = 0;
  vtkSmartPointer<vtkImageData> image;

  double
  coverage (double x_from = 0.0, double x_to = 1.0) const
  {
    const auto* pixels = static_cast<const unsigned char*> (image->GetScalarPointer ());
    const int channels = image->GetNumberOfScalarComponents ();
    const unsigned char* background = pixels; // the bottom-left corner is background
    long covered = 0, total = 0;
    for (int y = 0; y < height; ++y)
      for (int x = static_cast<int> (x_from * width); x < static_cast<int> (x_to * width); ++x, ++total) {
        const unsigned char* p = pixels + channels * (static_cast<long> (y) * width + x);
        covered +=
            std::abs (p[0] - background[0]) + std::abs (p[1] - background[1]) + std::abs (p[2] - background[2]) > 30
                ? 1
                : 0;
      }
    return static_cast<double> (covered) / total;
  }
};

Picture
readPng (const std::string& path)
{
  auto reader = vtkSmartPointer<vtkPNGReader>::New ();
  reader->SetFileName (path.c_str ());
  reader->Update ();
  Picture picture;
  picture.image = reader->GetOutput ();
  int dims[3];
  picture.image->GetDimensions (dims);
  picture.width = dims[0];
  picture.height = dims[1];
  return picture;
}

pcl::PointCloud<pcl::PointXYZ>::Ptr
verticesOf (const morphreg::TriangleMesh& mesh)
{
  pcl::PointCloud<pcl::PointXYZ>::Ptr cloud (new pcl::PointCloud<pcl::PointXYZ>);
  for (Eigen::Index v = 0; v < mesh.numVertices (); ++v)
    cloud->push_back (pcl::PointXYZ (static_cast<float> (mesh.vertices (0, v)),
                                     static_cast<float> (mesh.vertices (1, v)),
                                     static_cast<float> (mesh.vertices (2, v))));
  return cloud;
}
} // namespace

TEST (RegistrationVisualizerTest, HeatMapScreenshotHasTheSizeAndShowsTheHead)
{
  morphreg::test::TempDirectory dir;
  const auto a = generator ().sample (1).mesh, b = generator ().sample (2).mesh;
  const Eigen::VectorXd residuals = (a.vertices - b.vertices).colwise ().norm ().transpose ();
  RegistrationVisualizer viewer (RegistrationVisualizer::Display::Offscreen);
  viewer.addResidualHeatMap (a, residuals, 10.0);
  morphreg::LandmarkPositions landmarks;
  for (const auto& [id, vertex] : generator ().landmarks ())
    landmarks[id] = a.vertices.col (vertex);
  viewer.addLandmarks (landmarks, RegistrationVisualizer::LandmarkRole::Target);
  viewer.resetCamera ();
  const std::string png = dir.file ("heat.png");
  viewer.saveScreenshot (png, 640, 480);
  const Picture picture = readPng (png);
  EXPECT_EQ (picture.width, 640);
  EXPECT_EQ (picture.height, 480);
  const Eigen::Vector4d bar = RegistrationVisualizer::colourBarRegion ();
  const double geometry = picture.coverage (0.0, bar[0]);
  std::cout << "head covers " << 100.0 * geometry << "% of the image left of the colour bar\n";
  EXPECT_GE (geometry, 0.30) << "the head fills the picture left of the bar";
  EXPECT_GT (picture.coverage (bar[0], bar[2]), 0.02) << "the colour bar is drawn";
}

TEST (RegistrationVisualizerTest, BeforeAfterViewportsShowBothSides)
{
  morphreg::test::TempDirectory dir;
  const auto head = generator ().sample (3).mesh;
  RegistrationVisualizer viewer (RegistrationVisualizer::Display::Offscreen);
  int before = 0, after = 0;
  viewer.createBeforeAfterViewports (before, after);
  viewer.addTargetCloud (*verticesOf (head), "target_before", before);
  viewer.addModelMesh (head, 0.5, "model_after", after);
  pcl::Correspondences correspondences;
  for (int i = 0; i < 1000; ++i)
    correspondences.emplace_back (i, i, 0.0f);
  viewer.addCorrespondences (*verticesOf (head), *verticesOf (head), correspondences, 50, "lines", after);
  viewer.setMeshOpacity (0.8, "model_after");
  viewer.resetCamera (Eigen::Vector3d::UnitX ());
  viewer.saveScreenshot (dir.file ("split.png"), 800, 400);
  const Picture picture = readPng (dir.file ("split.png"));
  EXPECT_GE (picture.coverage (0.0, 0.5), 0.05) << "before";
  EXPECT_GE (picture.coverage (0.5, 1.0), 0.10) << "after";
}

TEST (RegistrationVisualizerTest, WatchesPclIcpIterate)
{
  const auto head = generator ().sample (4).mesh;
  const auto target = verticesOf (head);
  pcl::PointCloud<pcl::PointXYZ>::Ptr source (new pcl::PointCloud<pcl::PointXYZ>);
  const Eigen::Affine3f offset (Eigen::Translation3f (4.0f, -3.0f, 2.0f) *
                                Eigen::AngleAxisf (0.05f, Eigen::Vector3f::UnitY ()));
  pcl::transformPointCloud (*target, *source, offset);
  RegistrationVisualizer viewer (RegistrationVisualizer::Display::Offscreen);
  pcl::IterativeClosestPoint<pcl::PointXYZ, pcl::PointXYZ> icp;
  icp.setInputSource (source);
  icp.setInputTarget (target);
  icp.setMaximumIterations (5);
  auto callback = viewer.makeRegistrationCallback<pcl::PointXYZ, pcl::PointXYZ> (); // PCL takes it by reference
  icp.registerVisualizationCallback (callback);
  pcl::PointCloud<pcl::PointXYZ> aligned;
  icp.align (aligned);
  EXPECT_GE (viewer.getRegistrationUpdateCount (), 2u);
  EXPECT_TRUE (viewer.getVisualizer ().contains ("registration_source"));
  EXPECT_TRUE (viewer.getVisualizer ().contains ("registration_target"));
}

TEST (RegistrationVisualizerTest, BadInputIsRejected)
{
  morphreg::test::TempDirectory dir;
  const auto head = generator ().sample (5).mesh;
  RegistrationVisualizer viewer (RegistrationVisualizer::Display::Offscreen);
  EXPECT_THROW (viewer.addResidualHeatMap (head, Eigen::VectorXd::Zero (3)), morphreg::InvalidInputError);
  Eigen::VectorXd negative = Eigen::VectorXd::Ones (head.numVertices ());
  negative[7] = -1.0;
  EXPECT_THROW (viewer.addResidualHeatMap (head, negative), morphreg::InvalidInputError);
  EXPECT_THROW (viewer.addModelMesh (head, 1.5), morphreg::InvalidInputError);
  EXPECT_THROW (viewer.setMeshOpacity (0.5, "no_such_mesh"), morphreg::InvalidInputError);
  pcl::Correspondences wrong = {pcl::Correspondence (0, 999999, 0.0f)};
  EXPECT_THROW (viewer.addCorrespondences (*verticesOf (head), *verticesOf (head), wrong), morphreg::InvalidInputError);
  EXPECT_THROW (viewer.addTargetCloud (pcl::PointCloud<pcl::PointXYZ> ()), morphreg::InvalidInputError);
  EXPECT_THROW (viewer.saveScreenshot (dir.file ("zero.png"), 0, 100), morphreg::InvalidInputError);
  EXPECT_THROW (viewer.spin (), morphreg::InvalidInputError) << "offscreen has no window";
  viewer.addModelMesh (head);
  EXPECT_THROW (viewer.saveScreenshot (dir.file ("no/such/dir/x.png"), 64, 64), morphreg::IoError);

  const std::string display = std::getenv ("DISPLAY");
  unsetenv ("DISPLAY");
  EXPECT_THROW (RegistrationVisualizer (RegistrationVisualizer::Display::Offscreen), morphreg::Error);
  setenv ("DISPLAY", display.c_str (), 1);
}

TEST (RegistrationVisualizerTest, LayersHideTheFitWithItsColourBar)
{
  morphreg::test::TempDirectory dir;
  const auto head = generator ().sample (6).mesh;
  RegistrationVisualizer viewer (RegistrationVisualizer::Display::Offscreen);
  viewer.addResidualHeatMap (head, Eigen::VectorXd::LinSpaced (head.numVertices (), 0.0, 4.0), 4.0, "fit");
  viewer.addTargetCloud (*verticesOf (generator ().sample (7).mesh), "scan");
  morphreg::LayerToggles layers (viewer);
  layers.addLayer ("fit", 'm', {"fit"});
  layers.addLayer ("scan", 't', {"scan"});
  viewer.resetCamera ();
  const Eigen::Vector4d bar = RegistrationVisualizer::colourBarRegion ();
  layers.setVisible ("scan", false);
  viewer.saveScreenshot (dir.file ("fit.png"), 400, 300);
  EXPECT_GT (readPng (dir.file ("fit.png")).coverage (bar[0], bar[2]), 0.02) << "the colour bar is drawn";
  EXPECT_TRUE (layers.toggle ('m'));
  EXPECT_FALSE (layers.isVisible ("fit"));
  EXPECT_FALSE (viewer.isVisible ("fit"));
  viewer.saveScreenshot (dir.file ("hidden.png"), 400, 300);
  EXPECT_EQ (readPng (dir.file ("hidden.png")).coverage (), 0.0) << "the fit, its bar and the scan are hidden";
  layers.toggle ('t');
  viewer.saveScreenshot (dir.file ("scan.png"), 400, 300);
  EXPECT_GT (readPng (dir.file ("scan.png")).coverage (0.0, bar[0]), 0.05) << "the scan is shown again";
  EXPECT_LT (readPng (dir.file ("scan.png")).coverage (bar[0], bar[2]), 0.001) << "without the fit's bar";
  EXPECT_FALSE (layers.toggle ('z'));
  EXPECT_NE (layers.legend ().find ("m fit (off)"), std::string::npos) << layers.legend ();
  EXPECT_THROW (layers.addLayer ("points", 'p', {"scan"}), morphreg::InvalidInputError) << "PCL's key";
  EXPECT_THROW (layers.addLayer ("again", 'm', {"scan"}), morphreg::InvalidInputError) << "taken";
  EXPECT_THROW (layers.addLayer ("none", 'n', {"no_such_shape"}), morphreg::InvalidInputError);
  EXPECT_THROW (layers.setVisible ("no_such_layer", true), morphreg::InvalidInputError);
}

TEST (RegistrationVisualizerTest, OrganisedCloudsShowTheirValidPoints)
{
  morphreg::test::TempDirectory dir;
  pcl::PointCloud<pcl::PointXYZ> frame (40, 30); // organised, as a depth camera delivers it
  for (int row = 0; row < 30; ++row)
    for (int column = 0; column < 40; ++column)
      frame.at (column, row) = column < 10 ? pcl::PointXYZ (NAN, NAN, NAN) : pcl::PointXYZ (column, row, 500.0f);
  frame.is_dense = false;
  RegistrationVisualizer viewer (RegistrationVisualizer::Display::Offscreen);
  viewer.addTargetCloud (frame, "frame", 0, 3.0);
  viewer.resetCamera ();
  viewer.saveScreenshot (dir.file ("frame.png"), 320, 240);
  EXPECT_GT (readPng (dir.file ("frame.png")).coverage (), 0.05);
  pcl::PointCloud<pcl::PointXYZ> missing (2, 2, pcl::PointXYZ (NAN, NAN, NAN));
  EXPECT_THROW (viewer.addTargetCloud (missing), morphreg::InvalidInputError) << "no valid point";
  frame.at (20, 10).z = INFINITY;
  EXPECT_THROW (viewer.addTargetCloud (frame), morphreg::InvalidInputError) << "infinite is no missing point";
}

TEST (ConvergencePlotTest, WritesTheRmsPerIteration)
{
  morphreg::test::TempDirectory dir;
  morphreg::IcpReport report;
  for (int i = 0; i < 25; ++i)
    report.history.push_back ({i < 8 ? morphreg::IcpStage::similarity : morphreg::IcpStage::shape,
                               4.0 + 100.0 * std::exp (-0.3 * i), 1000, 900, 0.01});
  morphreg::saveConvergencePlot (dir.file ("plot.png"), report, "synthetic", 640, 400);
  const Picture picture = readPng (dir.file ("plot.png"));
  EXPECT_EQ (picture.width, 640);
  EXPECT_EQ (picture.height, 400);
  EXPECT_GT (picture.coverage (0.1, 0.95), 0.01) << "axes, labels and the lines are drawn";
  EXPECT_THROW (morphreg::saveConvergencePlot (dir.file ("empty.png"), morphreg::IcpReport ()),
                morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::saveConvergencePlot (dir.file ("tiny.png"), report, "", 50, 50), morphreg::InvalidInputError);
}

TEST (ColourMapTest, ViridisRunsFromBlueToYellowAndGreyForNoValue)
{
  const morphreg::Rgb8 low = morphreg::viridis (0.0), high = morphreg::viridis (1.0);
  EXPECT_GT (low[2], low[0]) << "low is blue-violet, not red";
  EXPECT_GT (high[0], 200);
  EXPECT_GT (high[1], 200);
  EXPECT_EQ (morphreg::viridis (std::nan ("")), morphreg::Rgb8 (150, 150, 150));
  EXPECT_EQ (morphreg::viridis (2.0), high) << "clamped";
  EXPECT_THROW (morphreg::residualColours (Eigen::VectorXd::Ones (2), 0.0), morphreg::InvalidInputError);
}

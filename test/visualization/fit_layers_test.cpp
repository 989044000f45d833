// SPDX-License-Identifier: BSD-3-Clause
// The pictures of a fit for any program (fit_layers.h): a fitted mesh file read back with its residuals, drawn with
// its correspondences to the scan, and the overlay picture `register --screenshot` writes.
#include <morphreg/common/colour_map.h>
#include <morphreg/common/error.h>
#include <morphreg/io/cloud_io.h>
#include <morphreg/io/fitted_mesh_io.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/visualization/fit_layers.h>
#include <morphreg/visualization/registration_visualizer.h>

#include "support/synthetic_heads.h"
#include "support/temp_directory.h"

#include <pcl/common/io.h>

#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cmath>

namespace
{
using morphreg::RegistrationVisualizer;

/** The head's vertices as a scan 1 mm out along z. */
pcl::PointCloud<pcl::PointNormal>
scanOf (const morphreg::TriangleMesh& mesh)
{
  pcl::PointCloud<pcl::PointNormal> scan;
  for (Eigen::Index v = 0; v < mesh.numVertices (); ++v) {
    pcl::PointNormal p;
    p.getVector3fMap () = mesh.vertices.col (v).cast<float> () + Eigen::Vector3f (0.0f, 0.0f, 1.0f);
    p.getNormalVector3fMap () = Eigen::Vector3f::UnitZ ();
    scan.push_back (p);
  }
  return scan;
}

TEST (FittedMeshFileTest, ResidualsComeBackFromTheQualityAndOtherQualitiesAreNamed)
{
  morphreg::test::TempDirectory dir;
  const morphreg::TriangleMesh head = morphreg::test::headGenerator (24).sample (3).mesh;
  Eigen::VectorXd residuals = Eigen::VectorXd::LinSpaced (head.numVertices (), 0.0, 4.0);
  residuals[5] = NAN; // no correspondence
  morphreg::savePolygonMesh (dir.file ("fit.ply"),
                             morphreg::toPolygonMesh (head, morphreg::residualColours (residuals, 4.0), residuals));
  morphreg::FittedMeshFile fit = morphreg::loadFittedMesh (dir.file ("fit.ply"));
  ASSERT_TRUE (fit.residuals);
  EXPECT_TRUE (std::isnan ((*fit.residuals)[5]));
  (*fit.residuals)[5] = 0.0;
  residuals[5] = 0.0;
  EXPECT_LT ((*fit.residuals - residuals).cwiseAbs ().maxCoeff (), 1e-6);
  EXPECT_TRUE (fit.note.empty ());

  residuals[7] = -0.5; // a curvature, not a distance
  const Eigen::Matrix<unsigned char, 3, Eigen::Dynamic> grey =
      Eigen::Matrix<unsigned char, 3, Eigen::Dynamic>::Constant (3, head.numVertices (), 128);
  morphreg::savePolygonMesh (dir.file ("curvature.ply"), morphreg::toPolygonMesh (head, grey, residuals));
  const morphreg::FittedMeshFile curvature = morphreg::loadFittedMesh (dir.file ("curvature.ply"));
  EXPECT_FALSE (curvature.residuals);
  EXPECT_NE (
      curvature.note.find (dir.file ("curvature.ply") + ": its vertex quality is not a distance (vertex 7: -0.5)"),
      std::string::npos)
      << curvature.note;

  morphreg::saveTriangleMesh (dir.file ("plain.ply"), head);
  const morphreg::FittedMeshFile plain = morphreg::loadFittedMesh (dir.file ("plain.ply"));
  EXPECT_FALSE (plain.residuals);
  EXPECT_TRUE (plain.note.empty ());
}

TEST (FitLayersTest, TheFitItsCorrespondencesAndTheOverlayPicture)
{
  morphreg::test::TempDirectory dir;
  const morphreg::TriangleMesh head = morphreg::test::headGenerator (24).sample (3).mesh;
  const pcl::PointCloud<pcl::PointNormal> scan = scanOf (head);
  Eigen::VectorXd residuals = Eigen::VectorXd::Constant (head.numVertices (), 1.0);
  residuals.head (head.numVertices () / 2).setConstant (NAN);
  morphreg::savePolygonMesh (dir.file ("fit.ply"),
                             morphreg::toPolygonMesh (head, morphreg::residualColours (residuals, 4.0), residuals));
  pcl::PointCloud<pcl::PointXYZ> points;
  pcl::copyPointCloud (scan, points);
  morphreg::saveCloud (dir.file ("scan.pcd"), points);

  RegistrationVisualizer viewer (RegistrationVisualizer::Display::Offscreen);
  const auto cloud = morphreg::addScanFile (viewer, dir.file ("scan.pcd"), true, 400, 300, "scan");
  EXPECT_EQ (cloud->size (), scan.size ());
  const morphreg::FittedMeshFile fit = morphreg::addFittedMeshFile (viewer, dir.file ("fit.ply"), 0.0, 1.0, "fit");
  ASSERT_TRUE (fit.residuals);
  morphreg::addFitCorrespondences (viewer, *cloud, head, fit.residuals, 50);
  EXPECT_TRUE (viewer.isVisible ("correspondences"));
  pcl::PointCloud<pcl::PointXYZ> missing (3, 1, pcl::PointXYZ (NAN, NAN, NAN));
  EXPECT_THROW (morphreg::addFitCorrespondences (viewer, missing, head, fit.residuals, 50, "none"),
                morphreg::InvalidInputError);

  RegistrationVisualizer overlay (RegistrationVisualizer::Display::Offscreen);
  morphreg::saveFitOverlay (overlay, scan, head, residuals, 4.0, Eigen::Matrix4d::Identity (), dir.file ("fit.png"),
                            320, 240);
  auto reader = vtkSmartPointer<vtkPNGReader>::New ();
  reader->SetFileName (dir.file ("fit.png").c_str ());
  reader->Update ();
  int size[3];
  reader->GetOutput ()->GetDimensions (size);
  EXPECT_EQ (size[0], 320);
  EXPECT_EQ (size[1], 240);
}
} // namespace

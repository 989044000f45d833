// SPDX-License-Identifier: BSD-3-Clause
// Agreement with VTK's thin plate spline (SetBasisToR: U = +r, the same L and right-hand side as ours).
#include <morphreg/warp/thin_plate_spline.h>

#include "tps_test_support.h"

#include <gtest/gtest.h>
#include <iostream>
#include <vtkNew.h>
#include <vtkPoints.h>
#include <vtkThinPlateSplineTransform.h>

using morphreg::test::bend;
using morphreg::test::extent;
using morphreg::test::randomLandmarks;

namespace
{
vtkNew<vtkPoints>
toVtkPoints (const Eigen::Matrix3Xd& points)
{
  vtkNew<vtkPoints> result;
  result->SetDataTypeToDouble (); // the default, float, would round the landmarks
  for (Eigen::Index j = 0; j < points.cols (); ++j)
    result->InsertNextPoint (points (0, j), points (1, j), points (2, j));
  return result;
}

/** Largest |ours - VTK| over \a queries for the spline fitted on (source, target). */
double
largestDifferenceFromVtk (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target,
                          const Eigen::Matrix3Xd& queries)
{
  morphreg::ThinPlateSpline<double, 3> ours;
  ours.fit (source, target);
  const Eigen::Matrix3Xd mine = ours.evaluate (queries);

  vtkNew<vtkThinPlateSplineTransform> vtk;
  auto vtk_source = toVtkPoints (source);
  auto vtk_target = toVtkPoints (target);
  vtk->SetSourceLandmarks (vtk_source);
  vtk->SetTargetLandmarks (vtk_target);
  vtk->SetBasisToR ();
  vtk->Update ();
  double largest = 0.0;
  for (Eigen::Index j = 0; j < queries.cols (); ++j) {
    Eigen::Vector3d theirs;
    vtk->TransformPoint (queries.col (j).data (), theirs.data ());
    largest = std::max (largest, (theirs - mine.col (j)).norm ());
  }
  return largest;
}
} // namespace

TEST (TpsTest, AgreesWithVtkThinPlateSplineTransform)
{
  for (const int n : {10, 66, 200, 500}) {
    const Eigen::Matrix3Xd source = randomLandmarks (n, 100 + n, 250.0, 300.0);
    Eigen::Matrix3Xd target = bend<3> (source);
    target += randomLandmarks (n, 200 + n, 10.0); // not smooth: large weights
    Eigen::Matrix3Xd queries (3, 400 + n);
    queries << randomLandmarks (400, 300 + n, 400.0, 300.0), source;
    const double difference = largestDifferenceFromVtk (source, target, queries);
    std::cout << n << " landmarks: largest difference from VTK " << difference / extent (target) << " of the extent\n";
    EXPECT_LE (difference, 1e-9 * extent (target)) << n << " landmarks";
  }
}

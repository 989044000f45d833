// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/model/procrustes.h>

#include <Eigen/Geometry>

#include <cmath>
#include <string>

namespace morphreg
{
namespace
{
/** \a shape moved rigidly onto \a target (least squares, no scaling). */
Eigen::Matrix3Xd
rigidlyAligned (const Eigen::Ref<const Eigen::Matrix3Xd>& shape, const Eigen::Matrix3Xd& target)
{
  const Eigen::Matrix4d transform = Eigen::umeyama (shape, target, false);
  return (transform.topLeftCorner<3, 3> () * shape).colwise () + transform.topRightCorner<3, 1> ();
}

/** The iteration of alignGeneralisedProcrustes on shapes of type \a Shape (Matrix3Xd or a Map of one). */
template <typename Shape>
void
alignShapes (std::vector<Shape>& shapes, int max_iterations, double tolerance)
{
  const Eigen::Matrix3Xd frame = shapes[0];
  Eigen::Matrix3Xd reference = frame;
  for (int iteration = 0; iteration < max_iterations; ++iteration) {
    Eigen::Matrix3Xd mean = Eigen::Matrix3Xd::Zero (3, frame.cols ());
    for (Shape& shape : shapes) {
      shape = rigidlyAligned (shape, reference);
      mean += shape;
    }
    mean = rigidlyAligned (mean / static_cast<double> (shapes.size ()), frame);
    const double change = (mean - reference).norm () / std::sqrt (static_cast<double> (frame.cols ()));
    reference = mean;
    if (change <= tolerance * (1.0 + reference.norm () / std::sqrt (static_cast<double> (frame.cols ()))))
      break;
  }
  for (Shape& shape : shapes)
    shape = rigidlyAligned (shape, reference);
}
} // namespace

void
alignGeneralisedProcrustes (std::vector<Eigen::Matrix3Xd>& shapes, int max_iterations, double tolerance)
{
  if (shapes.size () < 2)
    throw InvalidInputError ("alignGeneralisedProcrustes: at least two shapes are needed");
  for (size_t s = 1; s < shapes.size (); ++s)
    if (shapes[s].cols () != shapes[0].cols ())
      throw InvalidInputError ("alignGeneralisedProcrustes: shape " + std::to_string (s) + " has " +
                               std::to_string (shapes[s].cols ()) + " points, shape 0 has " +
                               std::to_string (shapes[0].cols ()));
  alignShapes (shapes, max_iterations, tolerance);
}

void
alignGeneralisedProcrustes (Eigen::MatrixXd& shapes, int max_iterations, double tolerance)
{
  if (shapes.cols () < 2)
    throw InvalidInputError ("alignGeneralisedProcrustes: at least two shapes (columns) are needed");
  if (shapes.rows () % 3 != 0)
    throw InvalidInputError ("alignGeneralisedProcrustes: " + std::to_string (shapes.rows ()) +
                             " rows per shape, not 3 per point");
  std::vector<Eigen::Map<Eigen::Matrix3Xd>> columns;
  for (Eigen::Index s = 0; s < shapes.cols (); ++s)
    columns.emplace_back (shapes.col (s).data (), 3, shapes.rows () / 3);
  alignShapes (columns, max_iterations, tolerance);
}

} // namespace morphreg

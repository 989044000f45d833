// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Conversions between numpy arrays and the library's Eigen and PCL types. Points are (N, 3) arrays: float64 arrays
// in C order are read in place (their memory is the library's 3 x N column-major layout), other float layouts are
// converted once. Results are returned without copies: the array owns the Eigen matrix it views.
#include <morphreg/common/landmarks.h>
#include <morphreg/mesh/triangle_mesh.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>

#include <string>
#include <utility>

namespace morphreg
{
namespace python
{
namespace py = pybind11;

/** A float64 array in C order; a float32 array or another layout is converted, a float64 C-order array is used in
 *  place. */
using DoubleArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/** \a object as a float64 C-order array of \a ndim dimensions (the last of \a columns unless it is -1); \a name
 *  names the argument in errors. Refuses other shapes, dtypes other than float16/32/64 and, unless \a allow_nan,
 *  non-finite values (InvalidInputError). */
DoubleArray
floatArray (const py::handle& object, const std::string& name, int ndim, py::ssize_t columns, bool allow_nan = false);

/** Points given as an (N, 3) array, viewed as the library's 3 x N matrix (no copy for float64 in C order). */
struct PointsArgument
{
  DoubleArray array;                         ///< keeps the memory alive
  Eigen::Map<const Eigen::Matrix3Xd> points; ///< 3 x N over it
};

/** The (N, 3) points of \a object (N >= \a minimum), checked as floatArray does. */
PointsArgument
pointsArgument (const py::handle& object, const std::string& name, py::ssize_t minimum = 1, bool allow_nan = false);

/** The 1-D float array of \a object as a vector; \a size >= 0 requires that length. */
Eigen::VectorXd
toVector (const py::handle& object, const std::string& name, py::ssize_t size = -1);

/** The (T, 3) integer array of \a object as 3 x T triangles, each index checked against \a num_vertices. */
TriangleMesh::Triangles
toTriangles (const py::handle& object, const std::string& name, Eigen::Index num_vertices);

/** A triangle mesh from (N, 3) vertices and (T, 3) faces. */
TriangleMesh
toMesh (const py::handle& vertices, const py::handle& faces, const std::string& name);

/** A PCL cloud of points with normals from (N, 3) points and, if given (not None), (N, 3) normals. */
pcl::PointCloud<pcl::PointNormal>::Ptr
toCloud (const py::handle& points, const py::handle& normals, const std::string& name);

/** A dict id -> (3,) position as landmark positions; ids must be known landmark ids (InvalidInputError). */
LandmarkPositions
toLandmarks (const py::handle& landmarks, const std::string& name);

/** \a matrix as a numpy array that owns it: a 3 x N matrix becomes (N, 3), a vector (N,), a matrix (R, C). */
py::array
toArray (Eigen::Matrix3Xd matrix);
py::array
toArray (Eigen::VectorXd vector);
py::array
toArray (TriangleMesh::Triangles triangles);
py::array
toArray (Eigen::MatrixXd matrix);

/** A read-only (N, 3) view of the 3 x N memory at \a data, keeping \a owner alive. */
py::array
pointsView (const double* data, Eigen::Index count, py::handle owner);

/** Landmark positions as a dict id -> (3,) array. */
py::dict
toDict (const LandmarkPositions& landmarks);

} // namespace python
} // namespace morphreg

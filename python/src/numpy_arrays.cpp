// SPDX-License-Identifier: BSD-3-Clause
#include "numpy_arrays.h"

#include <morphreg/common/error.h>

#include <cmath>
#include <memory>
#include <sstream>

namespace morphreg
{
namespace python
{
namespace
{
std::string
shapeText (const py::array& array)
{
  std::ostringstream text;
  text << '(';
  for (py::ssize_t d = 0; d < array.ndim (); ++d)
    text << (d ? ", " : "") << array.shape (d);
  text << (array.ndim () == 1 ? ",)" : ")");
  return text.str ();
}

std::string
expectedShape (int ndim, py::ssize_t columns)
{
  if (ndim == 1)
    return "(N,)";
  return columns < 0 ? "(N, K)" : "(N, " + std::to_string (columns) + ")";
}

/** \a object as a numpy array (array-likes such as lists are converted); anything else is an InvalidInputError. */
py::array
asArray (const py::handle& object, const std::string& name)
{
  if (object.is_none ())
    throw InvalidInputError (name + ": None where an array was expected");
  py::array array = py::array::ensure (object);
  if (!array)
    throw InvalidInputError (name + ": " + std::string (py::str (py::type::handle_of (object).attr ("__name__"))) +
                             " is not an array");
  return array;
}

void
requireShape (const py::array& array, const std::string& name, int ndim, py::ssize_t columns)
{
  if (array.ndim () == ndim && (columns < 0 || array.shape (ndim - 1) == columns))
    return;
  throw InvalidInputError (name + ": shape " + shapeText (array) + ", expected " + expectedShape (ndim, columns));
}

void
requireFinite (const DoubleArray& array, const std::string& name)
{
  const double* data = array.data ();
  const py::ssize_t columns = array.ndim () == 2 ? array.shape (1) : 1;
  for (py::ssize_t i = 0; i < array.size (); ++i)
    if (!std::isfinite (data[i])) {
      const std::string where = array.ndim () == 2
                                    ? "row " + std::to_string (i / columns) + ", column " + std::to_string (i % columns)
                                    : "entry " + std::to_string (i);
      throw InvalidInputError (name + ": " + where + " is not finite (" + std::to_string (data[i]) + ")");
    }
}

/** A numpy array over \a data (shape and strides in bytes) that owns \a owner's object. */
template <typename T, typename Owner>
py::array
ownedArray (std::unique_ptr<Owner> owner, const T* data, std::vector<py::ssize_t> shape,
            std::vector<py::ssize_t> strides)
{
  Owner* raw = owner.release ();
  py::capsule free_owner (raw, [] (void* p) { delete static_cast<Owner*> (p); });
  return py::array_t<T> (std::move (shape), std::move (strides), data, free_owner);
}
} // namespace

DoubleArray
floatArray (const py::handle& object, const std::string& name, int ndim, py::ssize_t columns, bool allow_nan)
{
  const py::array array = asArray (object, name);
  if (array.dtype ().kind () != 'f')
    throw InvalidInputError (name + ": dtype " + std::string (py::str (array.dtype ())) +
                             ", expected float64 or float32");
  requireShape (array, name, ndim, columns);
  DoubleArray doubles = DoubleArray::ensure (array);
  if (!allow_nan)
    requireFinite (doubles, name);
  return doubles;
}

PointsArgument
pointsArgument (const py::handle& object, const std::string& name, py::ssize_t minimum, bool allow_nan)
{
  DoubleArray array = floatArray (object, name, 2, 3, allow_nan);
  if (array.shape (0) < minimum)
    throw InvalidInputError (name + ": " + std::to_string (array.shape (0)) + " points, at least " +
                             std::to_string (minimum) + " needed");
  const Eigen::Map<const Eigen::Matrix3Xd> points (array.data (), 3, array.shape (0));
  return {std::move (array), points};
}

Eigen::VectorXd
toVector (const py::handle& object, const std::string& name, py::ssize_t size)
{
  const DoubleArray array = floatArray (object, name, 1, -1);
  if (size >= 0 && array.shape (0) != size)
    throw InvalidInputError (name + ": " + std::to_string (array.shape (0)) + " values, expected " +
                             std::to_string (size));
  return Eigen::Map<const Eigen::VectorXd> (array.data (), array.shape (0));
}

TriangleMesh::Triangles
toTriangles (const py::handle& object, const std::string& name, Eigen::Index num_vertices)
{
  const py::array array = asArray (object, name);
  if (array.dtype ().kind () != 'i' && array.dtype ().kind () != 'u')
    throw InvalidInputError (name + ": dtype " + std::string (py::str (array.dtype ())) + ", expected integers");
  requireShape (array, name, 2, 3);
  const auto indices = py::array_t<long long, py::array::c_style | py::array::forcecast>::ensure (array);
  TriangleMesh::Triangles triangles (3, indices.shape (0));
  const long long* data = indices.data ();
  for (py::ssize_t i = 0; i < indices.size (); ++i) {
    if (data[i] < 0 || data[i] >= num_vertices)
      throw InvalidInputError (name + ": face " + std::to_string (i / 3) + " has vertex index " +
                               std::to_string (data[i]) + ", outside 0-" + std::to_string (num_vertices - 1));
    triangles.data ()[i] = static_cast<int> (data[i]);
  }
  return triangles;
}

TriangleMesh
toMesh (const py::handle& vertices, const py::handle& faces, const std::string& name)
{
  const PointsArgument points = pointsArgument (vertices, name + " vertices", 3);
  TriangleMesh mesh{points.points, toTriangles (faces, name + " faces", points.points.cols ())};
  validateMesh (mesh, name);
  return mesh;
}

pcl::PointCloud<pcl::PointNormal>::Ptr
toCloud (const py::handle& points, const py::handle& normals, const std::string& name)
{
  const PointsArgument xyz = pointsArgument (points, name);
  auto cloud = std::make_shared<pcl::PointCloud<pcl::PointNormal>> ();
  cloud->resize (xyz.points.cols ());
  for (Eigen::Index i = 0; i < xyz.points.cols (); ++i)
    (*cloud)[i].getVector3fMap () = xyz.points.col (i).cast<float> ();
  if (!normals.is_none ()) {
    const PointsArgument n = pointsArgument (normals, name + " normals");
    if (n.points.cols () != xyz.points.cols ())
      throw InvalidInputError (name + ": " + std::to_string (n.points.cols ()) + " normals for " +
                               std::to_string (xyz.points.cols ()) + " points");
    for (Eigen::Index i = 0; i < n.points.cols (); ++i)
      (*cloud)[i].getNormalVector3fMap () = n.points.col (i).cast<float> ();
  }
  return cloud;
}

LandmarkPositions
toLandmarks (const py::handle& landmarks, const std::string& name)
{
  if (!py::isinstance<py::dict> (landmarks))
    throw InvalidInputError (name + ": expected a dict of landmark id -> (x, y, z), got " +
                             std::string (py::str (py::type::handle_of (landmarks).attr ("__name__"))));
  LandmarkPositions positions;
  for (const auto& item : py::reinterpret_borrow<py::dict> (landmarks)) {
    if (!py::isinstance<py::str> (item.first))
      throw InvalidInputError (name + ": landmark ids are strings, got " + std::string (py::repr (item.first)));
    const auto id = item.first.cast<std::string> ();
    requireKnownLandmarkId (id, name);
    positions[id] = toVector (item.second, name + "[\"" + id + "\"]", 3);
    if (!positions[id].allFinite ())
      throw InvalidInputError (name + "[\"" + id + "\"]: not finite");
  }
  return positions;
}

py::array
toArray (Eigen::Matrix3Xd matrix)
{
  auto owner = std::make_unique<Eigen::Matrix3Xd> (std::move (matrix));
  const double* data = owner->data ();
  const py::ssize_t n = owner->cols ();
  return ownedArray (std::move (owner), data, {n, 3}, {3 * sizeof (double), sizeof (double)});
}

py::array
toArray (Eigen::VectorXd vector)
{
  auto owner = std::make_unique<Eigen::VectorXd> (std::move (vector));
  const double* data = owner->data ();
  const py::ssize_t n = owner->size ();
  return ownedArray (std::move (owner), data, {n}, {sizeof (double)});
}

py::array
toArray (TriangleMesh::Triangles triangles)
{
  auto owner = std::make_unique<TriangleMesh::Triangles> (std::move (triangles));
  const int* data = owner->data ();
  const py::ssize_t n = owner->cols ();
  return ownedArray (std::move (owner), data, {n, 3}, {3 * sizeof (int), sizeof (int)});
}

py::array
toArray (Eigen::MatrixXd matrix)
{
  auto owner = std::make_unique<Eigen::MatrixXd> (std::move (matrix));
  const double* data = owner->data ();
  const py::ssize_t rows = owner->rows (), cols = owner->cols ();
  return ownedArray (std::move (owner), data, {rows, cols},
                     {sizeof (double), static_cast<py::ssize_t> (rows * sizeof (double))});
}

py::array
pointsView (const double* data, Eigen::Index count, py::handle owner)
{
  py::array_t<double> view ({static_cast<py::ssize_t> (count), py::ssize_t{3}}, {3 * sizeof (double), sizeof (double)},
                            data, owner);
  view.attr ("setflags") (py::arg ("write") = false);
  return std::move (view);
}

py::dict
toDict (const LandmarkPositions& landmarks)
{
  py::dict dict;
  for (const auto& [id, position] : landmarks)
    dict[py::str (id)] = toArray (Eigen::VectorXd (position));
  return dict;
}

} // namespace python
} // namespace morphreg

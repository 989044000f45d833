// SPDX-License-Identifier: BSD-3-Clause
#pragma once
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_normals.h>
#include <morphreg/warp/impl/tps_solver.h>
#include <morphreg/warp/thin_plate_spline.h>

#include <pcl/PCLPointField.h>
#include <pcl/type_traits.h>

#include <Eigen/LU>

#include <cmath>
#include <array>
#include <cstring>
#include <sstream>
#include <string>

namespace morphreg
{
template <typename Scalar, int Dim>
void
ThinPlateSpline<Scalar, Dim>::setRegularization (double lambda)
{
  if (!std::isfinite (lambda) || lambda < 0.0)
    throw InvalidInputError ("ThinPlateSpline::setRegularization: lambda must be finite and >= 0, got " +
                             std::to_string (lambda));
  regularization_ = lambda;
}

template <typename Scalar, int Dim>
void
ThinPlateSpline<Scalar, Dim>::setMaxConditionNumber (double limit)
{
  if (!(limit > 1.0))
    throw InvalidInputError ("ThinPlateSpline::setMaxConditionNumber: the limit must be > 1, got " +
                             std::to_string (limit));
  max_condition_number_ = limit;
}

template <typename Scalar, int Dim>
void
ThinPlateSpline<Scalar, Dim>::fit (const Eigen::Ref<const Points>& source, const Eigen::Ref<const Points>& target)
{
  fitted_ = false;
  detail::TpsFitOptions options;
  options.regularization = regularization_;
  options.max_condition_number = max_condition_number_;
  options.caller = "ThinPlateSpline::fit";
  const detail::TpsFit fit =
      detail::fitThinPlateSpline (source.template cast<double> (), target.template cast<double> (), options);
  coefficients_.landmarks = fit.landmarks.cast<Scalar> ();
  coefficients_.weights = fit.weights.cast<Scalar> ();
  coefficients_.affine = fit.affine.cast<Scalar> ();
  bending_energy_ = fit.bending_energy;
  condition_estimate_ = fit.condition_estimate;
  merged_landmarks_ = fit.merged;
  fitted_ = true;
}

template <typename Scalar, int Dim>
template <typename PointSource, typename PointTarget>
void
ThinPlateSpline<Scalar, Dim>::fit (const pcl::PointCloud<PointSource>& source,
                                   const pcl::PointCloud<PointTarget>& target)
{
  if (source.size () != target.size ()) {
    std::ostringstream msg;
    msg << "ThinPlateSpline::fit: mismatched landmark counts: the source cloud has " << source.size ()
        << " points but the target cloud " << target.size ();
    throw InvalidInputError (msg.str ());
  }
  fit (cloudCoordinates<Scalar, Dim> (source), cloudCoordinates<Scalar, Dim> (target));
}

template <typename Scalar, int Dim>
template <typename PointSource, typename PointTarget>
void
ThinPlateSpline<Scalar, Dim>::fit (const pcl::PointCloud<PointSource>& source,
                                   const pcl::PointCloud<PointTarget>& target,
                                   const pcl::Correspondences& correspondences)
{
  if (correspondences.empty ())
    throw InvalidInputError ("ThinPlateSpline::fit: no correspondences given");
  pcl::Indices source_indices, target_indices;
  source_indices.reserve (correspondences.size ());
  target_indices.reserve (correspondences.size ());
  for (std::size_t c = 0; c < correspondences.size (); ++c) {
    const pcl::Correspondence& pair = correspondences[c];
    if (pair.index_query < 0 || static_cast<std::size_t> (pair.index_query) >= source.size () || pair.index_match < 0 ||
        static_cast<std::size_t> (pair.index_match) >= target.size ()) {
      std::ostringstream msg;
      msg << "ThinPlateSpline::fit: correspondence " << c << " (" << pair.index_query << " -> " << pair.index_match
          << ") is out of range for clouds of " << source.size () << " and " << target.size ()
          << " points (remove unmatched correspondences first)";
      throw InvalidInputError (msg.str ());
    }
    source_indices.push_back (pair.index_query);
    target_indices.push_back (pair.index_match);
  }
  fit (cloudCoordinates<Scalar, Dim> (source, source_indices), cloudCoordinates<Scalar, Dim> (target, target_indices));
}

template <typename Scalar, int Dim>
void
ThinPlateSpline<Scalar, Dim>::requireFitted (const char* caller) const
{
  if (!fitted_)
    throw InvalidInputError (std::string ("ThinPlateSpline::") + caller +
                             ": the spline has not been fitted (call fit first, and check it did not throw)");
}

template <typename Scalar, int Dim>
const typename ThinPlateSpline<Scalar, Dim>::LandmarkMatrix&
ThinPlateSpline<Scalar, Dim>::getLandmarks () const
{
  requireFitted ("getLandmarks");
  return coefficients_.landmarks;
}

template <typename Scalar, int Dim>
const typename ThinPlateSpline<Scalar, Dim>::LandmarkMatrix&
ThinPlateSpline<Scalar, Dim>::getWeights () const
{
  requireFitted ("getWeights");
  return coefficients_.weights;
}

template <typename Scalar, int Dim>
const typename ThinPlateSpline<Scalar, Dim>::AffineMatrix&
ThinPlateSpline<Scalar, Dim>::getAffine () const
{
  requireFitted ("getAffine");
  return coefficients_.affine;
}

template <typename Scalar, int Dim>
double
ThinPlateSpline<Scalar, Dim>::bendingEnergy () const
{
  requireFitted ("bendingEnergy");
  return bending_energy_;
}

template <typename Scalar, int Dim>
double
ThinPlateSpline<Scalar, Dim>::conditionEstimate () const
{
  requireFitted ("conditionEstimate");
  return condition_estimate_;
}

template <typename Scalar, int Dim>
Eigen::Index
ThinPlateSpline<Scalar, Dim>::mergedLandmarks () const
{
  requireFitted ("mergedLandmarks");
  return merged_landmarks_;
}

template <typename Scalar, int Dim>
typename ThinPlateSpline<Scalar, Dim>::Point
ThinPlateSpline<Scalar, Dim>::transformPoint (const Point& x) const
{
  requireFitted ("transformPoint");
  return detail::evaluateTpsPoint (coefficients_, x.data ());
}

template <typename Scalar, int Dim>
typename ThinPlateSpline<Scalar, Dim>::Points
ThinPlateSpline<Scalar, Dim>::evaluate (const Eigen::Ref<const Points>& points) const
{
  requireFitted ("evaluate");
  Points result (Dim, points.cols ());
  detail::evaluateTps<Scalar, Dim> (coefficients_, points, result);
  return result;
}

template <typename Scalar, int Dim>
typename ThinPlateSpline<Scalar, Dim>::Jacobian
ThinPlateSpline<Scalar, Dim>::jacobian (const Point& x) const
{
  requireFitted ("jacobian");
  return detail::evaluateTpsJacobian (coefficients_, x.data ());
}

template <typename Scalar, int Dim>
template <typename PointT>
void
ThinPlateSpline<Scalar, Dim>::transformCloud (const pcl::PointCloud<PointT>& input,
                                              pcl::PointCloud<PointT>& output) const
{
  requireFitted ("transformCloud");
  const Points warped = evaluate (cloudCoordinates<Scalar, Dim> (input));
  if (&output != &input)
    output = input;
  const auto count = static_cast<Eigen::Index> (output.size ());
#pragma omp parallel for schedule(static) if (double(count) * double(coefficients_.landmarks.rows()) >                 \
                                              detail::kTpsParallelPairs)
  for (Eigen::Index j = 0; j < count; ++j) {
    PointT& p = output[j];
    if constexpr (pcl::traits::has_normal_v<PointT>) {
      // Normals are covectors: n' ~ J^-T n, with J the full 3D Jacobian (identity on z in 2D).
      const Point x = p.getVector3fMap ().template head<Dim> ().template cast<Scalar> ();
      Eigen::Matrix3d j3 = Eigen::Matrix3d::Identity ();
      j3.template topLeftCorner<Dim, Dim> () =
          detail::evaluateTpsJacobian (coefficients_, x.data ()).template cast<double> ();
      const Eigen::Vector3d n = j3.inverse ().transpose () * p.getNormalVector3fMap ().template cast<double> ();
      if (n.allFinite () && n.norm () > 0.0)
        p.getNormalVector3fMap () = (n / n.norm ()).template cast<float> ();
    }
    for (int k = 0; k < Dim; ++k)
      p.data[k] = static_cast<float> (warped (k, j));
  }
}

namespace detail
{
/** \brief Byte offset and datatype of field \a name of \a cloud, or offset -1 if absent or not float/double. */
inline std::pair<int, std::uint8_t>
floatingField (const pcl::PCLPointCloud2& cloud, const std::string& name)
{
  for (const auto& field : cloud.fields)
    if (field.name == name && field.count >= 1 &&
        (field.datatype == pcl::PCLPointField::FLOAT32 || field.datatype == pcl::PCLPointField::FLOAT64))
      return {static_cast<int> (field.offset), field.datatype};
  return {-1, 0};
}

/** \brief A float/double x, y, z-like triple of fields of a PCLPointCloud2: (offset, datatype) each. */
using VectorFields = std::array<std::pair<int, std::uint8_t>, 3>;

/** \brief The fields \a fields of every point of \a cloud as columns (3 x N). */
inline Eigen::Matrix3Xd
readVectorField (const pcl::PCLPointCloud2& cloud, const VectorFields& fields)
{
  const std::size_t count = std::size_t (cloud.width) * cloud.height;
  Eigen::Matrix3Xd values (3, static_cast<Eigen::Index> (count));
  for (std::size_t i = 0; i < count; ++i)
    for (int k = 0; k < 3; ++k) {
      const std::uint8_t* at = cloud.data.data () + i * cloud.point_step + fields[k].first;
      if (fields[k].second == pcl::PCLPointField::FLOAT64) {
        double v;
        std::memcpy (&v, at, sizeof v);
        values (k, i) = v;
      }
      else {
        float v;
        std::memcpy (&v, at, sizeof v);
        values (k, i) = v;
      }
    }
  return values;
}

/** \brief Stores the columns of \a values into the fields \a fields of every point of \a cloud. */
inline void
writeVectorField (pcl::PCLPointCloud2& cloud, const VectorFields& fields, const Eigen::Matrix3Xd& values)
{
  for (Eigen::Index i = 0; i < values.cols (); ++i)
    for (int k = 0; k < 3; ++k) {
      std::uint8_t* at = cloud.data.data () + i * cloud.point_step + fields[k].first;
      if (fields[k].second == pcl::PCLPointField::FLOAT64) {
        const double v = values (k, i);
        std::memcpy (at, &v, sizeof v);
      }
      else {
        const float v = static_cast<float> (values (k, i));
        std::memcpy (at, &v, sizeof v);
      }
    }
}
} // namespace detail

template <typename Scalar, int Dim>
void
ThinPlateSpline<Scalar, Dim>::transformMesh (const pcl::PolygonMesh& input, pcl::PolygonMesh& output) const
{
  requireFitted ("transformMesh");
  detail::VectorFields xyz, normal;
  for (int k = 0; k < 3; ++k) {
    xyz[k] = detail::floatingField (input.cloud, std::string (1, "xyz"[k]));
    normal[k] = detail::floatingField (input.cloud, std::string ("normal_") + "xyz"[k]);
    if (xyz[k].first < 0)
      throw InvalidInputError ("ThinPlateSpline::transformMesh: the mesh's vertex cloud has no float or double " +
                               std::string (1, "xyz"[k]) + " field");
  }
  if (&output != &input)
    output = input;
  TriangleMesh mesh; // the polygons fanned into triangles, for the normals
  mesh.vertices = detail::readVectorField (output.cloud, xyz);
  transformPositions (mesh.vertices);
  detail::writeVectorField (output.cloud, xyz, mesh.vertices);
  if (normal[0].first < 0 || normal[1].first < 0 || normal[2].first < 0)
    return;
  Eigen::Index triangles = 0;
  for (const auto& polygon : output.polygons)
    triangles += std::max<Eigen::Index> (0, Eigen::Index (polygon.vertices.size ()) - 2);
  mesh.triangles.resize (3, triangles);
  Eigen::Index t = 0;
  for (std::size_t f = 0; f < output.polygons.size (); ++f) {
    const auto& v = output.polygons[f].vertices;
    for (const auto index : v)
      if (index >= mesh.numVertices ()) {
        std::ostringstream msg;
        msg << "ThinPlateSpline::transformMesh: polygon " << f << " uses vertex " << index << " of "
            << mesh.numVertices ();
        throw InvalidInputError (msg.str ());
      }
    for (std::size_t c = 2; c < v.size (); ++c)
      mesh.triangles.col (t++) = Eigen::Vector3i (int (v[0]), int (v[c - 1]), int (v[c]));
  }
  detail::writeVectorField (output.cloud, normal, vertexNormals (mesh));
}

template <typename Scalar, int Dim>
TriangleMesh
ThinPlateSpline<Scalar, Dim>::transformMesh (const TriangleMesh& mesh) const
{
  TriangleMesh warped = mesh;
  transformPositions (warped.vertices);
  return warped;
}

template <typename Scalar, int Dim>
void
ThinPlateSpline<Scalar, Dim>::transformPositions (Eigen::Matrix3Xd& positions) const
{
  const Points warped = evaluate (positions.topRows (Dim).template cast<Scalar> ());
  positions.topRows (Dim) = warped.template cast<double> ();
}

template <typename Scalar, int Dim, typename PointT>
Eigen::Matrix<Scalar, Dim, Eigen::Dynamic>
cloudCoordinates (const pcl::PointCloud<PointT>& cloud, const pcl::Indices& indices)
{
  const bool all = indices.empty ();
  const Eigen::Index count = all ? Eigen::Index (cloud.size ()) : Eigen::Index (indices.size ());
  Eigen::Matrix<Scalar, Dim, Eigen::Dynamic> points (Dim, count);
  for (Eigen::Index j = 0; j < count; ++j) {
    const auto i = all ? pcl::index_t (j) : indices[j];
    if (i < 0 || std::size_t (i) >= cloud.size ()) {
      std::ostringstream msg;
      msg << "cloudCoordinates: index " << i << " (entry " << j << ") is out of range for a cloud of " << cloud.size ()
          << " points";
      throw InvalidInputError (msg.str ());
    }
    const PointT& p = cloud[i];
    for (int k = 0; k < Dim; ++k)
      points (k, j) = static_cast<Scalar> (p.data[k]);
  }
  return points;
}

} // namespace morphreg

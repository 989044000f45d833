// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file thin_plate_spline.h
 *  \brief Thin plate spline warps (docs/method.md, "Thin plate splines"): exact or regularised fits from landmark pairs, and
 *  fast evaluation on points, PCL clouds and meshes.
 */
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/warp/impl/tps_kernel.hpp>

#include <pcl/PolygonMesh.h>
#include <pcl/correspondence.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <memory>
#include <type_traits>

namespace morphreg
{
/** \brief A thin plate spline f: R^Dim -> R^Dim, f(x) = A^T [1; x] + sum_i W_i U(|x - p_i|), with U(r) = r in 3D
 *  (as VTK's vtkThinPlateSplineTransform::SetBasisToR) and U(r) = r^2 log r^2 in 2D (VTK's r^2 log r gives the same
 *  interpolating warp with doubled weights).
 *
 *  The fit reduces the symmetric indefinite system [[K P][P^T 0]] [W; A] = [Q; 0] to the null space of P^T and
 *  solves the (then definite) kernel block by Cholesky, followed by one step of iterative refinement if needed:
 *  O(n^3 / 3) with a single n x n matrix. It is always computed in double; \a Scalar is the precision of the stored
 *  coefficients and of evaluation. Coincident landmark pairs are merged; degenerate landmarks are an
 *  InvalidInputError and an ill-conditioned system a NumericalError, never a silent result.
 *
 *  Evaluation is vectorised over the landmarks and threaded (OpenMP) over the query points. Points use the
 *  project's column layout (Dim x N, like TriangleMesh::vertices); the coefficient accessors use the matrices
 *  of docs/method.md (one row per landmark). For Dim = 2 the spline warps x and y and leaves z unchanged.
 *
 *  \code
 *  morphreg::ThinPlateSpline<double, 3> tps;
 *  tps.fit (source_landmarks, target_landmarks); // 3 x n each, in mm
 *  pcl::PolygonMesh warped;
 *  tps.transformMesh (scan, warped);              // vertices moved, triangles kept, normals recomputed
 *  \endcode
 */
template <typename Scalar = double, int Dim = 3>
class ThinPlateSpline
{
  static_assert (std::is_floating_point<Scalar>::value, "ThinPlateSpline needs a floating-point Scalar");
  static_assert (Dim == 2 || Dim == 3, "ThinPlateSpline is 2D or 3D");

public:
  using Ptr = std::shared_ptr<ThinPlateSpline>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const ThinPlateSpline>; ///< shared pointer to const
  using Point = Eigen::Matrix<Scalar, Dim, 1>;             ///< one point
  /** \brief Points as columns (Dim x N). */
  using Points = Eigen::Matrix<Scalar, Dim, Eigen::Dynamic>;
  /** \brief One row per landmark (n x Dim): the landmarks p_i^T and the weights W. */
  using LandmarkMatrix = Eigen::Matrix<Scalar, Eigen::Dynamic, Dim>;
  /** \brief The affine part A ((Dim+1) x Dim): f's affine term is A^T [1; x]. */
  using AffineMatrix = Eigen::Matrix<Scalar, Dim + 1, Dim>;
  using Jacobian = Eigen::Matrix<Scalar, Dim, Dim>; ///< df/dx, row i the gradient of f's coordinate i

  /** \brief Default limit of the condition estimate: beyond it the weights carry less than ~6 correct digits. */
  static constexpr double kDefaultMaxConditionNumber = 1e10;

  /** \brief An unfitted spline: exact interpolation and the default condition limit. */
  ThinPlateSpline () = default;

  /** \brief lambda >= 0 trades landmark fidelity for smoothness (0, the default: exact interpolation). The fit then
   *  minimises sum |f(p_i) - q_i|^2 + lambda * bendingEnergy(); lambda has the kernel's unit (mm in 3D, mm^2 in 2D).
   *  In 3D, where U = +r makes K negative definite on the constraint space, this is K - lambda I in L.
   *  Throws InvalidInputError if \a lambda is negative or not finite. Takes effect at the next fit.
   *  \param[in] lambda the smoothing weight
   */
  void
  setRegularization (double lambda);

  /** \brief The smoothing weight of the next fit.
   *  \return lambda
   */
  double
  getRegularization () const
  {
    return regularization_;
  }

  /** \brief Fits with a condition estimate above \a limit (> 1) throw NumericalError.
   *  \param[in] limit the largest accepted condition estimate
   */
  void
  setMaxConditionNumber (double limit);

  /** \brief The largest accepted condition estimate.
   *  \return the limit
   */
  double
  getMaxConditionNumber () const
  {
    return max_condition_number_;
  }

  /** \brief Fits the spline mapping each column of \a source to the same column of \a target (Dim x n each).
   *  \param[in] source the source landmarks p_i
   *  \param[in] target the target landmarks q_i
   */
  void
  fit (const Eigen::Ref<const Points>& source, const Eigen::Ref<const Points>& target);

  /** \brief Fits on the first Dim coordinates (x, y[, z]) of two clouds of equal size, point i to point i.
   *  \param[in] source the source landmarks
   *  \param[in] target the target landmarks
   */
  template <typename PointSource, typename PointTarget>
  void
  fit (const pcl::PointCloud<PointSource>& source, const pcl::PointCloud<PointTarget>& target);

  /** \brief Fits on the pairs (source[index_query], target[index_match]) of \a correspondences; throws
   *  InvalidInputError naming any correspondence whose index is out of range.
   *  \param[in] source the source cloud
   *  \param[in] target the target cloud
   *  \param[in] correspondences the landmark pairs
   */
  template <typename PointSource, typename PointTarget>
  void
  fit (const pcl::PointCloud<PointSource>& source, const pcl::PointCloud<PointTarget>& target,
       const pcl::Correspondences& correspondences);

  /** \brief Whether a fit has succeeded.
   *  \return true once fit() returned without throwing
   */
  bool
  isFitted () const
  {
    return fitted_;
  }

  /** \brief The distinct source landmarks p_i (n x Dim, duplicates merged) the weights belong to.
   *  \return one row per landmark
   */
  const LandmarkMatrix&
  getLandmarks () const;

  /** \brief The kernel weights W (n x Dim), one row per landmark of getLandmarks().
   *  \return W
   */
  const LandmarkMatrix&
  getWeights () const;

  /** \brief The affine part A ((Dim+1) x Dim).
   *  \return A
   */
  const AffineMatrix&
  getAffine () const;

  /** \brief Bending energy, sign * trace(W^T K W) with the sign that makes it >= 0 (-1 in 3D, +1 in 2D); zero
   *  exactly when the warp is affine.
   *  \return the bending energy of the last fit
   */
  double
  bendingEnergy () const;

  /** \brief The condition estimate of the last fit: the larger of the reduced kernel system's (1-norm, from the
   *  Cholesky factor) and the affine part's (widest / thinnest spread of the landmarks).
   *  \return the estimate
   */
  double
  conditionEstimate () const;

  /** \brief Landmark pairs the last fit dropped as duplicates of pairs before them in the input.
   *  \return their number
   */
  Eigen::Index
  mergedLandmarks () const;

  /** \brief f(x) for one point.
   *  \param[in] x the point
   *  \return its image
   */
  Point
  transformPoint (const Point& x) const;

  /** \brief f at every column of \a points (Dim x N); non-finite points give non-finite results.
   *  \param[in] points the points
   *  \return their images, column by column
   */
  Points
  evaluate (const Eigen::Ref<const Points>& points) const;

  /** \brief The Jacobian df/dx at \a x.
   *  \param[in] x the point
   *  \return the Jacobian there
   */
  Jacobian
  jacobian (const Point& x) const;

  /** \brief Warps the XYZ of every point; all other fields are kept, except normals (if PointT has them), which are
   *  mapped by the inverse transpose of the Jacobian and renormalised. \a output may be \a input.
   *  \param[in] input the cloud to warp
   *  \param[out] output the warped cloud
   */
  template <typename PointT>
  void
  transformCloud (const pcl::PointCloud<PointT>& input, pcl::PointCloud<PointT>& output) const;

  /** \brief Warps the vertices of \a input into \a output (may be \a input): triangles and all other fields kept;
   *  normal_x/y/z, when present, recomputed from the warped polygons (area-weighted). Throws InvalidInputError if
   *  the vertex cloud has no float/double x, y, z fields or a polygon index is out of range.
   *  \param[in] input the mesh to warp
   *  \param[out] output the warped mesh
   */
  void
  transformMesh (const pcl::PolygonMesh& input, pcl::PolygonMesh& output) const;

  /** \brief \a mesh with warped vertices and the same triangles.
   *  \param[in] mesh the mesh to warp
   *  \return the warped mesh
   */
  TriangleMesh
  transformMesh (const TriangleMesh& mesh) const;

  /** \brief Warps the columns of \a positions (3 x N, double) in place; in 2D only x and y.
   *  \param[in,out] positions the points, replaced by their images
   */
  void
  transformPositions (Eigen::Matrix3Xd& positions) const;

private:
  void
  requireFitted (const char* caller) const;

  double regularization_ = 0.0;
  double max_condition_number_ = kDefaultMaxConditionNumber;
  bool fitted_ = false;
  detail::TpsCoefficients<Scalar, Dim> coefficients_;
  double bending_energy_ = 0.0;
  double condition_estimate_ = 0.0;
  Eigen::Index merged_landmarks_ = 0;
};

/** \brief The first Dim coordinates (x, y[, z]) of the points of \a cloud at \a indices (all points if empty), as
 *  columns.
 *  \param[in] cloud the cloud
 *  \param[in] indices the points wanted; empty for all
 *  \return Dim x indices.size () (or x cloud.size ()) coordinates
 */
template <typename Scalar, int Dim, typename PointT>
Eigen::Matrix<Scalar, Dim, Eigen::Dynamic>
cloudCoordinates (const pcl::PointCloud<PointT>& cloud, const pcl::Indices& indices = pcl::Indices ());

} // namespace morphreg

/// \cond
#define MORPHREG_DECLARE_TPS_POINT(S, D, T)                                                                            \
  extern template void morphreg::ThinPlateSpline<S, D>::fit<T, T> (const pcl::PointCloud<T>&,                          \
                                                                   const pcl::PointCloud<T>&);                         \
  extern template void morphreg::ThinPlateSpline<S, D>::fit<T, T> (                                                    \
      const pcl::PointCloud<T>&, const pcl::PointCloud<T>&, const pcl::Correspondences&);                              \
  extern template void morphreg::ThinPlateSpline<S, D>::transformCloud<T> (const pcl::PointCloud<T>&,                  \
                                                                           pcl::PointCloud<T>&) const;                 \
  extern template Eigen::Matrix<S, D, Eigen::Dynamic> morphreg::cloudCoordinates<S, D, T> (const pcl::PointCloud<T>&,  \
                                                                                           const pcl::Indices&);
#define MORPHREG_DECLARE_TPS(S, D)                                                                                     \
  extern template class morphreg::ThinPlateSpline<S, D>;                                                               \
  MORPHREG_DECLARE_TPS_POINT (S, D, pcl::PointXYZ)                                                                     \
  MORPHREG_DECLARE_TPS_POINT (S, D, pcl::PointNormal)                                                                  \
  MORPHREG_DECLARE_TPS_POINT (S, D, pcl::PointXYZRGBNormal)
MORPHREG_DECLARE_TPS (double, 3)
MORPHREG_DECLARE_TPS (float, 3)
MORPHREG_DECLARE_TPS (double, 2)
MORPHREG_DECLARE_TPS (float, 2)
#undef MORPHREG_DECLARE_TPS
#undef MORPHREG_DECLARE_TPS_POINT
/// \endcond

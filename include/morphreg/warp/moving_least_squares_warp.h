// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file moving_least_squares_warp.h
 *  \brief A landmark warp by moving least squares: every point gets the affine map that best carries the landmarks,
 *  weighted by their inverse squared distance to it (Schaefer, McPhail and Warren 2006, in 3D).
 */
#include <morphreg/mesh/triangle_mesh.h>

#include <pcl/PolygonMesh.h>

#include <Eigen/Core>

#include <memory>

namespace morphreg
{
/** \brief Warps points and meshes from source to target landmarks with a moving least squares affine deformation:
 *  point x goes to q*(x) + M(x)^T (x - p*(x)), where p*, q* are the landmarks' weighted centroids and M the affine
 *  map that best carries the source landmarks onto the targets under the weights w_i = 1 / |x - p_i|^(2 alpha).
 *  It interpolates the landmarks, reproduces any affine map exactly and, unlike a thin plate spline, is local: each
 *  region follows its nearest landmarks' affine motion, which suits warps between subjects (body proportions) with
 *  joints inside the body and landmarks on it. For re-posturing use ArticulatedWarp: an affine blend bends bones.
 *
 *  \code
 *  morphreg::MovingLeastSquaresWarp warp;
 *  warp.setLandmarks (source, target);                 // 3 x n each, mm
 *  morphreg::TriangleMesh warped = warp.warp (mesh);
 *  \endcode
 */
class MovingLeastSquaresWarp
{
public:
  using Ptr = std::shared_ptr<MovingLeastSquaresWarp>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const MovingLeastSquaresWarp>; ///< shared pointer to const

  /** \brief Sets the landmark pairs (columns). Coincident sources with coincident targets are merged. Throws
   *  InvalidInputError for mismatched counts, non-finite landmarks, coincident sources with different targets,
   *  fewer than four distinct landmarks or coplanar ones (an affine map in 3D needs four not on one plane).
   *  \param[in] source source landmarks (3 x n, mm)
   *  \param[in] target their targets (3 x n, mm)
   */
  void
  setLandmarks (const Eigen::Matrix3Xd& source, const Eigen::Matrix3Xd& target);

  /** \brief How fast a landmark's weight falls with distance: w = 1 / distance^(2 alpha) (alpha > 0, default 1;
   *  larger is more local).
   *  \param[in] alpha the exponent
   */
  void
  setFalloff (double alpha);

  /** \brief The falloff exponent alpha.
   *  \return alpha
   */
  double
  getFalloff () const
  {
    return alpha_;
  }

  /** \brief Landmark pairs dropped by setLandmarks() as duplicates of an earlier pair.
   *  \return the number
   */
  Eigen::Index
  mergedLandmarks () const
  {
    return merged_;
  }

  /** \brief The warped positions of \a points (InvalidInputError before setLandmarks() or for non-finite points).
   *  \param[in] points the points (3 x n, mm)
   *  \return their images
   */
  Eigen::Matrix3Xd
  transformPoints (const Eigen::Matrix3Xd& points) const;

  /** \brief \a mesh with every vertex warped (same triangles).
   *  \param[in] mesh the mesh
   *  \return the warped mesh
   */
  TriangleMesh
  warp (const TriangleMesh& mesh) const;

  /** \brief As warp(TriangleMesh) for a pcl::PolygonMesh of triangles; vertex normals are recomputed.
   *  \param[in] input the mesh to warp
   *  \param[out] output the warped mesh
   */
  void
  warp (const pcl::PolygonMesh& input, pcl::PolygonMesh& output) const;

private:
  /** The weights of landmarks at \a squared_distances (mm^2) from a point. */
  Eigen::ArrayXd
  weights (const Eigen::ArrayXd& squared_distances) const;

  /** Warps the columns of \a points into \a warped (a block of transformPoints()). */
  void
  warpBlock (const Eigen::Ref<const Eigen::Matrix3Xd>& points, Eigen::Ref<Eigen::Matrix3Xd> warped) const;

  Eigen::Matrix3Xd source_;  ///< distinct source landmarks
  Eigen::Matrix3Xd target_;  ///< their targets
  double coincidence_ = 0.0; ///< a point this close to a landmark (mm) is that landmark
  double alpha_ = 1.0;
  Eigen::Index merged_ = 0;
};

} // namespace morphreg

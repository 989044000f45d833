// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file triangle_locator.h
 *  \brief Closest point on a triangle mesh (point-to-triangle, not point-to-vertex) with a bounding volume
 *  hierarchy over the triangles, and whether that point lies on the mesh's open boundary.
 */
#include <morphreg/mesh/triangle_mesh.h>

#include <memory>
#include <vector>

namespace morphreg
{
/** \brief Barycentric coordinates (weights of a, b, c; sum 1) of the point of triangle (a, b, c) closest to \a p.
 *  A weight is exactly 0 when the closest point lies on the opposite edge, so edge and vertex cases are exact.
 *  Degenerate triangles are handled (their closest point lies on an edge).
 *  \param[in] p the query point
 *  \param[in] a the triangle's first corner
 *  \param[in] b its second corner
 *  \param[in] c its third corner
 *  \return the weights of a, b and c
 */
Eigen::Vector3d
closestPointOnTriangle (const Eigen::Vector3d& p, const Eigen::Vector3d& a, const Eigen::Vector3d& b,
                        const Eigen::Vector3d& c);

/** \brief Nearest-surface queries on a fixed triangle mesh (copied on construction).
 *
 *  \code
 *  morphreg::TriangleLocator locator (fitted);
 *  const auto hit = locator.closestPoint (sample);   // hit.point, hit.distance, hit.on_boundary
 *  \endcode
 */
class TriangleLocator
{
public:
  using Ptr = std::shared_ptr<TriangleLocator>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const TriangleLocator>; ///< shared pointer to const

  /** \brief Where a query met the surface. */
  struct Hit
  {
    Eigen::Vector3d point = Eigen::Vector3d::Zero ();       ///< the closest surface point
    Eigen::Vector3d barycentric = Eigen::Vector3d::Zero (); ///< its weights in \a triangle
    int triangle = -1;                                      ///< the triangle it lies on
    double distance = 0.0;                                  ///< from the query (mm)
    bool on_boundary = false; ///< it lies on an edge used by one triangle only, or on a vertex of such an edge
  };

  /** \brief Builds the hierarchy; throws InvalidInputError (via validateMesh) for an invalid mesh.
   *  \param[in] mesh the surface to query
   */
  explicit TriangleLocator (const TriangleMesh& mesh);

  /** \brief The closest point of the surface to \a query; throws InvalidInputError for a non-finite query.
   *  \param[in] query the point (mm)
   *  \return where the surface is closest to it
   */

  Hit
  closestPoint (const Eigen::Vector3d& query) const;

private:
  struct Node
  {
    Eigen::Vector3d low;
    Eigen::Vector3d high;
    int first; ///< leaf: first entry of order_; inner node: index of the left child
    int count; ///< leaf: number of triangles; 0 for an inner node
    int right; ///< inner node: index of the right child
  };

  int
  build (int begin, int end, const Eigen::Matrix3Xd& centroids);

  bool
  onBoundary (int triangle, const Eigen::Vector3d& barycentric) const;

  TriangleMesh mesh_;
  std::vector<int> order_;
  std::vector<Node> nodes_;
  std::vector<unsigned char> boundary_edges_; ///< per triangle: bit k set if the edge opposite corner k is open
  std::vector<bool> boundary_vertices_;
};

} // namespace morphreg

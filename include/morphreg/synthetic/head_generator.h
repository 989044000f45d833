// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file head_generator.h
 *  \brief Deterministic synthetic human heads in one fixed topology: the project's built-in head population.
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/model/region_segmentation.h>
#include <morphreg/synthetic/head_parameters.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace morphreg
{
namespace synthetic
{
/** \brief The seven regions of the thesis's multi-region model. */
enum class HeadRegion : int
{
  eyes = 0,  ///< both eyes and their sockets
  nose,      ///< the nose
  mouth,     ///< lips and mouth
  ears,      ///< both ears
  chin,      ///< the chin
  cheeks,    ///< both cheeks
  skull_neck ///< everything else: skull, forehead, neck
};

/** \brief Number of HeadRegion values. */
constexpr int kNumHeadRegions = 7;

/** \brief Lower-case name of a region ("eyes", ..., "skull_neck").
 *  \param[in] region the region
 *  \return its name
 */
std::string
headRegionName (HeadRegion region);

/** \brief One generated head: its mesh (mm) and the parameters that shaped it. */
struct SyntheticHead
{
  TriangleMesh mesh;         ///< the head, mm
  HeadParameters parameters; ///< the measurements it was generated from
};

/** \brief Generates closed, manifold head-and-neck meshes (+Y up, +Z out of the face, +X to the subject's
 *  left, mm) whose shape follows HeadParameters. Every head shares one topology, so vertex i is the same
 *  anatomical point on every head: landmarks, the profile line and region labels hold for all of them.
 *
 *  \code
 *  morphreg::synthetic::HeadGenerator generator;
 *  auto heads = generator.population (200, 42);            // deterministic from the seed
 *  int nose = generator.landmarks ().at ("nose_tip");
 *  \endcode
 */
class HeadGenerator
{
public:
  using Ptr = std::shared_ptr<HeadGenerator>;            ///< shared pointer
  using ConstPtr = std::shared_ptr<const HeadGenerator>; ///< shared pointer to const

  /** \brief \a resolution (even, 20-44) cells per cube edge of the underlying sphere: 6 r^2 + 2 vertices
   *  (the default 40 gives 9602).
   *  \param[in] resolution the sphere's cells per cube edge
   */
  explicit HeadGenerator (int resolution = 40);

  /** \brief The head with the given parameters (validated).
   *  \param[in] parameters the measurements
   *  \return the head mesh
   */
  TriangleMesh
  generate (const HeadParameters& parameters) const;

  /** \brief The head whose parameters are drawn from the population with \a seed.
   *  \param[in] seed the random seed
   *  \return the head and its parameters
   */
  SyntheticHead
  sample (std::uint64_t seed) const;

  /** \brief \a count heads; head i uses the parameters drawn with seed + i, so any subset can be regenerated.
   *  \param[in] count the number of heads
   *  \param[in] seed the seed of the first head
   *  \return the heads, in seed order
   */
  std::vector<SyntheticHead>
  population (int count, std::uint64_t seed) const;

  /** \brief The shared triangles (3 x M, counter-clockwise seen from outside).
   *  \return the triangles of every head
   */
  const TriangleMesh::Triangles&
  triangles () const
  {
    return triangles_;
  }

  /** \brief The number of vertices of every head.
   *  \return 6 r^2 + 2 for resolution r
   */
  Eigen::Index
  numVertices () const
  {
    return directions_.cols ();
  }

  /** \brief Landmark ids of docs/landmarks.md -> vertex index (every id that exists on a 3D head).
   *  \return id -> vertex index, the same on every head
   */
  const LandmarkVertices&
  landmarks () const
  {
    return landmarks_;
  }

  /** \brief Vertices on the mid-sagittal plane (x = 0), ordered from the front of the neck over the face and
   *  the crown to the back of the neck.
   *  \return the vertex indices in order
   */
  const std::vector<int>&
  profileLine () const
  {
    return profile_line_;
  }

  /** \brief Region of each vertex.
   *  \return one region per vertex
   */
  const std::vector<HeadRegion>&
  regionLabels () const
  {
    return region_labels_;
  }

  /** \brief The seven regions named (headRegionName) and indexed per vertex, as ModelBuilder::build takes them.
   *  \return the region names and labels
   */

  RegionLabels
  regions () const;

private:
  void
  placeLandmarks ();

  void
  traceProfileLine (const TriangleMesh& mean_head, double neck_cut);

  void
  labelRegions (const TriangleMesh& mean_head);

  Eigen::Matrix3Xd directions_;
  TriangleMesh::Triangles triangles_;
  LandmarkVertices landmarks_;
  std::vector<int> profile_line_;
  std::vector<HeadRegion> region_labels_;
};

} // namespace synthetic
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file fitted_mesh_io.h
 *  \brief A fitted mesh as `morphreg register` and ScanFileRegistration write it, read back with its residuals: the
 *  per-vertex float "quality" of the PLY (mm; NaN where no scan point corresponds), so that a viewer can colour it.
 */
#include <pcl/PolygonMesh.h>

#include <Eigen/Core>

#include <optional>
#include <string>

namespace morphreg
{
/** \brief A mesh file and the residuals it carries, if any. */
struct FittedMeshFile
{
  pcl::PolygonMesh mesh;                    ///< the mesh as read
  std::optional<Eigen::VectorXd> residuals; ///< per vertex (mm; NaN: no correspondence); none without a quality
  std::string note; ///< why a quality field was not taken as residuals (not a distance); empty otherwise
};

/** \brief The residuals in \a mesh's per-vertex float "quality", if it has one that can be a distance (no negative
 *  or infinite value: another tool's curvature is not taken for residuals, and \a note says why).
 *  \param[in] mesh the mesh
 *  \param[out] note empty, or why the quality was not taken
 *  \return the residuals, or none */
std::optional<Eigen::VectorXd>
vertexResiduals (const pcl::PolygonMesh& mesh, std::string& note);

/** \brief Loads a mesh file (loadPolygonMesh) with its residuals (vertexResiduals); the note names \a path.
 *  \param[in] path the mesh file
 *  \return the mesh, its residuals and the note */
FittedMeshFile
loadFittedMesh (const std::string& path);
} // namespace morphreg

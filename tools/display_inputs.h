// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// What render and view show, read from files: scans (missing points skipped) and fitted meshes coloured by their
// residuals (the per-vertex "quality" register writes), with the colour scale register uses.
#include <pcl/PolygonMesh.h>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <optional>
#include <string>
#include <utility>

namespace morphreg
{
class RegistrationVisualizer;

namespace tools
{
/** The residuals (mm) of a mesh register wrote: its per-vertex float "quality" (NaN where no scan point
 *  corresponds); none when the mesh has no such field. A quality that cannot be a distance (negative or infinite,
 *  e.g. another tool's curvature) gives none, and a note naming \a path on stderr. */
std::optional<Eigen::VectorXd>
vertexQuality (const pcl::PolygonMesh& mesh, const std::string& path);

/** Shows the scan file \a path as \a id: alone, every valid point; over a mesh (\a over_mesh), a sparse grey sample
 *  for a \a width x \a height picture (addScanOverlay). A cloud without a valid point is an InvalidInputError naming
 *  \a path. \return the cloud as read */
pcl::PointCloud<pcl::PointXYZ>::Ptr
addScanFile (RegistrationVisualizer& viewer, const std::string& path, bool over_mesh, int width, int height,
             const std::string& id);

/** Shows the mesh file \a path as \a id in \a viewport: coloured by its residuals with the colour bar (top
 *  \a colour_max mm, 0: residualColourScale's) if it has them, else in the model colour at \a opacity.
 *  \return the mesh as read and its residuals, if any */
std::pair<pcl::PolygonMesh, std::optional<Eigen::VectorXd>>
addMeshFile (RegistrationVisualizer& viewer, const std::string& path, double colour_max, double opacity,
             const std::string& id, int viewport = 0);
} // namespace tools
} // namespace morphreg

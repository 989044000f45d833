// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file fit_layers.h
 *  \brief What the command line's pictures of a fit show, for any program: scan and fitted-mesh files added to a
 *  RegistrationVisualizer (the fit coloured by its residuals), the fit's correspondences to the scan, and the overlay
 *  picture `morphreg register --screenshot` writes.
 */
#include <morphreg/io/fitted_mesh_io.h>
#include <morphreg/mesh/triangle_mesh.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <Eigen/Core>

#include <cstddef>
#include <optional>
#include <string>

namespace morphreg
{
class RegistrationVisualizer;

/** \brief Shows the scan file \a path as \a id: alone, every valid point; over a mesh (\a over_mesh), a sparse grey
 *  sample for a \a width x \a height picture (addScanOverlay). InvalidInputError naming \a path for a cloud without a
 *  valid point.
 *  \param[in,out] viewer the visualiser
 *  \param[in] path the scan file
 *  \param[in] over_mesh whether a mesh is drawn over it
 *  \param[in] width the picture's width (pixels)
 *  \param[in] height the picture's height (pixels)
 *  \param[in] id the layer's id
 *  \return the cloud as read */
pcl::PointCloud<pcl::PointXYZ>::Ptr
addScanFile (RegistrationVisualizer& viewer, const std::string& path, bool over_mesh, int width, int height,
             const std::string& id);

/** \brief Shows the mesh file \a path as \a id in \a viewport: coloured by its residuals with the colour bar (top
 *  \a colour_max mm, 0: residualColourScale's) if it has them (loadFittedMesh), else in the model colour.
 *  \param[in,out] viewer the visualiser
 *  \param[in] path the mesh file
 *  \param[in] colour_max the residual at the top of the colour scale (mm; 0: from the residuals)
 *  \param[in] opacity the opacity of a mesh without residuals
 *  \param[in] id the layer's id
 *  \param[in] viewport the viewport
 *  \return the file as read (its note says why a quality was not drawn as residuals) */
FittedMeshFile
addFittedMeshFile (RegistrationVisualizer& viewer, const std::string& path, double colour_max, double opacity,
                   const std::string& id, int viewport = 0);

/** \brief Lines from the fitted vertices that have a residual (all, without residuals) to their nearest valid scan
 *  points, at most \a most of them, evenly spread over the vertices, as the layer \a id.
 *  \param[in,out] viewer the visualiser
 *  \param[in] scan the scan (NaN points skipped)
 *  \param[in] fit the fitted mesh, in the scan's frame
 *  \param[in] residuals the fit's per-vertex residuals (NaN: no correspondence), if known
 *  \param[in] most the most lines drawn
 *  \param[in] id the layer's id */
void
addFitCorrespondences (RegistrationVisualizer& viewer, const pcl::PointCloud<pcl::PointXYZ>& scan,
                       const TriangleMesh& fit, const std::optional<Eigen::VectorXd>& residuals, std::size_t most,
                       const std::string& id = "correspondences");

/** \brief Writes the picture of a fit: the fitted mesh coloured by residual under a sparse sample of the scan's
 *  points (small, grey: no moire), seen from the fitted face's front-left, the head filling the picture.
 *  \param[in,out] viewer an offscreen visualiser
 *  \param[in] scan the scan
 *  \param[in] fitted the fitted mesh, in the scan's frame
 *  \param[in] residuals its per-vertex residuals (mm; NaN: no correspondence)
 *  \param[in] colour_scale the residual at the top of the colour scale (mm)
 *  \param[in] pose the fit's similarity from the model's frame into the scan's (its rotation turns the view)
 *  \param[in] path the PNG to write
 *  \param[in] width the picture's width (pixels)
 *  \param[in] height the picture's height (pixels) */
void
saveFitOverlay (RegistrationVisualizer& viewer, const pcl::PointCloud<pcl::PointNormal>& scan,
                const TriangleMesh& fitted, const Eigen::VectorXd& residuals, double colour_scale,
                const Eigen::Matrix4d& pose, const std::string& path, int width, int height);
} // namespace morphreg

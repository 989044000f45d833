// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file mesh_annotations.h
 *  \brief Annotation files of meshes in correspondence (JSON): a region label per vertex and the vertex of each
 *  landmark. The synthetic populations carry them beside their heads; model building and the segmented and
 *  articulated warps read them.
 *
 *  Layouts: {"regions": [names], "labels": [region index per vertex]} (MakeHuman's segment files name the regions
 *  "segments") and {"landmark_vertices": {"nose_tip": 123, ...}}.
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/model/region_segmentation.h>

#include <Eigen/Core>

#include <string>

namespace morphreg
{
/** \brief Writes \a regions as {"regions": [names], "labels": [region index per vertex]}.
 *  \param[in] path the JSON file
 *  \param[in] regions the labels and their names
 */
void
saveRegionLabels (const std::string& path, const RegionLabels& regions);

/** \brief Reads a region label file for a mesh of \a num_vertices vertices (the names may be given as "segments"
 *  instead of "regions", or left out: region_<k>). Throws FormatError naming the file for a wrong layout, a wrong
 *  label count or an empty region.
 *  \param[in] path the JSON file
 *  \param[in] num_vertices the vertices of the mesh it labels
 *  \return the labels and their names
 */
RegionLabels
loadRegionLabels (const std::string& path, Eigen::Index num_vertices);

/** \brief Writes \a landmarks as {"landmark_vertices": {id: vertex index}}.
 *  \param[in] path the JSON file
 *  \param[in] landmarks the vertex of each landmark id
 */
void
saveLandmarkVertices (const std::string& path, const LandmarkVertices& landmarks);

/** \brief Reads a landmark vertex file. Throws FormatError naming the file for a wrong layout, an unknown landmark
 *  id or an index outside [0, num_vertices).
 *  \param[in] path the JSON file
 *  \param[in] num_vertices the vertices of the mesh it annotates
 *  \return the vertex of each landmark id
 */
LandmarkVertices
loadLandmarkVertices (const std::string& path, Eigen::Index num_vertices);
} // namespace morphreg

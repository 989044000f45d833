// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Annotation files of meshes in correspondence (JSON): region labels per vertex and landmark vertex indices.
// synth and demo write them next to the population; build-model and warp read them.
#include <morphreg/common/landmarks.h>
#include <morphreg/model/region_segmentation.h>
#include <morphreg/synthetic/head_generator.h>

#include <string>

namespace morphreg
{
namespace tools
{
/** Writes {"regions": [names], "labels": [region index per vertex]}. */
void
saveRegionLabels (const std::string& path, const RegionLabels& regions);

/** Reads a region label file for a mesh of \a num_vertices vertices (the names may be given as "segments" instead
 *  of "regions", or left out: region_<k>);
 *  throws FormatError naming the file for a wrong layout, a wrong label count or an empty region.
 */
RegionLabels
loadRegionLabels (const std::string& path, Eigen::Index num_vertices);

/** Writes {"landmark_vertices": {id: vertex index}}. */
void
saveLandmarkVertices (const std::string& path, const LandmarkVertices& landmarks);

/** Reads a landmark vertex file; throws FormatError naming the file for a wrong layout or an index outside
 *  [0, num_vertices).
 */
LandmarkVertices
loadLandmarkVertices (const std::string& path, Eigen::Index num_vertices);
} // namespace tools
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Writing the synthetic population and simulated scans to disk, shared by the synth and demo commands.
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/photo_simulator.h>
#include <morphreg/synthetic/scan_simulator.h>

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace morphreg
{
namespace tools
{
/** Writes head_<i>.ply and head_<i>_landmarks.json for each head, regions.json and landmark_vertices.json (the
 *  shared topology's annotations, see morphreg/io/mesh_annotations.h) and population.json (parameters per head, profile line);
 *  returns the manifest written. */
nlohmann::json
writePopulation (const std::string& directory, const synthetic::HeadGenerator& generator,
                 const std::vector<synthetic::SyntheticHead>& heads, std::uint64_t seed, bool quiet);

/** Writes <name>.pcd (points with normals), <name>_truth.json (pose, per-point source triangle), the scanned
 *  \a head posed into the scan frame as <name>_truth.ply (the ground truth of `register --truth`), its landmarks
 *  there as <name>_landmarks.json and, when the scan has one, <name>_range.ply; returns a summary for reports. */
nlohmann::json
writeScan (const std::string& directory, const std::string& name, const synthetic::SimulatedScan& scan,
           const TriangleMesh& head, const LandmarkVertices& landmarks);

/** Writes the annotations of two simulated photos of head \a head_index of writePopulation's heads as
 *  <name>_profile.json and <name>_frontal.json (read by `fit-photos`), and <name>_truth.json: the head file and the
 *  similarity that took it into the photos' normalised frame (the ground truth of `fit-photos --truth`); returns a
 *  summary for reports. */
nlohmann::json
writePhotos (const std::string& directory, const std::string& name, const synthetic::SimulatedPhotos& photos,
             std::size_t head_index);

/** Creates \a directory (and parents); throws IoError naming it on failure. */
void
makeDirectory (const std::string& directory);

} // namespace tools
} // namespace morphreg

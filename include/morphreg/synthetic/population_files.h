// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file population_files.h
 *  \brief The synthetic population, simulated scans and simulated photos written to disk as a study: the heads with
 *  their landmarks and the topology's annotations, each scan with its ground truth, each photo pair with the head and
 *  similarity it was taken of. Every front end that writes synthetic data writes these files.
 *
 *  \code
 *  const morphreg::synthetic::HeadGenerator generator (40);
 *  const auto heads = generator.population (20, 1);
 *  morphreg::synthetic::writePopulationFiles ("out", generator, heads, 1);  // out/population.json and the heads
 *  \endcode
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/photo_simulator.h>
#include <morphreg/synthetic/scan_simulator.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace morphreg
{
namespace synthetic
{
/** \brief Called after each head is written, with the number written so far (from 1). */
using HeadWrittenCallback = std::function<void (std::size_t)>;

/** \brief Writes head_\<i\>.ply and head_\<i\>_landmarks.json for each head, regions.json and landmark_vertices.json
 *  (the shared topology's annotations, see morphreg/io/mesh_annotations.h) and, last, population.json (parameters
 *  per head, profile line). Creates \a directory; IoError naming a directory or file that cannot be written.
 *  \param[in] directory the folder to write into
 *  \param[in] generator the generator of \a heads (topology, regions, landmarks, profile line)
 *  \param[in] heads the heads drawn from \a generator with seeds \a seed, \a seed + 1, ...
 *  \param[in] seed the first head's seed, recorded in the manifest
 *  \param[in] provenance added to population.json as "morphreg" when not null (what wrote it)
 *  \param[in] head_written told after each head, or empty
 *  \return the manifest written (population.json without the provenance)
 */
nlohmann::json
writePopulationFiles (const std::string& directory, const HeadGenerator& generator,
                      const std::vector<SyntheticHead>& heads, std::uint64_t seed,
                      const nlohmann::json& provenance = nullptr, const HeadWrittenCallback& head_written = {});

/** \brief Writes \<name\>.pcd (points with normals), \<name\>_truth.json (pose, per-point source triangle), the scanned
 *  \a head posed into the scan frame as \<name\>_truth.ply (a registration's ground truth), its landmarks there as
 *  \<name\>_landmarks.json and, when the scan has one, \<name\>_range.ply. Creates \a directory; IoError naming a
 *  directory or file that cannot be written.
 *  \param[in] directory the folder to write into
 *  \param[in] name the files' common stem
 *  \param[in] scan the simulated scan of \a head
 *  \param[in] head the scanned head, head frame (mm)
 *  \param[in] landmarks the landmarks' vertices on \a head
 *  \param[in] provenance added to the truth JSON as "morphreg" when not null
 *  \return a summary for reports: the files, point and outlier counts and the scale
 */
nlohmann::json
writeScanFiles (const std::string& directory, const std::string& name, const SimulatedScan& scan,
                const TriangleMesh& head, const LandmarkVertices& landmarks,
                const nlohmann::json& provenance = nullptr);

/** \brief Writes the annotations of two simulated photos of head \a head_index of writePopulationFiles()'s heads as
 *  \<name\>_profile.json and \<name\>_frontal.json, and \<name\>_truth.json: the head file and the similarity that took it
 *  into the photos' normalised frame (read by readPhotoTruth() in morphreg/pipeline/photo_registration.h). Creates
 *  \a directory; IoError naming a directory or file that cannot be written.
 *  \param[in] directory the folder to write into (the population's, for the truth's head file to be found)
 *  \param[in] name the files' common stem
 *  \param[in] photos the simulated photos
 *  \param[in] head_index the photographed head's index in the population
 *  \param[in] provenance added to the truth JSON as "morphreg" when not null
 *  \return a summary for reports: the files
 */
nlohmann::json
writePhotoFiles (const std::string& directory, const std::string& name, const SimulatedPhotos& photos,
                 std::size_t head_index, const nlohmann::json& provenance = nullptr);

/** \brief What writeSyntheticStudy writes: the heads, and scans and photo pairs of the first of them. */
struct SyntheticStudySettings
{
  int count = 20;                    ///< heads
  std::uint64_t seed = 1;            ///< seed of the first head (head i uses seed + i)
  int resolution = 40;               ///< the heads' mesh resolution (HeadGenerator)
  int scans = 0;                     ///< scans of the first heads (at most count)
  int photos = 0;                    ///< profile and frontal photo pairs of the first heads, each nodding 5 degrees
  ScanSimulator::Parameters scanner; ///< the scanner of the scans
};

/** \brief Progress of writeSyntheticStudy: \a done of \a count of the stage ("writing heads", "scanning heads"). */
using StudyProgress = std::function<void (const std::string& stage, int done, int count)>;

/** \brief A synthetic study written into \a directory (`morphreg synth`): the heads (writePopulationFiles), scans
 *  scan_I (writeScanFiles) and photo pairs photo_I (writePhotoFiles). InvalidInputError before anything is written
 *  for bad scanner settings or more scans or photos than heads.
 *  \param[in] directory the folder (it must exist)
 *  \param[in] settings what to write
 *  \param[in] provenance what made the files, in their records (e.g. the version and command line)
 *  \param[in] progress told as the heads are written and scanned; empty: nobody */
void
writeSyntheticStudy (const std::string& directory, const SyntheticStudySettings& settings,
                     const nlohmann::json& provenance = nullptr, const StudyProgress& progress = {});

} // namespace synthetic
} // namespace morphreg

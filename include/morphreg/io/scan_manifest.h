// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file scan_manifest.h
 *  \brief The list of scans of a study (`register --scans`, `build-model --from-scans`): a manifest CSV or a
 *  folder of scans, and a deterministic share of it for one machine of a cluster.
 *
 *  Manifest CSV: one scan a row, `scan[,landmarks[,id]]`; an optional header `scan,landmarks,id`; blank lines and
 *  lines starting with `#` are ignored. Relative paths are relative to the manifest's folder. The id (default: the
 *  scan's file name without extension) names the scan's outputs, so it must be unique and a plain file name.
 *
 *  \code
 *  morphreg::ScanManifest scans = morphreg::loadScanList ("study/manifest.csv");
 *  for (const morphreg::ScanEntry& entry : morphreg::manifestShard (scans, 0, 4))
 *    std::cout << entry.id << ": " << entry.scan << '\n';
 *  \endcode
 */
#include <string>
#include <vector>

namespace morphreg
{
/** \brief One scan of a study: its file, optional landmark file and the id naming its outputs. */
struct ScanEntry
{
  std::string id;        ///< names the scan's outputs (a plain file name)
  std::string scan;      ///< the scan file
  std::string landmarks; ///< empty: none
  std::string where;     ///< where it was listed ("manifest.csv:4" or the folder), for messages
};

/** \brief The scans of a study, in manifest (or file name) order. */
using ScanManifest = std::vector<ScanEntry>;

/** \brief Reads a manifest CSV. Throws IoError for a missing file, FormatError naming the file and line for a
 *  row of more than three fields, an empty scan path, an id that is not a plain file name, a duplicate id, or
 *  a manifest without rows.
 *  \param[in] path the manifest CSV
 *  \return its rows, relative paths resolved against the manifest's folder
 */
ScanManifest
loadScanManifest (const std::string& path);

/** \brief Every scan file (.pcd .ply .obj .stl .off .gltf .glb) directly in \a directory, sorted by name, each with the
 *  landmark file `<name>_landmarks.{json,pp,csv,pts}` beside it if there is one. Throws IoError if \a directory
 *  is missing, FormatError if it holds no scan or two scans share a name.
 *  \param[in] directory the folder of scans
 *  \return one entry per scan, with its file name stem as id
 */
ScanManifest
listScanDirectory (const std::string& directory);

/** \brief listScanDirectory() for a folder, loadScanManifest() for a file.
 *  \param[in] directory_or_manifest a folder of scans or a manifest CSV
 *  \return the scans
 */
ScanManifest
loadScanList (const std::string& directory_or_manifest);

/** \brief Share \a index of \a count (0 <= index < count): the entries at positions index, index + count, ...
 *  Deterministic, so the machines of a job array together take every scan exactly once. Throws
 *  InvalidInputError for an index outside [0, count).
 *  \param[in] manifest all scans
 *  \param[in] index this machine's share, 0-based
 *  \param[in] count the number of shares
 *  \return the share's entries, in manifest order
 */

ScanManifest
manifestShard (const ScanManifest& manifest, int index, int count);

} // namespace morphreg

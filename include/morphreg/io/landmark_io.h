// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file landmark_io.h
 *  \brief Landmark files: MeshLab PickedPoints (.pp), JSON (.json: morphreg's or scalismo's array layout), CSV
 *  (.csv) and iBUG (.pts, the 68 points as ibug68_00 .. ibug68_67), holding 3D positions (mm) or, for photos, 2D
 *  pixel positions. The layouts are documented in README.md (Landmark files).
 *
 *  Every reader rejects, with an error naming the file and the line or element: a missing or empty file (IoError),
 *  malformed content, a malformed or non-finite number, a wrong number of coordinates, a duplicate id or a file
 *  without landmarks (FormatError), and an id that is not in knownLandmarkIds() (InvalidInputError listing them).
 *
 *  \code
 *  morphreg::LandmarkPositions marked = morphreg::loadLandmarks ("scan_landmarks.pp");
 *  morphreg::saveLandmarks ("scan_landmarks.json", marked);
 *  \endcode
 */
#include <morphreg/common/landmarks.h>

#include <Eigen/Core>

#include <map>
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace morphreg
{
/** \brief Loads 3D landmarks from a .pp, .json, .csv or .pts file (chosen by the extension), in millimetres
 *  (JSON files stating "cm" or "m" are converted). Inactive MeshLab points (active="0") are skipped. A JSON file
 *  whose top level is an array is read as scalismo's layout [{"id": ..., "coordinates": [x, y, z]}], with Basel
 *  Face Model ids translated by fromBfmLandmarkId().
 *  \param[in] path the landmark file
 *  \return the landmarks by id, mm
 */
LandmarkPositions
loadLandmarks (const std::string& path);

/** \brief As loadLandmarks(path), and requires exactly the ids \a expected_ids: throws FormatError stating the
 *  counts and listing the missing and unexpected ids otherwise.
 *  \param[in] path the landmark file
 *  \param[in] expected_ids the ids the file must hold, no more and no fewer
 *  \return the landmarks by id, mm
 */
LandmarkPositions
loadLandmarks (const std::string& path, const std::vector<std::string>& expected_ids);

/** \brief As loadLandmarks(path), but any non-empty name is accepted (e.g. the joint names of a body rig for
 *  thin plate spline warping); duplicates and malformed content are still errors.
 *  \param[in] path the file
 *  \return the points by name, mm
 */
LandmarkPositions
loadNamedPoints (const std::string& path);

/** \brief Parses scalismo landmark JSON \a text (e.g. a BFM-2017 file's metadata/landmarks/json), naming
 *  \a source in errors; ids are translated by fromBfmLandmarkId() and otherwise kept as they are.
 *  \param[in] text the JSON text
 *  \param[in] source where the text comes from, for messages
 *  \return the landmarks by id, mm
 */
LandmarkPositions
parseScalismoLandmarks (const std::string& text, const std::string& source);

/** \brief Loads 2D pixel landmarks from a .json, .csv or .pts file (PickedPoints files hold 3D points only).
 *  \param[in] path the landmark file
 *  \return the landmarks by id, pixels
 */
LandmarkPixels
loadLandmarkPixels (const std::string& path);

/** \brief As loadLandmarkPixels(path), and requires exactly the ids \a expected_ids.
 *  \param[in] path the landmark file
 *  \param[in] expected_ids the ids the file must hold, no more and no fewer
 *  \return the landmarks by id, pixels
 */
LandmarkPixels
loadLandmarkPixels (const std::string& path, const std::vector<std::string>& expected_ids);

/** \brief Writes 3D landmarks (mm) as .pp, .json or .csv (by the extension), in the order of knownLandmarkIds()
 *  then ibug68LandmarkIds().
 *  Throws InvalidInputError for an empty set, an unknown id or a non-finite position, IoError if the file
 *  cannot be written.
 *  \param[in] path the file; its extension chooses the format
 *  \param[in] landmarks the landmarks by id, mm
 */
void
saveLandmarks (const std::string& path, const LandmarkPositions& landmarks);

/** \brief The JSON document saveLandmarkPixels() writes for \a pixels (a file's content to extend before writing it).
 *  \param[in] pixels the landmarks, in pixels
 *  \param[in] path the file it is meant for, for messages
 *  \return the document
 */
nlohmann::json
landmarkPixelsJson (const LandmarkPixels& pixels, const std::string& path);

/** \brief Writes 2D pixel landmarks as .json or .csv, in the order of knownLandmarkIds().
 *  \param[in] path the file; its extension chooses the format
 *  \param[in] pixels the landmarks by id, pixels
 */

void
saveLandmarkPixels (const std::string& path, const LandmarkPixels& pixels);

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file landmarks.h
 *  \brief The project's landmark vocabulary (docs/landmarks.md) and a named landmark set.
 */
#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief All landmark ids the project knows, in the order of docs/landmarks.md (frontal 1-40, then the rest).
 *  \return the ids, built once
 */
const std::vector<std::string>&
knownLandmarkIds ();

/** \brief The id of iBUG-68 point \a number (0-67, the 1-68 of the annotation scheme less one): "ibug68_07".
 *  \param[in] number the 0-based point number; InvalidInputError outside 0-67
 *  \return the id, with two digits
 */
std::string
ibug68LandmarkId (int number);

/** \brief The 68 iBUG ids "ibug68_00" .. "ibug68_67", in point order (the order of a .pts file).
 *  \return the ids, built once
 */
const std::vector<std::string>&
ibug68LandmarkIds ();

/** \brief Whether \a id is one of knownLandmarkIds() or of ibug68LandmarkIds().
 *  \param[in] id the landmark id
 *  \return true for a project or iBUG id
 */
bool
isKnownLandmarkId (const std::string& id);

/** \brief The project id of a Basel Face Model / scalismo landmark id ("center.nose.tip" -> "nose_tip"), or
 *  \a id itself when it has no equivalent. Left and right are the subject's in both vocabularies.
 *  \param[in] id a BFM / scalismo landmark id
 *  \return the project id, or \a id unchanged
 */
std::string
fromBfmLandmarkId (const std::string& id);

/** \brief Throws InvalidInputError naming \a source and listing the known ids when \a id is unknown.
 *  \param[in] id the landmark id to check
 *  \param[in] source where the id was read (a file and line), for the message
 */
void
requireKnownLandmarkId (const std::string& id, const std::string& source);

/** \brief Named 3D landmark positions (mm), e.g. marked on a scan: id -> position. */
using LandmarkPositions = std::map<std::string, Eigen::Vector3d>;

/** \brief Named 2D landmark positions in a photo, in pixels: x to the right, y down, origin at the top-left
 *  corner of the image (the centre of the first pixel is (0.5, 0.5)).
 */
using LandmarkPixels = std::map<std::string, Eigen::Vector2d>;

/** \brief Throws InvalidInputError naming both ids and both files when two landmarks at one position in \a source
 *  (within 1e-9 of its extent) are apart in \a target: a warp cannot send one point to two places. Landmarks that
 *  coincide in both (a bone's tail at the next bone's head) are fine: a warp merges them.
 *  \param[in] source the source landmarks
 *  \param[in] target the target landmarks, with the same ids
 *  \param[in] source_name where \a source was read, for the message
 *  \param[in] target_name where \a target was read, for the message
 */
void
requireOneTargetPerPoint (const LandmarkPositions& source, const LandmarkPositions& target,
                          const std::string& source_name, const std::string& target_name);

/** \brief Named landmark vertices of a mesh or model: id -> vertex index. */
using LandmarkVertices = std::map<std::string, int>;

/** \brief Keeps the landmarks of \a landmarks whose id is one of \a known (e.g. a model's landmark vertices).
 *  \param[in,out] landmarks the landmarks, left with the known ones
 *  \param[in] known the ids to keep
 *  \return the ids removed, in order
 */
std::vector<std::string>
keepKnownLandmarks (LandmarkPositions& landmarks, const LandmarkVertices& known);

/** \brief The 40 frontal-photo landmark ids (docs/landmarks.md 1-40, thesis table 1), in that order.
 *  \return the ids
 */
std::vector<std::string>
frontalLandmarkIds ();

/** \brief Whether \a id is a point of a photo's outline rather than a fixed point of the face: the jaw, chin,
 *  neck and head-contour ids (docs/landmarks.md 29-40), the menton `chin` and iBUG-68's jaw line (ibug68_00 ..
 *  ibug68_16). Where the outline runs over the head depends on the head's shape and pose, so no one vertex of a model
 *  marks it.
 *  \param[in] id the landmark id
 *  \return true for an outline id
 */
bool
isOutlineLandmarkId (const std::string& id);

/** \brief The entries of \a landmarks whose id is one of frontalLandmarkIds().
 *  \param[in] landmarks landmark vertices of a mesh or model
 *  \return the frontal ones among them
 */
LandmarkVertices

frontalLandmarks (const LandmarkVertices& landmarks);

} // namespace morphreg

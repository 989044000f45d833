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
/** \brief All landmark ids the project knows, in the order of docs/landmarks.md (frontal 1-40, then the rest). */
const std::vector<std::string>&
knownLandmarkIds ();

/** \brief The id of iBUG-68 point \a number (0-67, the 1-68 of the annotation scheme less one): "ibug68_07". */
std::string
ibug68LandmarkId (int number);

/** \brief The 68 iBUG ids "ibug68_00" .. "ibug68_67", in point order (the order of a .pts file). */
const std::vector<std::string>&
ibug68LandmarkIds ();

/** \brief True if \a id is one of knownLandmarkIds() or of ibug68LandmarkIds(). */
bool
isKnownLandmarkId (const std::string& id);

/** \brief The project id of a Basel Face Model / scalismo landmark id ("center.nose.tip" -> "nose_tip"), or
 *  \a id itself when it has no equivalent. Left and right are the subject's in both vocabularies.
 */
std::string
fromBfmLandmarkId (const std::string& id);

/** \brief Throws InvalidInputError naming \a source and listing the known ids when \a id is unknown. */
void
requireKnownLandmarkId (const std::string& id, const std::string& source);

/** \brief Named 3D landmark positions (mm), e.g. marked on a scan: id -> position. */
using LandmarkPositions = std::map<std::string, Eigen::Vector3d>;

/** \brief Named landmark vertices of a mesh or model: id -> vertex index. */
using LandmarkVertices = std::map<std::string, int>;

/** \brief The 40 frontal-photo landmark ids (docs/landmarks.md 1-40, thesis table 1), in that order. */
std::vector<std::string>
frontalLandmarkIds ();

/** \brief Whether \a id is a point of a frontal photo's outline rather than a fixed point of the face: the jaw, chin,
 *  neck and head-contour ids (docs/landmarks.md 29-40) and the menton `chin`. Where the outline runs over the head depends
 *  on the head's shape and pose, so no one vertex of a model marks it.
 */
bool
isFrontalContourLandmarkId (const std::string& id);

/** \brief The entries of \a landmarks whose id is one of frontalLandmarkIds(). */
LandmarkVertices
frontalLandmarks (const LandmarkVertices& landmarks);

} // namespace morphreg

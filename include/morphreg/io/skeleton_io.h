// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file skeleton_io.h
 *  \brief Skeleton files (JSON): the bones of an ArticulatedWarp, by joint names.
 *
 *  Layout: {"bones": [{"name": "upperleg.L", "head": "hip.L", "tail": "knee.L", "segment": "lower_body",
 *  "twist": ["hip.R", "hip.L"]}, ...], "other_joints": ["thigh_mid.L", ...]}; "twist" is optional (no twist: the
 *  bone's shortest rotation), and so are "other_joints" (joints no bone uses; landmarks with these names are
 *  ignored by the warp rather than taken for surface points).
 */
#include <morphreg/warp/skeleton.h>

#include <string>

namespace morphreg
{
/** \brief Reads a skeleton file. Throws IoError for a missing file, FormatError naming the file and the bone for
 *  malformed JSON, a missing or non-string field or a twist that is not two joint names, and InvalidInputError naming
 *  the file for a skeleton that Skeleton refuses (duplicate bone names, a bone from a joint to itself, ...).
 *  \param[in] path the JSON file
 *  \return the skeleton
 */
Skeleton
loadSkeleton (const std::string& path);

/** \brief Writes \a skeleton in the layout above, atomically.
 *  \param[in] path the JSON file
 *  \param[in] skeleton the skeleton
 */
void
saveSkeleton (const std::string& path, const Skeleton& skeleton);

} // namespace morphreg

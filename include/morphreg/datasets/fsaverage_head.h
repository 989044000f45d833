// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file fsaverage_head.h
 *  \brief Import of MNE-Python's fsaverage scalp surface as exported to a folder holding
 *  fsaverage_head.ply and fsaverage_head_landmarks.json. The data is in metres; it is converted to millimetres
 *  on import. The frame stays FreeSurfer's MRI surface RAS (+x the subject's right, +y anterior, +z superior).
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/mesh/triangle_mesh.h>

#include <string>

namespace morphreg
{
/** \brief The fsaverage scalp (closed: a flat cap closes it below the head) and its fiducials, in mm. */
struct FsaverageHead
{
  TriangleMesh mesh; ///< the closed scalp, mm
  /** "nasion", and the preauricular points LPA / RPA under the nearest project ids (docs/landmarks.md):
   *  "left_tragus" / "right_tragus".
   */
  LandmarkPositions landmarks;
};

/** \brief Loads the scalp and fiducials from \a directory. Throws IoError if a file is missing or unreadable,
 *  FormatError naming the file if the JSON is malformed, its units are not metres or a fiducial is missing.
 *  \param[in] directory the folder with fsaverage_head.ply and fsaverage_head_landmarks.json
 *  \return the scalp and its landmarks in mm
 */

FsaverageHead
loadFsaverageHead (const std::string& directory);

} // namespace morphreg

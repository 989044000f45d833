// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file ict_facekit.h
 *  \brief Import of the ICT-FaceKit head model (ICT Face Model Light, head and neck part) as shipped in
 *  ../shared/data/ict_facekit: PLY mean, .npy orthonormal PCA basis and eigenvalues, JSON landmarks.
 *  The data is in centimetres; it is converted to millimetres on import (coordinates x10, variances x100).
 */
#include <morphreg/model/morphable_model.h>

#include <string>

namespace morphreg
{
/** \brief Loads the ICT head model from \a directory as a one-region (global PCA) MorphableModel in mm.
 *  Landmarks: the iBUG-68 points as "ibug68_00" .. "ibug68_67", the project ids of docs/landmarks.md that map to
 *  iBUG points, and the points ICT lacks, picked by geometry: left_tragus 7321, right_tragus 8048, nasion 1358.
 *  Profile line: the mid-sagittal vertices (x = 0; the mesh is exactly symmetric), ordered from the front of the
 *  neck over the face and crown to the back of the neck.
 *  Throws IoError if a file is missing, FormatError naming the file and the problem if shapes, counts, values or
 *  indices are wrong.
 *  \param[in] directory the ICT-FaceKit folder
 *  \return the model
 */

MorphableModel::Ptr
loadIctFaceKit (const std::string& directory);

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file ict_facekit.h
 *  \brief Import of the ICT-FaceKit head model (ICT Face Model Light, face, head and neck: vertices [0, 11248) of
 *  ICT's 26,719) from either of two layouts: ICT-FaceKit's own, as its repository publishes it (FaceXModel/
 *  generic_neutral_mesh.obj, identity000.obj ..., vertex_indices.json), or a converted one (PLY mean, .npy
 *  orthonormal PCA basis and eigenvalues, JSON landmarks).
 *  The data is in centimetres; it is converted to millimetres on import (coordinates x10, variances x100).
 */
#include <morphreg/model/morphable_model.h>

#include <string>

namespace morphreg
{
/** \brief Loads the ICT head model from \a directory as a one-region (global PCA) MorphableModel in mm.
 *  ICT-FaceKit's layout (\a directory is a clone of the repository or its FaceXModel folder): the mean is
 *  generic_neutral_mesh.obj; ICT's identity modes are identityNNN.obj - generic_neutral_mesh.obj, each drawn with a
 *  standard normal weight (x = mean + sum_k c_k mode_k, c_k ~ N(0, 1)), so the model's orthonormal basis and variances
 *  are the eigenvectors and eigenvalues of sum_k mode_k mode_k^T over the kept vertices (computePca of the modes,
 *  variances times K - 1). Every identityNNN.obj found is used (at least two); the expression OBJs, when present, are
 *  not read (the model is of identity alone). Quads are split into (0, 1, 2) and (0, 2, 3). With all 100 identities
 *  this is the converted layout's model; the landmarks are vertex_indices.json's idx_to_landmark_verts.
 *  The converted layout is used when \a directory holds ict_head_mean.ply.
 *  Landmarks: the iBUG-68 points as "ibug68_00" .. "ibug68_67", the project ids of docs/landmarks.md that map to
 *  iBUG points, and the points ICT lacks, picked by geometry: left_tragus 7321, right_tragus 8048, nasion 1358.
 *  Profile line: the mid-sagittal vertices (x = 0; the mesh is exactly symmetric), ordered from the front of the
 *  neck over the face and crown to the back of the neck.
 *  Throws IoError if a file is missing (naming both layouts when neither is there), FormatError naming the file and
 *  the problem if shapes, counts, values or indices are wrong.
 *  \param[in] directory the ICT-FaceKit folder (either layout)
 *  \return the model
 */
MorphableModel::Ptr
loadIctFaceKit (const std::string& directory);

} // namespace morphreg

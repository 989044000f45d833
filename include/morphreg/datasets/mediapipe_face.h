// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file mediapipe_face.h
 *  \brief Import of MediaPipe's canonical face mesh (the canonical_face_model.obj of its repository,
 *  468 vertices, the vertex index is the Face Mesh landmark id). The file is in centimetres; it is converted to
 *  millimetres on import. Its axes already match the project's (+Y up, +Z forward, +X the subject's left).
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/mesh/triangle_mesh.h>

#include <string>

namespace morphreg
{
/** \brief The canonical face (front only, open) in mm, with the project landmark ids MediaPipe has. */
struct MediaPipeFace
{
  TriangleMesh mesh; ///< the 468-vertex canonical face, mm
  /** Vertex of each landmark of the MediaPipe column of docs/landmarks.md: eye corners, nose tip, mouth corners, chin,
   *  forehead.
   */
  LandmarkVertices landmarks;
};

/** \brief Loads the canonical face OBJ at \a path. Throws IoError if the file is missing or unreadable,
 *  FormatError naming the file if it is not a triangle mesh with the 468 Face Mesh vertices.
 *  \param[in] path the canonical face OBJ (cm)
 *  \return the face in mm and its landmark vertices
 */

MediaPipeFace
loadMediaPipeFace (const std::string& path);

} // namespace morphreg

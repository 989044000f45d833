// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file landmark_reference.h
 *  \brief The reference mesh of a resampling from landmarks alone (METHOD section 5): the template warped by a 3D thin
 *  plate spline that moves its landmark vertices onto the landmarks marked on the scan.
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/mesh/triangle_mesh.h>

#include <string>

namespace morphreg
{
/** \brief The template warped onto the scan's landmarks: a thin plate spline from the template's landmark vertices to
 *  the scan's positions of the same ids (those on one side only are ignored), applied to every template vertex.
 *  Throws InvalidInputError naming \a scan_landmarks_name when fewer than 5 ids are shared (a 3D spline needs 4
 *  points off one plane, and one more to bend), and the spline's error when the shared landmarks are degenerate
 *  (coplanar, coincident with different targets).
 *  \param[in] reference_template the template mesh (mm), e.g. a model's mean
 *  \param[in] template_landmarks the template's landmark vertices by id
 *  \param[in] scan_landmarks the landmarks marked on the scan (mm, the scan's frame)
 *  \param[in] scan_landmarks_name where \a scan_landmarks came from, for messages
 *  \param[in] regularization the spline's lambda (0 interpolates the landmarks)
 *  \return the warped template, same triangles
 */
TriangleMesh
landmarkReference (const TriangleMesh& reference_template, const LandmarkVertices& template_landmarks,
                   const LandmarkPositions& scan_landmarks, const std::string& scan_landmarks_name,
                   double regularization = 0.0);

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file frontal_texture.h
 *  \brief Per-vertex colours of a fitted head from its frontal photo: the orthographic projection of
 *  docs/method.md, "Texture" (thesis eq. 48-49), for the vertices the camera sees.
 */
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/photo/photo_normalisation.h>
#include <morphreg/io/rgb_image.h>
#include <morphreg/common/colour_map.h>

#include <vector>

namespace morphreg
{
/** \brief Vertex colours sampled from a photo; vertices the camera does not see are grey and flagged. */
struct VertexTexture
{
  VertexColours colours;     ///< 3 x N
  std::vector<bool> visible; ///< facing the camera, inside the image and not hidden behind other triangles

  /** \brief The number of visible vertices.
   *  \return how many flags in \a visible are true
   */
  int
  visibleCount () const;
};

/** \brief Projects \a image_mesh (the fitted head in the normalised frame, e.g. TwoViewFit::image_mesh) along Z into
 *  the frontal photo \a image (whose annotations gave \a frontal) and samples each visible vertex's colour
 *  bilinearly. A vertex is visible if its normal has a positive Z (it faces the camera), it projects into the image
 *  and no triangle lies more than \a depth_tolerance pixels in front of it there (a depth buffer of the mesh at the
 *  image's resolution). Throws InvalidInputError if the image size differs from the annotated one or the image is
 *  empty.
 *  \param[in] image_mesh the fitted head in the normalised photo frame
 *  \param[in] frontal the frontal photo's normalisation (size and nose tip)
 *  \param[in] image the frontal photo
 *  \param[in] depth_tolerance how far (pixels) a triangle may lie in front of a vertex that still counts as seen
 *  \return a colour and a visibility flag per vertex
 */
VertexTexture

frontalTexture (const TriangleMesh& image_mesh, const PhotoNormalisation& frontal, const RgbImage& image,
                double depth_tolerance = 2.0);
} // namespace morphreg

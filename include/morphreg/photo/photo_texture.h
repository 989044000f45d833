// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file photo_texture.h
 *  \brief Per-vertex colours of a fitted head from its photos (docs/method.md, "Texture"): each photo projected onto
 *  the vertices its camera sees, the photos blended by how squarely each vertex faces each camera.
 */
#include <morphreg/common/colour_map.h>
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/photo/photo_camera.h>
#include <morphreg/photo/photo_normalisation.h>
#include <morphreg/common/rgb_image.h>

#include <vector>

namespace morphreg
{
/** \brief Vertex colours sampled from photos; vertices no camera sees are grey and flagged. */
struct VertexTexture
{
  VertexColours colours;     ///< 3 x N
  std::vector<bool> visible; ///< seen by a camera: facing it, inside its image, not hidden behind other triangles

  /** \brief The number of visible vertices.
   *  \return how many flags in \a visible are true
   */
  int
  visibleCount () const;
};

/** \brief A photo and the camera that took it, for texturing. */
struct TexturePhoto
{
  PhotoCamera camera;    ///< maps the mesh's frame to the photo's pixels
  const RgbImage* image; ///< the photo (not owned)
};

/** \brief The colours of \a mesh (in the cameras' frame, e.g. PhotoFit::image_mesh) from \a photos. A vertex is seen
 *  by a camera if its normal faces the camera, it projects into the image and no triangle lies more than
 *  \a depth_tolerance pixels nearer the camera there (a depth buffer of the mesh at the image's resolution); its
 *  colour is the bilinear sample of each photo that sees it, weighted by the squared cosine between its normal and the
 *  direction to that camera (a photo seen at a grazing angle gives little). Throws InvalidInputError for an empty
 *  or inconsistent image.
 *  \param[in] mesh the fitted head in the cameras' frame
 *  \param[in] photos the photos and their cameras
 *  \param[in] depth_tolerance how far (pixels) a triangle may lie in front of a vertex that still counts as seen
 *  \return a colour and a visibility flag per vertex
 */
VertexTexture
blendedTexture (const TriangleMesh& mesh, const std::vector<TexturePhoto>& photos, double depth_tolerance = 2.0);

/** \brief The colours of \a image_mesh (the normalised frame of the orthographic pair) from the frontal photo
 *  \a image, whose annotations gave \a frontal: blendedTexture with the frontal photo's orthographic camera. Throws
 *  InvalidInputError if the image size differs from the annotated one.
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

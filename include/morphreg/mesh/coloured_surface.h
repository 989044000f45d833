// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file coloured_surface.h
 *  \brief A scan's surface with what colours it (per-point colours, or texture images at texture coordinates), and
 *  its colours sampled at other points: how the fitted and the resampled meshes take on the scan's colours.
 */
#include <morphreg/common/colour_map.h>
#include <morphreg/common/rgb_image.h>

#include <Eigen/Core>

#include <vector>

namespace morphreg
{
/** \brief A triangle mesh or a cloud (no triangles), in mm, with per-point colours, textures, both or neither.
 *
 *  Where a triangle has a texture, its colour at a point is the texture's at the interpolated texture coordinates,
 *  times the interpolated point colours if there are any (as glTF multiplies its base-colour texture and COLOR_0).
 */
struct ColouredSurface
{
  Eigen::Matrix3Xd points;           ///< the mesh's vertices or the cloud's points, mm
  Eigen::Matrix3Xi triangles;        ///< 0-based point indices; none for a cloud
  VertexColours colours;             ///< one colour per point, or none
  Eigen::Matrix2Xf corner_uv;        ///< texture coordinates of corner k of triangle t in column 3 t + k, or none
  std::vector<int> triangle_texture; ///< per triangle with corner_uv: its index in textures, -1 for none
  std::vector<RgbImage> textures;    ///< the images; u runs left to right, v top to bottom (glTF's convention)

  /** \brief Whether the surface has any colour: point colours or a textured triangle.
   *  \return true if sampleNearestColours() gives the scan's colours rather than none
   */
  bool
  hasColours () const;
};

/** \brief The colour of \a texture at texture coordinates \a uv (bilinear between pixel centres; coordinates outside
 *  [0, 1] repeat, glTF's default wrapping).
 *  \param[in] texture the image (not empty)
 *  \param[in] uv u from the left edge, v from the top edge, 1 the opposite edge
 *  \return the colour
 */
Rgb8
sampleTexture (const RgbImage& texture, const Eigen::Vector2f& uv);

/** \brief One colour per point of the surface: its point colour times its texture's colour at the texture
 *  coordinates of the first triangle corner at it (points on no textured triangle keep their point colour, or white).
 *  What a renderer that colours vertices shows. Throws InvalidInputError if the surface has no colours.
 *  \param[in] surface the coloured surface
 *  \return 3 x points colours
 */
VertexColours
pointColours (const ColouredSurface& surface);

/** \brief The colour of the surface point nearest to each query: for a mesh, the closest point on its triangles
 *  (colours and texture coordinates interpolated there), for a cloud the nearest point. Throws InvalidInputError if
 *  the surface has no colours, an invalid mesh, or a query is not finite.
 *  \param[in] surface the coloured scan, mm
 *  \param[in] queries the points to colour (e.g. a fitted mesh's vertices), mm, in the surface's frame
 *  \return one colour per query
 */
VertexColours
sampleNearestColours (const ColouredSurface& surface, const Eigen::Matrix3Xd& queries);

} // namespace morphreg

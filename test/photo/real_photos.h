// SPDX-License-Identifier: BSD-3-Clause
#pragma once
// Annotated photos of real meshes, made at test time, and the 3D score of a photo fit against the mesh they show.
// The profile photo's silhouette is what a person traces on a real photo: the outline of the head's orthographic
// projection from its left side, from the top of the head forwards over the face and down to the bottom of the
// picture (the chest and shoulders where the mesh has them), never the back of the head (hair hides it); hair on
// the crown can be added as an outward offset. The frontal landmarks are the projections of vertices picked on the
// mesh, with pixel noise.
#include <morphreg/common/landmarks.h>
#include <morphreg/mesh/triangle_locator.h>
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/photo/frontal_view.h>
#include <morphreg/photo/profile_view.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <random>
#include <vector>

namespace morphreg
{
namespace test
{
struct OutlinePhotoSettings
{
  double pixels_per_mm = 2.5;
  double landmark_noise = 1.0; ///< px
  double hair_thickness = 0.0; ///< mm added outwards to the outline above hair_from
  double hair_from = 60.0;     ///< mm above the nose tip
  int point_spacing = 4;       ///< px between kept outline points
  double trace_from = 1e9;     ///< mm above the nose tip where the person starts tracing (the hairline: below hair)
};

/** A binary image of \a mesh's orthographic projection onto (\a u_axis, Y), x = u, y = down, 1 px = 1 /
 *  pixels_per_mm mm, with \a origin (mm, in (u, y)) at pixel (margin, margin) of the top-left. */
struct ProjectionMask
{
  int width, height;
  std::vector<unsigned char> filled;
  Eigen::Vector2d origin; // (u_min, y_max) in mm
  double pixels_per_mm;

  bool
  at (int x, int y) const
  {
    return x >= 0 && y >= 0 && x < width && y < height && filled[static_cast<size_t> (y) * width + x];
  }

  Eigen::Vector2d
  toPixel (double u, double y) const
  {
    return {(u - origin.x ()) * pixels_per_mm + 2.0, (origin.y () - y) * pixels_per_mm + 2.0};
  }

  Eigen::Vector2d
  toMillimetres (const Eigen::Vector2d& pixel) const
  {
    return {origin.x () + (pixel.x () - 2.0) / pixels_per_mm, origin.y () - (pixel.y () - 2.0) / pixels_per_mm};
  }
};

inline ProjectionMask
projectionMask (const TriangleMesh& mesh, int u_axis, double pixels_per_mm)
{
  ProjectionMask mask;
  mask.pixels_per_mm = pixels_per_mm;
  mask.origin = {mesh.vertices.row (u_axis).minCoeff (), mesh.vertices.row (1).maxCoeff ()};
  const double u_span = mesh.vertices.row (u_axis).maxCoeff () - mask.origin.x ();
  const double y_span = mask.origin.y () - mesh.vertices.row (1).minCoeff ();
  mask.width = static_cast<int> (u_span * pixels_per_mm) + 5;
  mask.height = static_cast<int> (y_span * pixels_per_mm) + 5;
  mask.filled.assign (static_cast<size_t> (mask.width) * mask.height, 0);
  for (Eigen::Index t = 0; t < mesh.triangles.cols (); ++t) {
    Eigen::Vector2d p[3];
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d v = mesh.vertices.col (mesh.triangles (k, t));
      p[k] = mask.toPixel (v[u_axis], v.y ());
    }
    const Eigen::Vector2d low = p[0].cwiseMin (p[1]).cwiseMin (p[2]), high = p[0].cwiseMax (p[1]).cwiseMax (p[2]);
    const double area = (p[1] - p[0]).x () * (p[2] - p[0]).y () - (p[1] - p[0]).y () * (p[2] - p[0]).x ();
    for (int y = static_cast<int> (std::floor (low.y ())); y <= static_cast<int> (std::ceil (high.y ())); ++y)
      for (int x = static_cast<int> (std::floor (low.x ())); x <= static_cast<int> (std::ceil (high.x ())); ++x) {
        const Eigen::Vector2d q (x + 0.5, y + 0.5);
        bool inside = true;
        for (int k = 0; k < 3 && inside; ++k) {
          const Eigen::Vector2d a = p[k], b = p[(k + 1) % 3];
          const double cross = (b - a).x () * (q - a).y () - (b - a).y () * (q - a).x ();
          inside = (area >= 0.0 ? cross : -cross) >= -0.5 * (b - a).norm (); // half a pixel of slack
        }
        if (inside && x >= 0 && y >= 0 && x < mask.width && y < mask.height)
          mask.filled[static_cast<size_t> (y) * mask.width + x] = 1;
      }
  }
  return mask;
}

/** The outer boundary of \a mask (Moore neighbour tracing, clockwise on screen), from its topmost pixel. */
inline std::vector<Eigen::Vector2i>
traceOutline (const ProjectionMask& mask)
{
  Eigen::Vector2i start (-1, -1);
  for (int y = 0; y < mask.height && start.x () < 0; ++y)
    for (int x = 0; x < mask.width; ++x)
      if (mask.at (x, y)) {
        start = {x, y};
        break;
      }
  const Eigen::Vector2i directions[8] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
  std::vector<Eigen::Vector2i> outline{start};
  Eigen::Vector2i current = start;
  int from = 6; // we entered the start pixel from above
  for (int step = 0; step < 4 * (mask.width + mask.height) * 4; ++step) {
    bool moved = false;
    for (int k = 0; k < 8; ++k) {
      const int d = (from + 1 + k) % 8;
      const Eigen::Vector2i next = current + directions[d];
      if (mask.at (next.x (), next.y ())) {
        from = (d + 4) % 8;
        current = next;
        moved = true;
        break;
      }
    }
    if (!moved || current == start)
      break;
    outline.push_back (current);
  }
  return outline;
}

/** The two photos of \a mesh (mm, +Y up, +Z out of the face, +X the subject's left) with its landmark vertices. */
/** The nose tip's vertex among \a landmarks: by its own id, or as iBUG-68's point 30. */
inline int
noseTipVertex (const LandmarkVertices& landmarks)
{
  return landmarks.count ("nose_tip") ? landmarks.at ("nose_tip") : landmarks.at ("ibug68_30");
}

inline std::pair<ProfileView, FrontalView>
outlinePhotos (const TriangleMesh& mesh, const LandmarkVertices& landmarks, const OutlinePhotoSettings& settings,
               std::uint64_t seed)
{
  std::mt19937_64 rng (seed);
  std::normal_distribution<double> noise (0.0, settings.landmark_noise);
  const Eigen::Vector3d nose = mesh.vertices.col (noseTipVertex (landmarks));

  const ProjectionMask side = projectionMask (mesh, 2, settings.pixels_per_mm);
  const std::vector<Eigen::Vector2i> loop = traceOutline (side);
  // From the topmost pixel clockwise (towards +u, the face) to the lowest pixel: the front of the outline.
  size_t lowest = 0;
  for (size_t k = 0; k < loop.size (); ++k)
    if (loop[k].y () > loop[lowest].y ())
      lowest = k;
  std::vector<Eigen::Vector2d> silhouette;
  for (size_t k = 0; k <= lowest; k += static_cast<size_t> (settings.point_spacing)) {
    Eigen::Vector2d mm = side.toMillimetres (loop[k].cast<double> () + Eigen::Vector2d::Constant (0.5));
    if (mm.y () > nose.y () + settings.trace_from)
      continue;
    if (mm.y () > nose.y () + settings.hair_from && settings.hair_thickness > 0.0) {
      const Eigen::Vector2d centre (nose.z () - 90.0, nose.y () + settings.hair_from - 40.0);
      mm += settings.hair_thickness * (mm - centre).normalized ();
    }
    silhouette.push_back (side.toPixel (mm.x (), mm.y ()));
  }
  const Eigen::Vector2d profile_nose = side.toPixel (nose.z (), nose.y ()) + Eigen::Vector2d (noise (rng), noise (rng));

  const ProjectionMask front = projectionMask (mesh, 0, settings.pixels_per_mm);
  LandmarkPixels marked;
  for (const auto& [id, vertex] : landmarks) {
    const Eigen::Vector3d v = mesh.vertices.col (vertex);
    marked[id] = front.toPixel (v.x (), v.y ()) + Eigen::Vector2d (noise (rng), noise (rng));
  }
  // Both photos the same size: the fit needs the head at one size relative to the longer side.
  const int width = std::max (side.width, front.width), height = std::max (side.height, front.height);
  return {ProfileView (width, height, silhouette, profile_nose, "outline photo (profile)"),
          FrontalView (width, height, marked, "outline photo (frontal)")};
}

/** The similarity (Umeyama with scale) of \a from onto \a to. */
inline Eigen::Matrix4d
umeyamaSimilarity (const Eigen::Matrix3Xd& from, const Eigen::Matrix3Xd& to)
{
  return Eigen::umeyama (from, to, true);
}

/** \a fitted (model frame) aligned to \a source: a similarity from the landmark pairs, then 30 similarity ICP steps
 *  of the \a face vertices of the fit onto the closest points of \a source's surface. */
inline TriangleMesh
alignFitToSource (const TriangleMesh& fitted, const TriangleMesh& source,
                  const std::vector<std::pair<int, int>>& landmark_pairs, const std::vector<int>& face)
{
  Eigen::Matrix3Xd from (3, landmark_pairs.size ()), to (3, landmark_pairs.size ());
  for (size_t k = 0; k < landmark_pairs.size (); ++k) {
    from.col (static_cast<Eigen::Index> (k)) = fitted.vertices.col (landmark_pairs[k].first);
    to.col (static_cast<Eigen::Index> (k)) = source.vertices.col (landmark_pairs[k].second);
  }
  Eigen::Matrix4d pose = umeyamaSimilarity (from, to);
  const TriangleLocator locator (source);
  Eigen::Matrix3Xd face_points (3, static_cast<Eigen::Index> (face.size ()));
  for (size_t k = 0; k < face.size (); ++k)
    face_points.col (static_cast<Eigen::Index> (k)) = fitted.vertices.col (face[k]);
  for (int iteration = 0; iteration < 30; ++iteration) {
    const Eigen::Matrix3Xd posed =
        (pose.topLeftCorner<3, 3> () * face_points).colwise () + pose.topRightCorner<3, 1> ();
    Eigen::Matrix3Xd closest (3, posed.cols ());
    std::vector<double> distances (static_cast<size_t> (posed.cols ()));
    for (Eigen::Index i = 0; i < posed.cols (); ++i) {
      const auto hit = locator.closestPoint (posed.col (i));
      closest.col (i) = hit.point;
      distances[static_cast<size_t> (i)] = hit.on_boundary ? 1e9 : hit.distance;
    }
    std::vector<double> sorted = distances;
    std::nth_element (sorted.begin (), sorted.begin () + static_cast<long> (sorted.size () * 8 / 10), sorted.end ());
    const double limit = sorted[sorted.size () * 8 / 10];
    std::vector<Eigen::Index> kept;
    for (Eigen::Index i = 0; i < posed.cols (); ++i)
      if (distances[static_cast<size_t> (i)] <= limit)
        kept.push_back (i);
    Eigen::Matrix3Xd a (3, static_cast<Eigen::Index> (kept.size ())), b (3, static_cast<Eigen::Index> (kept.size ()));
    for (size_t k = 0; k < kept.size (); ++k) {
      a.col (static_cast<Eigen::Index> (k)) = face_points.col (kept[k]);
      b.col (static_cast<Eigen::Index> (k)) = closest.col (kept[k]);
    }
    pose = umeyamaSimilarity (a, b);
  }
  TriangleMesh aligned = fitted;
  aligned.vertices = (pose.topLeftCorner<3, 3> () * fitted.vertices).colwise () + pose.topRightCorner<3, 1> ();
  return aligned;
}

} // namespace test
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file global_alignment.h
 *  \brief A landmark-free start for MorphableICP from any rotation, on scans that hold more than the head
 *  (shoulders, a chair back, hair) or less (a face alone, one depth camera's view): the head is found as the
 *  strongest head-sized sphere of the scan, or for a one-view scan by laying the model's side facing the sensor onto
 *  the scan; the rotation by scoring a grid over all of SO(3) on distance transforms of the scan (and, for one view,
 *  of the model); and
 *  the best distinct poses are refined by a trimmed similarity ICP and scored again.
 */
#include <morphreg/mesh/triangle_mesh.h>

#include <Eigen/Core>

#include <optional>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief Settings of alignHeadGlobally. Lengths are relative to the model's size, so they hold for any model. */
struct GlobalAlignmentSettings
{
  double voxel_ratio = 0.05;      ///< the scan is thinned to one point per voxel of this share of the model's radius
  double min_radius_ratio = 0.6;  ///< smallest head sphere searched, relative to the model's own head sphere
  double max_radius_ratio = 1.6;  ///< largest head sphere searched, relative to the model's own head sphere
  int centre_candidates = 3;      ///< strongest distinct head spheres whose rotations are searched
  int rotation_directions = 256;  ///< directions of the model's up axis in the rotation grid (Fibonacci sphere)
  int rotation_twists = 24;       ///< rotations about the up axis per direction (24: 15 degree steps)
  int score_samples = 400;        ///< model surface samples (and scan points) scored per rotation on the transforms
  int rotations_per_anchor = 10;  ///< best distinct rotations kept per anchor (head sphere or centroid)
  int refined_poses = 24;         ///< of those, the best-scoring over all anchors refined by similarity ICP
  int refine_iterations = 30;     ///< similarity ICP iterations of the poses that are refined to the end
  int screen_iterations = 8;      ///< iterations every refined pose runs before only the best 3 go on
  double inlier_fraction = 0.7;   ///< share of the closest pairs kept in each similarity ICP step
  double truncation_ratio = 0.15; ///< distances are truncated at this share of the model's radius in the scores
  /** Where the sensor of a one-view scan stood (scan frame), e.g. a depth camera's origin: only the model surface
   *  facing it and within the scan's outline is expected on the scan, so a profile or a cropped face is not
   *  penalised for what it cannot show, and the model's facing side is also laid onto the scan directly (a face
   *  has no head sphere). Unset: the scan may show the head from every side. */
  std::optional<Eigen::Vector3d> viewpoint;
};

/** \brief The pose found by alignHeadGlobally, how sure it is and how it was chosen. */
struct GlobalAlignment
{
  Eigen::Matrix4d similarity = Eigen::Matrix4d::Identity (); ///< model frame -> scan frame, [sR | t]
  /** In [0, 1]: the share of the model's surface the scan covers at the pose (within a few voxels, normals
   *  agreeing) times how much better the pose scores than the best distinct alternative (1 - best / runner-up).
   */
  double confidence = 0.0;
  double coverage = 0.0;        ///< share of the model's surface samples with a scan point close by at the pose
  double score = 0.0;           ///< truncated mean distance (mm) of the model's surface samples to the scan
  double runner_up_score = 0.0; ///< the same for the best pose at least 30 degrees away (0 if there is none)
  Eigen::Vector3d head_centre = Eigen::Vector3d::Zero (); ///< centre of the head sphere that won (scan frame)
  double head_radius = 0.0;                               ///< its radius (mm)
  int rotations_scored = 0;                               ///< rotations scored on the distance transforms
  int poses_refined = 0;                                  ///< poses refined by similarity ICP
  std::vector<int> head_indices; ///< scan points near the aligned model: the head; the rest are outliers to the fit
  std::string method;            ///< a sentence saying how the pose was chosen (for reports)
};

/** \brief Finds the similarity mapping \a model_mean (the model's mean mesh, mm) onto its head in \a scan (3 x N,
 *  mm) from any rotation, without landmarks. \a scan_normals (3 x N) may be empty or hold non-finite columns:
 *  those normals are estimated from the neighbourhood (their sign does not matter).
 *  1. The scan is thinned to one point per voxel and isolated points (hair strands, spray) are dropped.
 *  2. Every point votes, along its normal in both directions and over a range of radii, for the centre of a
 *     sphere it may lie on; the strongest distinct peaks are head candidates (the cranium is the scan's most
 *     sphere-like part: shoulders and planes spread their votes), and the same vote on the model's mean gives the
 *     model's head sphere. The radii's ratio is the first scale.
 *  3. For each candidate, the rotations of a grid over SO(3) about the matched sphere centres are scored by the
 *     truncated mean distance of model samples to the scan (a distance transform of the scan); for a one-view scan
 *     averaged with that of the scan points about the candidate to the model (a distance transform of the model, in
 *     its frame), so that a face is not taken for a smaller, smoother part of the head that leaves its nose and chin
 *     out (around a whole head, the shoulders, a chair and hair would weigh in that half).
 *  4. With settings.viewpoint (one view), per grid rotation and at 0.8 to 1.2 times the model's size, the model's
 *     side facing the sensor is also laid onto the scan (its part within the scan's outline centred on the scan)
 *     and scored the same way, seeing only the model within the scan's outline.
 *  5. The best distinct poses over all anchors are refined by trimmed point-to-plane similarity ICP (of the model
 *     within the scan's outline, for one view); the pose with the lowest truncated distance (wrong normals count as
 *     far) and a scale within the searched radius range wins.
 *  Throws InvalidInputError for an invalid mesh, fewer than 10 scan points, non-finite points, normals of the
 *  wrong size or bad settings.
 *  \param[in] model_mean the model's mean mesh (mm), the shape searched for in the scan
 *  \param[in] scan the scan points (3 x N, mm)
 *  \param[in] scan_normals the scan normals (3 x N), or empty to estimate them
 *  \param[in] settings the search and refinement settings
 *  \return the pose (model frame to scan frame), its confidence and how it was chosen
 */
GlobalAlignment
alignHeadGlobally (const TriangleMesh& model_mean, const Eigen::Matrix3Xd& scan,
                   const Eigen::Matrix3Xd& scan_normals = Eigen::Matrix3Xd (),
                   const GlobalAlignmentSettings& settings = GlobalAlignmentSettings ());

} // namespace morphreg

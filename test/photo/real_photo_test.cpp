// SPDX-License-Identifier: BSD-3-Clause
// Photo fitting on photos of real meshes (made at test time): MediaPipe's canonical face (landmarks: its documented
// ids), the real head scan (landmark vertices picked on renders: annotations/leeperrysmith_head_landmarks.json) and
// james's face-only capture (its 68 landmarks), photographed as real_photos.h describes (frontal and profile) or by
// two perspective cameras 25 degrees to either side; james's two real photos; each scored in 3D against the mesh the photos show (the fit aligned
// by the landmark vertices and a similarity ICP of ICT's narrow face, then the face median of the mesh's area samples
// to the fit), with the model's mean head aligned and scored the same way as the baseline.
#include "real_photos.h"
#include "../real_scans/real_scan_support.h"
#include "support/accuracy_bound.h"

#include <morphreg/io/json_file.h>
#include <morphreg/io/landmark_io.h>
#include <morphreg/datasets/mediapipe_face.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/photo/photo_camera_io.h>
#include <morphreg/photo/photo_fitting.h>
#include <morphreg/registration/surface_distance.h>

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>

namespace
{
using namespace morphreg;
using namespace morphreg::test;

/** Face median (mm) of \a fitted (model frame) against \a source after the landmark and face-ICP alignment. */
double
faceMedian (const TriangleMesh& fitted, const TriangleMesh& source, const LandmarkVertices& source_landmarks,
            const MorphableModel& model)
{
  std::vector<std::pair<int, int>> pairs;
  for (const auto& [id, vertex] : source_landmarks)
    pairs.emplace_back (model.landmarkVertex (id), vertex);
  std::vector<int> face;
  for (int v = 0; v < 6706; ++v) // ICT's narrow face: what a face-only mesh covers
    face.push_back (v);
  const TriangleMesh aligned = alignFitToSource (fitted, source, pairs, face);
  std::vector<bool> face_triangles (static_cast<size_t> (model.triangles ().cols ()));
  for (Eigen::Index t = 0; t < model.triangles ().cols (); ++t)
    face_triangles[static_cast<size_t> (t)] = (model.triangles ().col (t).array () < 9409).all ();
  return surfaceDistanceOver (surfaceDistance (source, aligned), face_triangles).median;
}

/** The model's mean head (no component). */
TriangleMesh
meanHead (const MorphableModel& model)
{
  return model.generateMesh (Eigen::VectorXd::Zero (0),
                             ComponentSelection (std::vector<int> (static_cast<size_t> (model.numRegions ()), 0)));
}

/** A bound on a fit's face median as a ratio to the mean head's; \a beats_mean_head false for a case where the fit
 *  is known to be no better than the mean head (the bound then only guards against it getting worse). */
struct RatioBound
{
  double ratio;
  bool beats_mean_head = true;
};

/** Fits the three approaches to photos of \a mesh (its \a landmarks) and checks each against the mean head's face
 *  median; \a bounds are the largest ratios to the mean head allowed (joint, TPS-ICP, profile), each within 1.3x of
 *  the fit's ratio, and the mean head, scored the same way, fails them. */
void
fitAndScore (const char* name, const TriangleMesh& mesh, const LandmarkVertices& landmarks,
             const std::array<RatioBound, 3>& bounds, const OutlinePhotoSettings& settings = OutlinePhotoSettings ())
{
  const auto photos = outlinePhotos (mesh, landmarks, settings, 3);
  const MorphableModel::ConstPtr& model = ictModel30 ();
  const TriangleMesh mean = meanHead (*model);
  const double baseline = faceMedian (mean, mesh, landmarks, *model);
  std::printf ("[ real photo ] %s: %zu silhouette points; the mean head %.3f mm\n", name,
               photos.first.silhouette ().size (), baseline);
  PhotoFitting fitting (model);
  const char* approaches[] = {"joint", "tps", "profile"};
  for (int a = 0; a < 3; ++a) {
    const std::string approach = approaches[a];
    const PhotoFit fit = fitting.fit (orthographicPairViews (photos.first, &photos.second), approach);
    const double median = faceMedian (fit.model_mesh, mesh, landmarks, *model);
    std::printf ("[ real photo ] %s %s (returned %s): face median %.3f mm = %.2f x the mean head; largest "
                 "coefficient %.2f sigma; profile RMS %.2f mm, landmark RMS %.2f mm\n",
                 name, approach.c_str (), fit.returned.c_str (), median, median / baseline, fit.maxCoefficientSigma (),
                 fit.final_residuals.outline_rms, fit.final_residuals.landmark_rms);
    std::printf (
        "[ real photo ]   lambda_2 %.3f (%s, noise %.3f), beats mean head %d, shape distance %.2f, plausible %d\n",
        fit.prior.weight, fit.prior.rule.c_str (), fit.prior.noise_weight, fit.prior.beats_mean_head,
        fit.shapeDistance (), isPlausibleShape (fit.coefficients));
    const RatioBound& bound = bounds[static_cast<size_t> (a)];
    EXPECT_PRED_FORMAT2 (tightUpperBound, median, bound.ratio * baseline) << name << " " << approach;
    if (bound.beats_mean_head)
      EXPECT_PRED_FORMAT2 (noOpFailsUpperBound, baseline, bound.ratio * baseline) << name << " " << approach;
    EXPECT_LE (fit.maxCoefficientSigma (), PhotoFitting::kDefaultCoefficientLimit + 1e-9) << name << " " << approach;
  }
}

TEST (RealPhotoTest, MediaPipeFace)
{
  const std::string path = sharedDataPath ("mediapipe_canonical_face/canonical_face_model.obj");
  if (!ictAvailable () || !std::filesystem::exists (path))
    GTEST_SKIP () << "ICT-FaceKit or MediaPipe's face not found in " << MORPHREG_SHARED_DATA_DIR;
  const MediaPipeFace face = loadMediaPipeFace (path);
  LandmarkVertices landmarks;
  for (const char* id : {"right_eye_outer", "right_eye_inner", "left_eye_inner", "left_eye_outer", "nose_tip",
                         "right_mouth_corner", "left_mouth_corner", "chin"})
    landmarks[id] = face.landmarks.at (id);
  // At the defaults the fits reach joint 0.85x, TPS-ICP 0.83x, profile 0.86x the mean head (0.824 mm). With a fixed
  // lambda_2 0.3 they reached 0.69x, 0.61x, 0.69x: the prior chosen by leaving out runs of MediaPipe's 7 fixed
  // landmarks (an eye and a mouth corner at a time) is 10 times the noise weight, stronger than this face needs.
  fitAndScore ("MediaPipe", face.mesh, landmarks, {{{0.9}, {0.9}, {0.9}}});
}

/** Photos of the real head scan with hair 12 mm thick on everything 60 mm above the nose tip, traced around the hair
 *  or, when \a from_hairline, from the hairline down. */
OutlinePhotoSettings
hairSettings (bool from_hairline)
{
  OutlinePhotoSettings hair;
  hair.hair_thickness = 12.0;
  if (from_hairline)
    hair.trace_from = hair.hair_from;
  return hair;
}

// The three photo sets of the real head scan are three tests, so that ctest -j balances them.
TEST (RealPhotoTest, RealHeadScan)
{
  if (!realScanDataAvailable ())
    GTEST_SKIP () << "the real head scan or ICT-FaceKit is not in " << MORPHREG_SHARED_DATA_DIR;
  // The silhouette runs from the crown over the face down the chest (the scan's shoulders). At the defaults the
  // mean head is at 3.28 mm; joint reaches 0.67x, TPS-ICP 0.62x, profile 0.67x.
  fitAndScore ("Lee Perry-Smith", leeHeadMesh (), leeLandmarks (), {{{0.7}, {0.75}, {0.85}}});
}

TEST (RealPhotoTest, RealHeadScanWithHairInTheOutline)
{
  if (!realScanDataAvailable ())
    GTEST_SKIP () << "the real head scan or ICT-FaceKit is not in " << MORPHREG_SHARED_DATA_DIR;
  // With the hair the outline is the head's outer bound above the forehead (one-sided rows where it leaves the fitted
  // skull): the fits reach joint 0.62x, TPS-ICP 0.64x, profile 0.71x (with the hair taken for the skull they were
  // 0.85x, 0.82x, 1.02x); issue 34's targets, 0.75x for joint and TPS-ICP and 0.9x for the profile, are the bounds.
  // TPS-ICP was at 0.83x while its warp guided the skull under the hair as much as the face (warpTrust).
  fitAndScore ("Lee Perry-Smith with hair", leeHeadMesh (), leeLandmarks (), {{{0.75}, {0.75}, {0.9}}},
               hairSettings (false));
}

TEST (RealPhotoTest, RealHeadScanTracedFromTheHairline)
{
  if (!realScanDataAvailable ())
    GTEST_SKIP () << "the real head scan or ICT-FaceKit is not in " << MORPHREG_SHARED_DATA_DIR;
  // The photo with hair traced from the hairline down: 0.55x, 0.57x, 0.78x.
  fitAndScore ("Lee Perry-Smith from the hairline", leeHeadMesh (), leeLandmarks (), {{{0.65}, {0.7}, {0.8}}},
               hairSettings (true));
}

/** The iBUG-68 number of each point of james's landmark files, in the order of james.ljson (menpo's groups: chin,
 *  leye, reye, leyebrow, nose, reyebrow, mouth; not iBUG-68's order, which the files' ibug68_* ids and the data
 *  README assume): each group's points map in order onto its iBUG-68 range. */
std::vector<int>
jamesIbugNumbers ()
{
  const std::map<std::string, int> starts = {{"chin", 0},  {"leyebrow", 17}, {"reyebrow", 22}, {"nose", 27},
                                             {"leye", 36}, {"reye", 42},     {"mouth", 48}};
  std::vector<int> numbers (68, -1);
  const nlohmann::json groups = readJsonFile (realScanPath ("menpo3d_james/james.ljson")).at ("groups").at ("LJSON");
  for (const nlohmann::json& label : groups.at ("labels")) {
    const std::vector<int> mask = label.at ("mask").get<std::vector<int>> ();
    for (size_t k = 0; k < mask.size (); ++k)
      numbers.at (static_cast<size_t> (mask[k])) =
          starts.at (label.at ("label").get<std::string> ()) + static_cast<int> (k);
  }
  return numbers;
}

/** The 68 landmarks of one of james's photos (the CSV of u, v in james.ljson's order), as ibug68_* pixels. */
LandmarkPixels
jamesPixels (const std::string& csv_path)
{
  const std::vector<int> numbers = jamesIbugNumbers ();
  std::ifstream csv (csv_path);
  LandmarkPixels pixels;
  size_t k = 0;
  for (std::string line; std::getline (csv, line);)
    if (!line.empty () && line.front () != '#')
      pixels[ibug68LandmarkId (numbers.at (k++))] =
          Eigen::Vector2d (std::stod (line), std::stod (line.substr (line.find (',') + 1)));
  return pixels;
}

/** james's two real photos (about 25 degrees to either side, perspective), each with its 68 landmarks and, when
 *  \a cameras, the camera recovered with the scan. */
std::vector<PhotoView>
jamesViews (bool cameras)
{
  std::vector<PhotoView> views;
  for (const char* side : {"left", "right"}) {
    const std::string image = realScanPath (std::string ("menpo3d_james/james_photo_") + side + ".jpg");
    PhotoView view (1200, 1600,
                    jamesPixels (realScanPath (std::string ("menpo3d_james/james_photo_") + side + "_landmarks68.csv")),
                    image);
    if (cameras)
      view.setCamera (loadPhotoCamera (realScanPath ("menpo3d_james/james_cameras.json"), image, 1200, 1600));
    views.push_back (std::move (view));
  }
  return views;
}

/** james's scan's landmark vertices: the vertex of \a scan nearest each of its 68 landmarks (1.4 mm median, README),
 *  by their iBUG-68 ids. */
LandmarkVertices
jamesLandmarkVertices (const TriangleMesh& scan)
{
  LandmarkVertices landmarks;
  const std::vector<int> numbers = jamesIbugNumbers ();
  for (const auto& [id, position] : loadLandmarks (realScanPath ("menpo3d_james/james_landmarks.json"))) {
    Eigen::Index nearest = 0;
    (scan.vertices.colwise () - position).colwise ().squaredNorm ().minCoeff (&nearest);
    landmarks[ibug68LandmarkId (numbers.at (static_cast<size_t> (std::stoi (id.substr (7)))))] =
        static_cast<int> (nearest);
  }
  return landmarks;
}

/** Fits the joint approach to james's two real photos, with their recovered cameras when \a given or cameras
 *  estimated from the landmarks otherwise, and scores it against james's scan. */
void
fitJamesPhotos (bool given)
{
  const TriangleMesh scan = loadTriangleMesh (realScanPath ("menpo3d_james/james.obj"));
  const LandmarkVertices landmarks = jamesLandmarkVertices (scan);
  const MorphableModel::ConstPtr& model = ictModel30 ();
  const TriangleMesh mean = meanHead (*model);
  const double baseline = faceMedian (mean, scan, landmarks, *model);
  PhotoFitting fitting (model);
  // Issue 34's targets: <= 0.8x the mean head with the given cameras (measured 0.79x: 2.12 mm against 2.69 mm),
  // <= 0.85x with the cameras estimated from the landmarks on the mean head (measured 0.84x; the focal lengths found,
  // 1770 and 8101 px against the true 6300 and 6500, are loosely fixed by a face seen from 1.4 m).
  const PhotoFit fit = fitting.fit (jamesViews (given), "joint");
  const double median = faceMedian (fit.model_mesh, scan, landmarks, *model);
  std::printf ("[ real photo ] james, cameras %s: face median %.3f mm = %.2f x the mean head (%.3f mm); landmark "
               "RMS %.2f mm; lambda_2 %.3f (%s); largest coefficient %.2f sigma; focal %.0f / %.0f px\n",
               given ? "given" : "estimated", median, median / baseline, baseline, fit.final_residuals.landmark_rms,
               fit.prior.weight, fit.prior.rule.c_str (), fit.maxCoefficientSigma (),
               fit.views[0].camera.intrinsics () (0, 0), fit.views[1].camera.intrinsics () (0, 0));
  std::printf ("[ real photo ]   scale %.4f, %zu iterations, landmark RMS %.2f -> %.2f mm, outline landmarks %d "
               "(RMS %.2f mm), camera RMS %.2f / %.2f px\n",
               fit.scale, fit.history.size (), fit.history.front ().landmark_rms, fit.final_residuals.landmark_rms,
               fit.final_residuals.outline_landmarks, fit.final_residuals.outline_landmark_rms,
               fit.views[0].camera_rms_pixels, fit.views[1].camera_rms_pixels);
  for (const PriorCandidate& candidate : fit.prior.candidates)
    std::printf ("[ real photo ]   lambda_2 %.3f: left-out landmarks %.3f mm\n", candidate.weight, candidate.error_mm);
  std::printf ("[ real photo ]   the mean head: left-out landmarks %.3f mm\n", fit.prior.mean_head_error_mm);
  EXPECT_EQ (fit.views[0].camera_estimated, !given);
  EXPECT_TRUE (isPlausibleShape (fit.coefficients)) << given;
  const double bound = given ? 0.8 : 0.85;
  EXPECT_PRED_FORMAT2 (tightUpperBound, median, bound * baseline) << "cameras given " << given;
  EXPECT_PRED_FORMAT2 (noOpFailsUpperBound, baseline, bound * baseline) << "cameras given " << given;
}

bool
jamesPhotosAvailable ()
{
  return ictAvailable () && std::filesystem::exists (realScanPath ("menpo3d_james/james_cameras.json"));
}

// Given and estimated cameras are two tests, so that ctest -j balances them.
TEST (RealPhotoTest, JamesTwoRealPhotosWithTheirCameras)
{
  if (!jamesPhotosAvailable ())
    GTEST_SKIP () << "menpo3d_james or ICT-FaceKit is not in " << MORPHREG_SHARED_DATA_DIR;
  fitJamesPhotos (true);
}

TEST (RealPhotoTest, JamesTwoRealPhotosWithCamerasEstimated)
{
  if (!jamesPhotosAvailable ())
    GTEST_SKIP () << "menpo3d_james or ICT-FaceKit is not in " << MORPHREG_SHARED_DATA_DIR;
  fitJamesPhotos (false);
}

/** \a scan turned rigidly into the model's frame (upright, facing +Z) by its landmark vertices and the mean head's. */
TriangleMesh
inModelFrame (TriangleMesh scan, const LandmarkVertices& landmarks, const MorphableModel& model)
{
  const TriangleMesh mean = meanHead (model);
  Eigen::Matrix3Xd from (3, landmarks.size ()), to (3, landmarks.size ());
  Eigen::Index column = 0;
  for (const auto& [id, vertex] : landmarks) {
    from.col (column) = scan.vertices.col (vertex);
    to.col (column++) = mean.vertices.col (model.landmarkVertex (id));
  }
  const Eigen::Matrix4d rigid = Eigen::umeyama (from, to, false);
  scan.vertices = (rigid.topLeftCorner<3, 3> () * scan.vertices).colwise () + rigid.topRightCorner<3, 1> ();
  return scan;
}

/** james's face-only capture (open at the back) turned into the model's frame, and its 68 landmark vertices. */
std::pair<TriangleMesh, LandmarkVertices>
jamesScanInModelFrame ()
{
  const TriangleMesh scan = loadTriangleMesh (realScanPath ("menpo3d_james/james.obj"));
  LandmarkVertices landmarks = jamesLandmarkVertices (scan);
  return {inModelFrame (scan, landmarks, *ictModel30 ()), std::move (landmarks)};
}

// Photos rendered from james's capture as from the real head scan, its 68 landmarks marked with 1 px noise (the jaw
// and head contour among them, as outline landmarks). Measured: joint 0.51x, TPS-ICP 0.52x, profile 0.51x the mean
// head (2.687 mm).
TEST (RealPhotoTest, JamesScanRendered)
{
  if (!jamesPhotosAvailable ())
    GTEST_SKIP () << "menpo3d_james or ICT-FaceKit is not in " << MORPHREG_SHARED_DATA_DIR;
  const auto [scan, landmarks] = jamesScanInModelFrame ();
  fitAndScore ("james rendered", scan, landmarks, {{{0.65}, {0.65}, {0.65}}});
}

// The same with hair 12 mm thick above the forehead in the outline (traced around it): joint 0.65x (its largest
// coefficient at the 3-sigma limit), TPS-ICP 0.56x, profile 0.54x.
TEST (RealPhotoTest, JamesScanRenderedWithHairInTheOutline)
{
  if (!jamesPhotosAvailable ())
    GTEST_SKIP () << "menpo3d_james or ICT-FaceKit is not in " << MORPHREG_SHARED_DATA_DIR;
  const auto [scan, landmarks] = jamesScanInModelFrame ();
  fitAndScore ("james rendered with hair", scan, landmarks, {{{0.75}, {0.7}, {0.7}}}, hairSettings (false));
}

/** Two perspective photos (1200 x 1600 px, focal length 4000 px, the nose tip 1 m from the camera: a portrait lens)
 *  of \a mesh (model frame) turned \a yaw degrees to either side, each landmark vertex marked where it projects with
 *  1 px noise (the jaw and head contour's are outline landmarks, which hold where the surface turns away); with
 *  their cameras when \a cameras, else the fit estimates them. */
std::vector<PhotoView>
obliqueViews (const TriangleMesh& mesh, const LandmarkVertices& landmarks, double yaw, bool cameras)
{
  std::mt19937_64 rng (7);
  std::normal_distribution<double> noise (0.0, 1.0);
  const Eigen::Vector3d nose = mesh.vertices.col (noseTipVertex (landmarks));
  Eigen::Matrix3d K;
  K << 4000.0, 0.0, 600.0, 0.0, 4000.0, 800.0, 0.0, 0.0, 1.0;
  std::vector<PhotoView> views;
  for (const double side : {-1.0, 1.0}) {
    // Facing the camera is X right, Y down, Z away in the camera's frame: (x, -y, -z) of the head's.
    const Eigen::Matrix3d R =
        Eigen::Vector3d (1.0, -1.0, -1.0).asDiagonal () *
        Eigen::AngleAxisd (side * yaw * M_PI / 180.0, Eigen::Vector3d::UnitY ()).toRotationMatrix ();
    const PhotoCamera camera =
        PhotoCamera::perspective (K, R, Eigen::Vector3d (0.0, 0.0, 1000.0) - R * nose, "rendered");
    LandmarkPixels marked;
    for (const auto& [id, vertex] : landmarks)
      marked[id] = camera.project (mesh.vertices.col (vertex)) + Eigen::Vector2d (noise (rng), noise (rng));
    PhotoView view (1200, 1600, marked, side < 0 ? "rendered photo (left)" : "rendered photo (right)");
    if (cameras)
      view.setCamera (camera);
    views.push_back (std::move (view));
  }
  return views;
}

/** Fits the joint approach to the oblique pair of \a mesh, with the cameras given and estimated, and checks each
 *  against the mean head's face median: at most \a bounds (given, estimated) times it. */
void
fitObliqueAndScore (const char* name, const TriangleMesh& mesh, const LandmarkVertices& landmarks,
                    const std::array<RatioBound, 2>& bounds)
{
  const MorphableModel::ConstPtr& model = ictModel30 ();
  const TriangleMesh mean = meanHead (*model);
  const double baseline = faceMedian (mean, mesh, landmarks, *model);
  PhotoFitting fitting (model);
  for (const bool given : {true, false}) {
    const PhotoFit fit = fitting.fit (obliqueViews (mesh, landmarks, 25.0, given), "joint");
    const double median = faceMedian (fit.model_mesh, mesh, landmarks, *model);
    std::printf ("[ real photo ] %s, 25 degrees to either side, cameras %s: face median %.3f mm = %.2f x the mean "
                 "head (%.3f mm); landmark RMS %.2f mm; largest coefficient %.2f sigma; focal %.0f / %.0f px\n",
                 name, given ? "given" : "estimated", median, median / baseline, baseline,
                 fit.final_residuals.landmark_rms, fit.maxCoefficientSigma (), fit.views[0].camera.intrinsics () (0, 0),
                 fit.views[1].camera.intrinsics () (0, 0));
    std::printf ("[ real photo ]   lambda_2 %.3f (%s), beats mean head %d, left-out landmarks %.3f mm (the mean "
                 "head %.3f mm)\n",
                 fit.prior.weight, fit.prior.rule.c_str (), fit.prior.beats_mean_head,
                 fit.prior.candidates.empty () ? 0.0 : fit.prior.candidates.front ().error_mm,
                 fit.prior.mean_head_error_mm);
    for (const PriorCandidate& candidate : fit.prior.candidates)
      std::printf ("[ real photo ]   lambda_2 %.3f: left-out landmarks %.3f mm\n", candidate.weight,
                   candidate.error_mm);
    const RatioBound& bound = bounds[given ? 0 : 1];
    EXPECT_TRUE (isPlausibleShape (fit.coefficients)) << name << ", cameras given " << given;
    EXPECT_PRED_FORMAT2 (tightUpperBound, median, bound.ratio * baseline) << name << ", cameras given " << given;
    if (bound.beats_mean_head)
      EXPECT_PRED_FORMAT2 (noOpFailsUpperBound, baseline, bound.ratio * baseline)
          << name << ", cameras given " << given;
  }
}

// The real head scan's 8 landmarks (eye and mouth corners, nose tip, chin) without an outline do not beat the mean
// head: 1.02x with the cameras given, 1.00x estimated; the left-out landmarks choose the weakest prior (0.275) and
// predict them to 3.9 mm against the mean head's 4.4 mm, but 32 image coordinates say little of a face's shape in a
// model of 7 x 30 components (a sample of the model itself, its 8 landmark vertices projected the same way, fits to
// 1.10x and 1.41x; with all 96 of the model's landmarks pinned, 0.74x and 0.94x). The frontal and profile pair's
// outline is what carries the shape. The bound keeps the fit from getting worse than the mean head.
TEST (RealPhotoTest, RealHeadScanObliquePerspectivePair)
{
  if (!realScanDataAvailable ())
    GTEST_SKIP () << "the real head scan or ICT-FaceKit is not in " << MORPHREG_SHARED_DATA_DIR;
  fitObliqueAndScore ("Lee Perry-Smith", leeHeadMesh (), leeLandmarks (), {{{1.05, false}, {1.05, false}}});
}

TEST (RealPhotoTest, JamesScanObliquePerspectivePair)
{
  if (!jamesPhotosAvailable ())
    GTEST_SKIP () << "menpo3d_james or ICT-FaceKit is not in " << MORPHREG_SHARED_DATA_DIR;
  const auto [scan, landmarks] = jamesScanInModelFrame ();
  // 68 landmarks: 0.77x with the cameras given, 0.81x estimated (focal lengths 3481 and 1441 px against 4000).
  fitObliqueAndScore ("james", scan, landmarks, {{{0.8}, {0.85}}});
}

bool
demofaceAvailable ()
{
  return ictAvailable () && std::filesystem::exists (realScanPath ("meshmonk_demoface/demoface_10k.obj"));
}

/** demoface's capture (head, neck, collar, spiky hair, open at the back) turned into the model's frame, and its
 *  landmark vertices (annotations/demoface_landmarks.json: placed by a fit, its "how" says). */
std::pair<TriangleMesh, LandmarkVertices>
demofaceInModelFrame ()
{
  const TriangleMesh scan = loadTriangleMesh (realScanPath ("meshmonk_demoface/demoface_10k.obj"));
  LandmarkVertices landmarks = annotatedLandmarks ("demoface_landmarks.json");
  return {inModelFrame (scan, landmarks, *ictModel30 ()), std::move (landmarks)};
}

// Photos rendered from demoface's capture: its profile outline runs around the capture's own spiky hair artefacts,
// traced as they are, and also with 12 mm of hair added above the forehead. Measured: joint 0.86x, TPS-ICP 0.86x,
// profile 0.86x the mean head (1.998 mm); with the hair 0.83x, 0.84x, 0.70x. Issue 34's 0.75x for joint and TPS-ICP
// is not met here: the left-out landmarks choose the strongest prior (lambda_2 11: its left-out error 1.45 mm, the
// mean head's 1.67 mm, the weakest prior's 2.08 mm), so the shape stays near the mean head (largest coefficient 0.6
// sigma) and the outline RMS is 2.5 mm (0.5 mm on the other scans). With lambda_2 fixed at 1.1 or 3.7 the same photos
// reach 0.68x and 0.66x: 8 landmarks validate the prior poorly where the outline carries the shape; holding out runs
// of the outline as well is the next step (issue 34, item 3).
TEST (RealPhotoTest, DemofaceScanRendered)
{
  if (!demofaceAvailable ())
    GTEST_SKIP () << "meshmonk_demoface or ICT-FaceKit is not in " << MORPHREG_SHARED_DATA_DIR;
  const auto [scan, landmarks] = demofaceInModelFrame ();
  fitAndScore ("demoface rendered", scan, landmarks, {{{0.9}, {0.9}, {0.9}}});
  fitAndScore ("demoface rendered with hair", scan, landmarks, {{{0.9}, {0.9}, {0.75}}}, hairSettings (false));
}

TEST (RealPhotoTest, DemofaceScanObliquePerspectivePair)
{
  if (!demofaceAvailable ())
    GTEST_SKIP () << "meshmonk_demoface or ICT-FaceKit is not in " << MORPHREG_SHARED_DATA_DIR;
  const auto [scan, landmarks] = demofaceInModelFrame ();
  // Its 8 landmarks as on the real head scan: 0.91x with the cameras given, 0.98x estimated.
  fitObliqueAndScore ("demoface", scan, landmarks, {{{0.95}, {1.05, false}}});
}
} // namespace

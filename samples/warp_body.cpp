// SPDX-License-Identifier: BSD-3-Clause
// The thin plate spline use cases of the seed paper on the MakeHuman bodies (three subjects, standing and seated,
// one vertex numbering; ../shared/data/makehuman_bodies, read in mm):
//  - re-posturing: each standing body warped to its seated pose on the 51 major joint centres (plus, with
//    --surface, 16 surface vertices) by (a) one global TPS, (b) hard segmentation into the four body segments,
//    (c) segments with seams blended over --blend mm along the body, and (d) rigid bones (ArticulatedWarp: the
//    joints move MakeHuman's skeleton, the surface vertices pin the refinement);
//  - between subjects: the base body warped onto each other subject's 326 joints (global, and blended segments:
//    the trunk on every joint, each arm on its own).
// Prints each warp's mean / max vertex error against the true mesh and the seam figures, and writes every warped
// body to OUT_DIR as PLY coloured by vertex error (viridis, 0-30 mm).
//
//   sample_warp_body BODIES_DIR [--out warp_body] [--subject NAME] [--blend 100] [--surface]
#include "sample_options.h"

#include <morphreg/datasets/makehuman_bodies.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/warp/articulated_warp.h>
#include <morphreg/warp/segmented_warp.h>
#include <morphreg/warp/warp_quality.h>
#include <morphreg/common/colour_map.h>

#include <cstdio>
#include <filesystem>
#include <limits>

using morphreg::BodyPose;
using morphreg::TriangleMesh;

namespace
{
const char* const kUsage = "usage: sample_warp_body BODIES_DIR [--out DIR] [--subject NAME] [--blend MM] [--surface]\n"
                           "  BODIES_DIR: ../shared/data/makehuman_bodies\n";

/** One warp problem: a body, where its landmarks are and where they should go, and the true result. */
struct WarpCase
{
  std::string name, file_stem;
  TriangleMesh source, truth;
  Eigen::Matrix3Xd from, to;
};

/** Prints the quality of \a warped against the truth and writes it coloured by vertex error. */
void
report (const morphreg::MakeHumanBodies& bodies, const WarpCase& c, const std::string& method,
        const TriangleMesh& warped, const std::string& out)
{
  const morphreg::WarpQuality q = morphreg::evaluateWarp (warped, c.truth, bodies.segmentLabels (), 100.0, &c.source);
  std::printf ("%-42s %-8s mean %6.2f mm  max %6.1f mm  seam %.3f  band %.3f  folded near seams %d\n", c.name.c_str (),
               method.c_str (), q.mean_error, q.max_error, q.seam, q.band, q.folded_in_band);
  const Eigen::VectorXd error = (warped.vertices - c.truth.vertices).colwise ().norm ().transpose ();
  const std::string file = out + "/" + c.file_stem + "_" + method + ".ply";
  morphreg::savePolygonMesh (file, morphreg::toPolygonMesh (warped, morphreg::residualColours (error, 30.0)));
}

/** Warps \a c by one global TPS and by segments, hard (unless \a hard is false) and blended over \a blend mm. */
void
compareWarps (const morphreg::MakeHumanBodies& bodies, const WarpCase& c, const std::vector<double>& overlap,
              double blend, bool hard, const std::string& out)
{
  morphreg::ThinPlateSpline<double, 3> global;
  global.fit (c.from, c.to);
  report (bodies, c, "global", global.transformMesh (c.source), out);
  morphreg::SegmentedWarp segmented (bodies.segmentLabels (), static_cast<int> (bodies.segmentNames ().size ()));
  segmented.setLandmarks (c.source, c.from, c.to, overlap); // landmark subsets per segment, overlapping at borders
  if (hard)
    report (bodies, c, "hard", segmented.warp (c.source), out);
  segmented.setBlendWidth (blend);
  report (bodies, c, "blended", segmented.warp (c.source), out);
}

/** Re-postures \a subject with rigid bones from its major joints (and, if \a surface, pinned surface vertices). */
void
articulatedWarp (const morphreg::MakeHumanBodies& bodies, const WarpCase& c, const std::string& subject, bool surface,
                 const std::string& out)
{
  morphreg::ArticulatedWarp warp (morphreg::makeHumanSkeleton (), bodies.segmentLabels (), bodies.segmentNames ());
  warp.setJoints (bodies.namedJoints (subject, BodyPose::standing, bodies.majorJoints ()),
                  bodies.namedJoints (subject, BodyPose::seated, bodies.majorJoints ()));
  if (surface)
    warp.setSurfaceLandmarks (bodies.surfaceVertices (), c.truth.vertices (Eigen::all, bodies.surfaceVertices ()));
  report (bodies, c, "bones", warp.warp (c.source), out);
}

/** Appends the positions of \a vertices of \a mesh as extra landmark columns. */
Eigen::Matrix3Xd
withSurfacePoints (const Eigen::Matrix3Xd& joints, const TriangleMesh& mesh, const std::vector<int>& vertices)
{
  Eigen::Matrix3Xd points (3, joints.cols () + static_cast<Eigen::Index> (vertices.size ()));
  points << joints, mesh.vertices (Eigen::all, vertices);
  return points;
}

void
warpBodies (int argc, char** argv)
{
  const samples::Options options (argc, argv, {{"--out", "warp_body"}, {"--subject", ""}, {"--blend", "100"}},
                                  {"--surface"});
  if (options.positional ().size () != 1)
    throw samples::UsageError ("expected one BODIES_DIR");
  const morphreg::MakeHumanBodies bodies (options.positional ()[0]);
  const std::string out = options.text ("--out");
  std::filesystem::create_directories (out);
  const double blend = options.number ("--blend");
  const bool surface = options.flag ("--surface");
  // Each segment takes the landmarks within 90 mm of it; with surface points the bending lower body takes all.
  const double all = std::numeric_limits<double>::infinity ();
  const std::vector<double> overlap{90.0, 90.0, 90.0, surface ? all : 90.0};

  std::vector<std::string> subjects = bodies.subjects ();
  if (!options.text ("--subject").empty ())
    subjects = {options.text ("--subject")};
  for (const auto& subject : subjects) {
    WarpCase c{subject + " standing->seated",
               subject + "_seated",
               bodies.loadMesh (subject, BodyPose::standing),
               bodies.loadMesh (subject, BodyPose::seated),
               bodies.joints (subject, BodyPose::standing, bodies.majorJoints ()),
               bodies.joints (subject, BodyPose::seated, bodies.majorJoints ())};
    if (surface) {
      c.from = withSurfacePoints (c.from, c.source, bodies.surfaceVertices ());
      c.to = withSurfacePoints (c.to, c.truth, bodies.surfaceVertices ());
    }
    compareWarps (bodies, c, overlap, blend, true, out);
    articulatedWarp (bodies, c, subject, surface, out);
  }

  const std::vector<std::string> joints = bodies.jointNames ();
  for (const auto& subject : subjects) {
    if (subject == "base")
      continue;
    const WarpCase c{"base->" + subject + " (" + std::to_string (joints.size ()) + " joints)",
                     "base_to_" + subject,
                     bodies.loadMesh ("base", BodyPose::standing),
                     bodies.loadMesh (subject, BodyPose::standing),
                     bodies.joints ("base", BodyPose::standing, joints),
                     bodies.joints (subject, BodyPose::standing, joints)};
    // Between subjects the trunk segments follow every joint and each arm only its own (see the test).
    compareWarps (bodies, c, {0.0, 0.0, all, all}, blend, false, out);
  }
  std::printf ("wrote the warped bodies to %s/ (vertex colours: error 0-30 mm)\n", out.c_str ());
}
} // namespace

int
main (int argc, char** argv)
{
  return samples::run (argc, argv, kUsage, warpBodies);
}

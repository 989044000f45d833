// SPDX-License-Identifier: BSD-3-Clause
// A thin plate spline warps one synthetic head onto another head's landmarks (the built-in population, ids of
// docs/landmarks.md). Landmarks land exactly; between them the warped head stays as close to the source shape as the smoothest
// spline allows. Prints the mean / max vertex error against the other head before and after the warp and writes the
// warped head as PLY coloured by that error (viridis, 0-10 mm).
//
//   sample_warp_head [--out warped_head.ply] [--source 31] [--target 32]    (population seeds of the heads)
#include "sample_options.h"

#include <morphreg/io/mesh_io.h>
#include <morphreg/mesh/polygon_mesh_conversion.h>
#include <morphreg/warp/thin_plate_spline.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/common/colour_map.h>

#include <cstdio>

namespace
{
const char* const kUsage = "usage: sample_warp_head [--out warped_head.ply] [--source SEED] [--target SEED]\n";

/** Positions (3 x L) of the landmark vertices \a ids on \a mesh. */
Eigen::Matrix3Xd
landmarkPoints (const morphreg::TriangleMesh& mesh, const std::vector<int>& ids)
{
  return mesh.vertices (Eigen::all, ids);
}

void
printError (const char* what, const morphreg::TriangleMesh& mesh, const morphreg::TriangleMesh& truth)
{
  const Eigen::VectorXd error = (mesh.vertices - truth.vertices).colwise ().norm ();
  std::printf ("%s: mean %.3f mm, max %.3f mm\n", what, error.mean (), error.maxCoeff ());
}

void
warpHead (int argc, char** argv)
{
  const samples::Options options (argc, argv, {{"--out", "warped_head.ply"}, {"--source", "31"}, {"--target", "32"}});
  const morphreg::synthetic::HeadGenerator generator;
  const morphreg::TriangleMesh source = generator.sample (options.integer ("--source", 0)).mesh;
  const morphreg::TriangleMesh target = generator.sample (options.integer ("--target", 0)).mesh;
  std::vector<int> ids;
  for (const auto& landmark : generator.landmarks ())
    ids.push_back (landmark.second);

  morphreg::ThinPlateSpline<double, 3> tps; // U(r) = r, exact interpolation
  tps.fit (landmarkPoints (source, ids), landmarkPoints (target, ids));
  const morphreg::TriangleMesh warped = tps.transformMesh (source);
  const double landmark_miss =
      (landmarkPoints (warped, ids) - landmarkPoints (target, ids)).colwise ().norm ().maxCoeff ();
  std::printf ("%zu landmarks, bending energy %.4g, largest landmark miss %.2e mm\n", ids.size (), tps.bendingEnergy (),
               landmark_miss);
  printError ("source head vs target head", source, target);
  printError ("warped head vs target head", warped, target);

  const Eigen::VectorXd error = (warped.vertices - target.vertices).colwise ().norm ().transpose ();
  morphreg::savePolygonMesh (options.text ("--out"),
                             morphreg::toPolygonMesh (warped, morphreg::residualColours (error, 10.0)));
  std::printf ("wrote %s (vertex colours: error 0-10 mm)\n", options.text ("--out").c_str ());
}
} // namespace

int
main (int argc, char** argv)
{
  return samples::run (argc, argv, kUsage, warpHead);
}

// SPDX-License-Identifier: BSD-3-Clause
// Builds a multi-region morphable model (one PCA per region, blended at the borders, plus the global PCA) from
// meshes in correspondence and writes it as a model file (HDF5, statismo layout + morphreg regions).
// Prints, per region, its vertices, its components and how much shape variance the leading components explain.
//
//   sample_build_model OUT.h5 [MESH.ply ...] [--count 30]
//
// Without meshes it uses --count heads of the built-in synthetic population. Meshes in the synthetic head topology
// (such as the PLY files the other samples write) get its seven regions; any other topology a one-region model.
#include "sample_heads.h"
#include "sample_options.h"

#include <morphreg/io/mesh_io.h>
#include <morphreg/io/model_io.h>
#include <morphreg/model/pca.h>

#include <cstdio>

namespace
{
const char* const kUsage = "usage: sample_build_model OUT.h5 [MESH ...] [--count N]\n"
                           "  without meshes: N heads (default 30) of the built-in synthetic population\n";

/** Components, and the variance fraction the first one and the first five explain; how many reach 95 %. */
void
printVariance (const std::string& name, std::size_t vertices, const Eigen::VectorXd& variances)
{
  if (variances.size () == 0) {
    std::printf ("%-12s %6zu vertices  no shape variation\n", name.c_str (), vertices);
    return;
  }
  const Eigen::VectorXd explained = morphreg::explainedVariance (variances);
  const Eigen::Index k = variances.size ();
  std::printf ("%-12s %6zu vertices  %3ld components  first %5.1f %%  first 5 %5.1f %%  95 %% with %d\n", name.c_str (),
               vertices, static_cast<long> (k), 100.0 * explained[0],
               100.0 * explained[std::min<Eigen::Index> (4, k - 1)], morphreg::componentsToKeep (variances, 0, 0.95));
}

void
buildModel (int argc, char** argv)
{
  const samples::Options options (argc, argv, {{"--count", "30"}});
  if (options.positional ().empty ())
    throw samples::UsageError ("expected the output model file");
  const std::string out = options.positional ().front ();
  const std::vector<std::string> files (options.positional ().begin () + 1, options.positional ().end ());

  const morphreg::synthetic::HeadGenerator generator;
  std::vector<morphreg::TriangleMesh> meshes;
  for (const auto& file : files)
    meshes.push_back (morphreg::loadTriangleMesh (file));
  if (files.empty ())
    meshes = samples::populationMeshes (generator, options.integer ("--count", 2), 1);
  std::printf ("%zu training meshes of %ld vertices\n", meshes.size (), static_cast<long> (meshes[0].numVertices ()));

  const morphreg::ModelBuilder builder; // Procrustes alignment, two blending rings, every component kept
  const bool head_topology =
      meshes[0].triangles.cols () == generator.triangles ().cols () && meshes[0].triangles == generator.triangles ();
  const morphreg::MorphableModel::Ptr model =
      head_topology ? builder.build (meshes, generator.regions ()) : builder.buildGlobal (meshes);
  if (head_topology) {
    model->setLandmarks (generator.landmarks ());
    model->setProfileLine (generator.profileLine ()); // what fitting to photos needs (sample_fit_photos)
  }

  for (const morphreg::ModelRegion& region : model->regions ())
    printVariance (region.name, region.vertices.size (), region.variances);
  printVariance ("global PCA", static_cast<std::size_t> (model->numVertices ()), model->globalVariances ());
  // The basis columns are unit vectors over all 3N coordinates: one standard deviation spreads over every vertex.
  std::printf ("one standard deviation of the first global component moves the vertices by %.2f mm RMS\n",
               std::sqrt (model->globalVariances ()[0] / static_cast<double> (model->numVertices ())));

  morphreg::saveModel (out, *model);
  const morphreg::MorphableModel::Ptr reloaded = morphreg::loadModel (out);
  std::printf ("wrote %s: %d regions, %d components in all, %zu landmarks\n", out.c_str (), reloaded->numRegions (),
               reloaded->allComponents ().total (), reloaded->landmarks ().size ());
}
} // namespace

int
main (int argc, char** argv)
{
  return samples::run (argc, argv, kUsage, buildModel);
}

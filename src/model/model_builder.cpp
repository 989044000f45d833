// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/model/model_builder.h>
#include <morphreg/model/model_builder_options.h>
#include <morphreg/model/procrustes.h>
#include <morphreg/model/region_blending.h>

#include <algorithm>
#include <numeric>

namespace morphreg
{
ModelBuilder::ModelBuilder (ModelBuilderSettings settings) : settings_ (settings)
{
  requireValidOptions (modelBuilderOptions (), settings_, "model builder setting");
}

void
ModelBuilder::prepareData (const std::vector<TriangleMesh>& meshes, Eigen::VectorXd& mean,
                           Eigen::MatrixXd& centred) const
{
  if (meshes.size () < 2)
    throw InvalidInputError ("ModelBuilder: at least two training meshes are needed, got " +
                             std::to_string (meshes.size ()));
  validateMesh (meshes[0], "ModelBuilder training mesh 0");
  const Eigen::Index rows = 3 * meshes[0].numVertices ();
  centred.resize (rows, static_cast<Eigen::Index> (meshes.size ()));
  for (size_t s = 0; s < meshes.size (); ++s) {
    const std::string name = "ModelBuilder training mesh " + std::to_string (s);
    validateMesh (meshes[s], name);
    requireSameTopology (meshes[0], meshes[s], name);
    centred.col (static_cast<Eigen::Index> (s)) = Eigen::Map<const Eigen::VectorXd> (meshes[s].vertices.data (), rows);
  }
  if (settings_.align)
    alignGeneralisedProcrustes (centred); // the columns in place
  mean = centred.rowwise ().mean ();
  centred.colwise () -= mean;
  // Identical meshes (after the alignment) leave nothing to learn: say so instead of building an empty basis.
  const double extent = mean.cwiseAbs ().maxCoeff ();
  if (!(centred.cwiseAbs ().maxCoeff () > 1e-9 * std::max (extent, 1.0)))
    throw InvalidInputError ("ModelBuilder: the " + std::to_string (meshes.size ()) + " training meshes are identical" +
                             (settings_.align ? " after alignment" : "") + ": there is no shape variation to model");
}

PcaBasis
ModelBuilder::truncatedPca (const Eigen::MatrixXd& centred) const
{
  return computePca (centred, settings_.pca_method, settings_.max_components, settings_.explained_variance);
}

double
ModelBuilder::memoryEstimate (std::size_t meshes, Eigen::Index vertices)
{
  const double columns = static_cast<double> (meshes), rows = 3.0 * static_cast<double> (vertices);
  const double gram = std::min (columns, rows);
  return 2.0 * rows * columns * sizeof (double) + gram * gram * sizeof (double);
}

MorphableModel::Ptr
ModelBuilder::buildGlobal (const std::vector<TriangleMesh>& meshes) const
{
  Eigen::VectorXd mean;
  Eigen::MatrixXd centred;
  prepareData (meshes, mean, centred);
  PcaBasis pca = truncatedPca (centred);
  return MorphableModel::fromGlobalPca (meshes[0].triangles, std::move (mean), std::move (pca.basis),
                                        std::move (pca.variances));
}

MorphableModel::Ptr
ModelBuilder::build (const std::vector<TriangleMesh>& meshes, const RegionLabels& regions) const
{
  if (meshes.empty ())
    throw InvalidInputError ("ModelBuilder: no training meshes");
  validateRegionLabels (regions, meshes[0].numVertices ());
  Eigen::VectorXd mean;
  Eigen::MatrixXd centred;
  prepareData (meshes, mean, centred);

  const MeshTopology topology (meshes[0]);
  const std::vector<BlendedRegion> blended = blendRegions (topology, regions, settings_.blend_rings);
  std::vector<std::vector<int>> vertex_sets;
  for (const BlendedRegion& region : blended)
    vertex_sets.push_back (region.vertices);
  vertex_sets.emplace_back (static_cast<std::size_t> (meshes[0].numVertices ()));
  std::iota (vertex_sets.back ().begin (), vertex_sets.back ().end (), 0); // the whole mesh: the global PCA
  std::vector<PcaBasis> pcas = computeVertexSetPcas (std::move (centred), vertex_sets, settings_.pca_method,
                                                     settings_.max_components, settings_.explained_variance);
  std::vector<ModelRegion> model_regions;
  for (size_t j = 0; j < blended.size (); ++j)
    model_regions.push_back ({regions.names[j], blended[j].vertices, blended[j].weights, std::move (pcas[j].basis),
                              std::move (pcas[j].variances)});
  PcaBasis& global = pcas.back ();
  auto model = std::make_shared<MorphableModel> (meshes[0].triangles, std::move (mean), std::move (model_regions));
  model->setGlobalPca (std::move (global.basis), std::move (global.variances));
  model->setMetadata ({{"builder", "morphreg::ModelBuilder"},
                       {"training_meshes", std::to_string (meshes.size ())},
                       {"blend_rings", std::to_string (settings_.blend_rings)},
                       {"procrustes_alignment", settings_.align ? "rigid" : "none"}});
  return model;
}

} // namespace morphreg

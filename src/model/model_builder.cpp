#include <morphreg/common/error.h>
#include <morphreg/mesh/mesh_topology.h>
#include <morphreg/model/model_builder.h>
#include <morphreg/model/procrustes.h>
#include <morphreg/model/region_blending.h>

namespace morphreg
{
ModelBuilder::ModelBuilder (ModelBuilderSettings settings) : settings_ (settings)
{
  if (!(settings_.explained_variance > 0.0 && settings_.explained_variance <= 1.0))
    throw InvalidInputError ("ModelBuilder: explained_variance must be in (0, 1], got " +
                             std::to_string (settings_.explained_variance));
  if (settings_.blend_rings < 0)
    throw InvalidInputError ("ModelBuilder: blend_rings must be >= 0, got " + std::to_string (settings_.blend_rings));
}

void
ModelBuilder::prepareData (const std::vector<TriangleMesh>& meshes, Eigen::VectorXd& mean,
                           Eigen::MatrixXd& centred) const
{
  if (meshes.size () < 2)
    throw InvalidInputError ("ModelBuilder: at least two training meshes are needed, got " +
                             std::to_string (meshes.size ()));
  validateMesh (meshes[0], "ModelBuilder training mesh 0");
  std::vector<Eigen::Matrix3Xd> shapes;
  for (size_t s = 0; s < meshes.size (); ++s) {
    const std::string name = "ModelBuilder training mesh " + std::to_string (s);
    validateMesh (meshes[s], name);
    requireSameTopology (meshes[0], meshes[s], name);
    shapes.push_back (meshes[s].vertices);
  }
  if (settings_.align)
    alignGeneralisedProcrustes (shapes);

  const Eigen::Index rows = 3 * meshes[0].numVertices ();
  centred.resize (rows, static_cast<Eigen::Index> (shapes.size ()));
  for (size_t s = 0; s < shapes.size (); ++s)
    centred.col (s) = Eigen::Map<const Eigen::VectorXd> (shapes[s].data (), rows);
  mean = centred.rowwise ().mean ();
  centred.colwise () -= mean;
}

PcaBasis
ModelBuilder::truncatedPca (const Eigen::MatrixXd& centred) const
{
  return computePca (centred, settings_.pca_method, settings_.max_components, settings_.explained_variance);
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
  std::vector<ModelRegion> model_regions;
  for (size_t j = 0; j < blended.size (); ++j) {
    const std::vector<int>& vertices = blended[j].vertices;
    Eigen::MatrixXd local (3 * static_cast<Eigen::Index> (vertices.size ()), centred.cols ());
    for (size_t r = 0; r < vertices.size (); ++r)
      local.middleRows<3> (3 * r) = centred.middleRows<3> (3 * static_cast<Eigen::Index> (vertices[r]));
    PcaBasis pca = truncatedPca (local);
    model_regions.push_back ({regions.names[j], vertices, blended[j].weights, std::move (pca.basis),
                              std::move (pca.variances)});
  }
  PcaBasis global = truncatedPca (centred);
  auto model = std::make_shared<MorphableModel> (meshes[0].triangles, std::move (mean), std::move (model_regions));
  model->setGlobalPca (std::move (global.basis), std::move (global.variances));
  model->setMetadata ({{"builder", "morphreg::ModelBuilder"},
                       {"training_meshes", std::to_string (meshes.size ())},
                       {"blend_rings", std::to_string (settings_.blend_rings)},
                       {"procrustes_alignment", settings_.align ? "rigid" : "none"}});
  return model;
}

} // namespace morphreg

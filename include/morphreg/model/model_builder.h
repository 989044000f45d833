// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file model_builder.h
 *  \brief Builds a (multi-region) MorphableModel from training meshes in correspondence (docs/method.md,
 *  "The multi-region shape model").
 */
#include <morphreg/model/morphable_model.h>
#include <morphreg/model/pca.h>
#include <morphreg/model/region_segmentation.h>

#include <vector>

namespace morphreg
{
/** \brief Settings of ModelBuilder. */
struct ModelBuilderSettings
{
  /** \brief At most this many components per region and in the global PCA (0: no limit). */
  int max_components = 0;
  /** \brief Keep the fewest leading components that explain this fraction of a region's variance (in (0, 1]). */
  double explained_variance = 1.0;
  /** \brief Rings of blending around each region (0 = hard regions, which still overlap by one ring). */
  int blend_rings = 2;
  /** \brief Rigid generalised Procrustes alignment of the training meshes before the PCA. */
  bool align = true;
  /** \brief How the PCAs are computed. */
  PcaMethod pca_method = PcaMethod::automatic;
};

/** \brief Global and region-wise PCA of training meshes that share one topology.
 *
 *  \code
 *  morphreg::ModelBuilder builder;                                  // Procrustes on, 2 blending rings
 *  morphreg::MorphableModel::Ptr model = builder.build (meshes, labels);
 *  \endcode
 */
class ModelBuilder
{
public:
  /** \brief A builder with \a settings.
   *  \param[in] settings component limits, blending and alignment
   */
  explicit ModelBuilder (ModelBuilderSettings settings = {});

  /** \brief A one-region model of the global PCA. Throws InvalidInputError for fewer than two meshes, an invalid
   *  mesh, or meshes not in correspondence (naming the mesh and the difference).
   *  \param[in] meshes the training meshes, one topology
   *  \return the model
   */
  MorphableModel::Ptr
  buildGlobal (const std::vector<TriangleMesh>& meshes) const;

  /** \brief A multi-region model: one PCA per region of \a regions (grown and blended), plus the global PCA as
   *  the model's statismo part. Throws InvalidInputError as buildGlobal, and for invalid region labels.
   *  \param[in] meshes the training meshes, one topology
   *  \param[in] regions a region label per vertex
   *  \return the model
   */
  MorphableModel::Ptr
  build (const std::vector<TriangleMesh>& meshes, const RegionLabels& regions) const;

  /** \brief About how many bytes building a model from \a meshes meshes of \a vertices vertices allocates at its
   *  peak: the meshes, their centred data matrix and the Gram matrix of the PCA. For requireMemory()
   *  (memory_budget.h) before the meshes are made or read.
   *  \param[in] meshes the number of training meshes
   *  \param[in] vertices the vertices of each
   *  \return bytes
   */
  static double
  memoryEstimate (std::size_t meshes, Eigen::Index vertices);

  /** \brief The builder's settings.
   *  \return the settings given at construction
   */
  const ModelBuilderSettings&
  settings () const

  {
    return settings_;
  }

private:
  /** Validated, optionally aligned training data: mean (3N) and centred columns (3N x M). */
  void
  prepareData (const std::vector<TriangleMesh>& meshes, Eigen::VectorXd& mean, Eigen::MatrixXd& centred) const;

  PcaBasis
  truncatedPca (const Eigen::MatrixXd& centred) const;

  ModelBuilderSettings settings_;
};

} // namespace morphreg

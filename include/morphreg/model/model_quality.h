// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file model_quality.h
 *  \brief The standard measures of a shape model's quality (Styner et al. 2003, as statismo and scalismo report
 *  them): compactness, generalisation and specificity of the model's global PCA (its statismo part).
 *
 *  Shapes are compared in correspondence: the distance of two meshes of the model's topology is the mean distance
 *  of their corresponding vertices (mm). Meshes given to generalisation() and specificity() are first moved
 *  rigidly (least squares, no scaling) onto the model's mean, as the training meshes of a Procrustes-aligned model
 *  were, so their pose does not count.
 *  \code
 *  const Eigen::VectorXd share = morphreg::compactness (*model);                  // share(k - 1): k components
 *  const morphreg::QualityMeasure g = morphreg::generalisation (*model, held_out, 20);
 *  const morphreg::QualityMeasure s = morphreg::specificity (*model, training, 20, 1000, 1);
 *  \endcode
 */
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/model/morphable_model.h>

#include <Eigen/Core>

#include <cstdint>
#include <vector>

namespace morphreg
{
/** \brief A mean distance over a set of shapes and its spread. */
struct QualityMeasure
{
  double mean = 0.0;    ///< mean over the shapes of the mean vertex distance (mm)
  double std_dev = 0.0; ///< standard deviation of the per-shape distances (mm)
};

/** \brief Compactness: the share of the model's variance the first k global components explain, for k = 1..K.
 *  Throws InvalidInputError for a model without global components or without variance.
 *  \param[in] model the model
 *  \return K cumulative shares, increasing to 1
 */
Eigen::VectorXd
compactness (const MorphableModel& model);

/** \brief The mean distance of corresponding vertices of two shapes of one topology.
 *  \param[in] a 3 x N
 *  \param[in] b 3 x N
 *  \return mm
 */
double
meanVertexDistance (const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b);

/** \brief Generalisation: each held-out mesh (not in the training set) aligned to the model's mean and projected
 *  onto the first \a components global components (least squares); the mean vertex distance of the reconstruction
 *  to the mesh, over the meshes. Throws InvalidInputError for no meshes, a mesh of another topology, or
 *  \a components outside [0, K].
 *  \param[in] model the model
 *  \param[in] held_out meshes in the model's topology
 *  \param[in] components k
 *  \return the reconstruction error over the meshes (mm)
 */
QualityMeasure
generalisation (const MorphableModel& model, const std::vector<TriangleMesh>& held_out, int components);

/** \brief Specificity: \a samples shapes drawn from the model's first \a components global components (each
 *  coefficient from N(0, its variance), a std::mt19937_64 seeded with \a seed), each at the mean vertex distance
 *  of the training mesh closest to it; the mean over the samples. Throws InvalidInputError for no training mesh,
 *  a mesh of another topology, \a components outside [0, K] or \a samples < 1.
 *  \param[in] model the model
 *  \param[in] training the meshes it was built from, in its topology
 *  \param[in] components k
 *  \param[in] samples the number of random shapes
 *  \param[in] seed the random generator's seed (the same seed, the same samples)
 *  \return the distance of the samples to the training set (mm)
 */
QualityMeasure
specificity (const MorphableModel& model, const std::vector<TriangleMesh>& training, int components, int samples,
             std::uint64_t seed);

} // namespace morphreg

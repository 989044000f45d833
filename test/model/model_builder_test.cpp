// SPDX-License-Identifier: BSD-3-Clause
#include "population.h"

#include <morphreg/common/error.h>
#include <morphreg/model/model_builder.h>
#include <morphreg/model/procrustes.h>

#include <Eigen/Geometry>
#include <Eigen/QR>
#include <gtest/gtest.h>

#include <algorithm>
#include <random>

using morphreg::ModelBuilder;
using morphreg::ModelBuilderSettings;
using morphreg::MorphableModel;
using morphreg::PcaMethod;
using morphreg::TriangleMesh;

namespace
{
const std::vector<TriangleMesh>&
meshes ()
{
  static const std::vector<TriangleMesh> instance = morphreg::test::trainingMeshes (30);
  return instance;
}

ModelBuilderSettings
unaligned (int blend_rings = 2, PcaMethod method = PcaMethod::automatic)
{
  ModelBuilderSettings settings;
  settings.align = false;
  settings.blend_rings = blend_rings;
  settings.pca_method = method;
  return settings;
}

void
expectOrthonormalSorted (const Eigen::MatrixXd& basis, const Eigen::VectorXd& variances, const std::string& what)
{
  ASSERT_EQ (basis.cols (), variances.size ()) << what;
  ASSERT_GT (basis.cols (), 0) << what;
  const Eigen::MatrixXd gram = basis.transpose () * basis;
  EXPECT_LT ((gram - Eigen::MatrixXd::Identity (gram.rows (), gram.cols ())).cwiseAbs ().maxCoeff (), 1e-9) << what;
  for (Eigen::Index k = 1; k < variances.size (); ++k)
    EXPECT_LE (variances[k], variances[k - 1]) << what << " component " << k;
  EXPECT_GT (variances.minCoeff (), 0.0) << what;
  const Eigen::VectorXd explained = morphreg::explainedVariance (variances);
  for (Eigen::Index k = 1; k < explained.size (); ++k)
    EXPECT_GE (explained[k], explained[k - 1]) << what;
  EXPECT_NEAR (explained[explained.size () - 1], 1.0, 1e-12) << what;
}

double
worstTrainingReconstruction (const MorphableModel& model, const std::vector<TriangleMesh>& training)
{
  double worst = 0.0;
  for (const TriangleMesh& mesh : training)
    worst = std::max (worst, model.project (mesh, model.allComponents (), 0.0).max_error);
  return worst;
}
} // namespace

TEST (ModelBuilderTest, GlobalModelReconstructsTrainingSamplesExactly)
{
  for (const PcaMethod method : {PcaMethod::gram, PcaMethod::thin_svd}) {
    const auto model = ModelBuilder (unaligned (2, method)).buildGlobal (meshes ());
    EXPECT_LT (worstTrainingReconstruction (*model, meshes ()), 1e-6);
    expectOrthonormalSorted (model->region (0).basis, model->region (0).variances, "global");
  }
}

TEST (ModelBuilderTest, RegionModelReconstructsTrainingSamplesExactly)
{
  for (const int blend : {0, 3}) {
    const auto model = ModelBuilder (unaligned (blend)).build (meshes (), morphreg::test::headRegions ());
    ASSERT_EQ (model->numRegions (), 7);
    EXPECT_LT (worstTrainingReconstruction (*model, meshes ()), 1e-6) << "blend " << blend;
  }
}

TEST (ModelBuilderTest, BasesOrthonormalVariancesSortedExplainedVarianceMonotone)
{
  const auto model = ModelBuilder ().build (meshes (), morphreg::test::headRegions ());
  for (int j = 0; j < model->numRegions (); ++j)
    expectOrthonormalSorted (model->region (j).basis, model->region (j).variances, model->region (j).name);
  expectOrthonormalSorted (model->globalBasis (), model->globalVariances (), "global part");
}

TEST (ModelBuilderTest, GramAndSvdAgree)
{
  const auto gram = ModelBuilder (unaligned (2, PcaMethod::gram)).buildGlobal (meshes ());
  const auto svd = ModelBuilder (unaligned (2, PcaMethod::thin_svd)).buildGlobal (meshes ());
  const Eigen::VectorXd& a = gram->region (0).variances;
  const Eigen::VectorXd& b = svd->region (0).variances;
  ASSERT_EQ (a.size (), b.size ());
  EXPECT_LT ((a - b).cwiseAbs ().maxCoeff (), 1e-8 * b[0]);
  // Leading directions agree up to sign.
  for (int k = 0; k < 5; ++k)
    EXPECT_NEAR (std::abs (gram->region (0).basis.col (k).dot (svd->region (0).basis.col (k))), 1.0, 1e-8);
}

TEST (ModelBuilderTest, ComponentCountAndExplainedVarianceFraction)
{
  ModelBuilderSettings by_count = unaligned ();
  by_count.max_components = 4;
  const auto counted = ModelBuilder (by_count).build (meshes (), morphreg::test::headRegions ());
  for (int j = 0; j < counted->numRegions (); ++j)
    EXPECT_EQ (counted->region (j).basis.cols (), 4);

  const auto full = ModelBuilder (unaligned ()).build (meshes (), morphreg::test::headRegions ());
  ModelBuilderSettings by_fraction = unaligned ();
  by_fraction.explained_variance = 0.9;
  const auto fraction = ModelBuilder (by_fraction).build (meshes (), morphreg::test::headRegions ());
  for (int j = 0; j < full->numRegions (); ++j) {
    const Eigen::VectorXd explained = morphreg::explainedVariance (full->region (j).variances);
    const Eigen::Index k = fraction->region (j).basis.cols ();
    ASSERT_GE (k, 1);
    EXPECT_GE (explained[k - 1], 0.9 - 1e-12) << full->region (j).name;
    if (k >= 2) {
      EXPECT_LT (explained[k - 2], 0.9) << full->region (j).name;
    }
  }
  EXPECT_THROW (ModelBuilder ({0, 1.5}), morphreg::InvalidInputError);
}

TEST (ModelBuilderTest, BlendingWeightsInUnitIntervalAndSumToOne)
{
  const auto model = ModelBuilder (unaligned (3)).build (meshes (), morphreg::test::headRegions ());
  Eigen::VectorXd sums = Eigen::VectorXd::Zero (model->numVertices ());
  bool some_fractional = false;
  for (const auto& region : model->regions ()) {
    EXPECT_GE (region.weights.minCoeff (), 0.0);
    EXPECT_LE (region.weights.maxCoeff (), 1.0);
    for (size_t r = 0; r < region.vertices.size (); ++r) {
      sums[region.vertices[r]] += region.weights[r];
      some_fractional |= region.weights[r] > 0.0 && region.weights[r] < 1.0;
    }
  }
  EXPECT_LT ((sums.array () - 1.0).abs ().maxCoeff (), 1e-12);
  EXPECT_TRUE (some_fractional);
  // A vertex two rings outside its neighbour region and inside its own: raw weights 1 and 1/3 -> 3/4 and 1/4.
  bool found = false;
  for (const auto& region : model->regions ())
    for (size_t r = 0; r < region.vertices.size () && !found; ++r)
      found = std::abs (region.weights[r] - 0.25) < 1e-12;
  EXPECT_TRUE (found);
}

TEST (ModelBuilderTest, HardRegionsStillOverlapByOneRing)
{
  const auto model = ModelBuilder (unaligned (0)).build (meshes (), morphreg::test::headRegions ());
  EXPECT_FALSE (model->gammaPairs ().empty ());
  for (const auto& region : model->regions ())
    for (Eigen::Index r = 0; r < region.weights.size (); ++r)
      EXPECT_TRUE (region.weights[r] == 0.0 || region.weights[r] == 1.0);
  const auto labels = morphreg::test::headRegions ().labels;
  for (const auto& pair : model->gammaPairs ()) {
    const int own = labels[pair.vertex];
    EXPECT_TRUE (pair.region_a == own || pair.region_b == own);
  }
}

TEST (ModelBuilderTest, RejectsMeshesNotInCorrespondence)
{
  std::vector<TriangleMesh> training (meshes ().begin (), meshes ().begin () + 3);
  std::vector<TriangleMesh> bad = training;
  bad[1] = morphreg::test::trainingMeshes (1)[0];
  std::swap (bad[1].triangles (0, 0), bad[1].triangles (1, 0));
  try {
    ModelBuilder ().buildGlobal (bad);
    FAIL () << "expected InvalidInputError";
  }
  catch (const morphreg::InvalidInputError& e) {
    EXPECT_NE (std::string (e.what ()).find ("training mesh 1"), std::string::npos) << e.what ();
  }
  bad = training;
  bad[2].vertices.conservativeResize (Eigen::NoChange, bad[2].vertices.cols () - 5);
  EXPECT_THROW (ModelBuilder ().buildGlobal (bad), morphreg::InvalidInputError);
  EXPECT_THROW (ModelBuilder ().buildGlobal ({training[0]}), morphreg::InvalidInputError);
  bad = training;
  bad[0].vertices (0, 0) = std::nan ("");
  EXPECT_THROW (ModelBuilder ().buildGlobal (bad), morphreg::InvalidInputError);
  morphreg::RegionLabels labels = morphreg::test::headRegions ();
  labels.labels.pop_back ();
  EXPECT_THROW (ModelBuilder ().build (training, labels), morphreg::InvalidInputError);
}

TEST (ModelBuilderTest, IdenticalMeshesAreReportedNotModelled)
{
  const std::vector<TriangleMesh> same (3, meshes ()[0]);
  for (const bool regional : {false, true}) {
    try {
      regional ? ModelBuilder ().build (same, morphreg::test::headRegions ()) : ModelBuilder ().buildGlobal (same);
      FAIL () << "expected InvalidInputError";
    }
    catch (const morphreg::InvalidInputError& e) {
      EXPECT_NE (std::string (e.what ()).find ("identical"), std::string::npos) << e.what ();
    }
  }
}

TEST (ModelBuilderTest, ProcrustesRemovesRigidMotion)
{
  std::vector<TriangleMesh> moved = meshes ();
  for (size_t s = 0; s < moved.size (); ++s) {
    const Eigen::AngleAxisd rotation (0.05 * static_cast<double> (s), Eigen::Vector3d (1, 2, 3).normalized ());
    moved[s].vertices =
        (rotation.toRotationMatrix () * moved[s].vertices).colwise () + Eigen::Vector3d (s, -2.0 * s, 0.5 * s);
  }
  const auto reference = ModelBuilder ().buildGlobal (meshes ());
  const auto aligned = ModelBuilder ().buildGlobal (moved);
  const auto unaligned_model = ModelBuilder (unaligned ()).buildGlobal (moved);
  const Eigen::VectorXd& a = reference->region (0).variances;
  const Eigen::VectorXd& b = aligned->region (0).variances;
  ASSERT_EQ (a.size (), b.size ());
  EXPECT_LT ((a - b).cwiseAbs ().maxCoeff (), 1e-6 * a[0]);
  EXPECT_GT (unaligned_model->region (0).variances[0], 2.0 * a[0]);
}

TEST (ModelBuilderTest, VertexSetPcasMatchOneSetAtATime)
{
  // 300 vertices, 40 samples with singular values from 1 down to 1e-5 (small components make the Gram route
  // re-orthonormalise), and overlapping vertex sets listed in scrambled order; the smallest set takes the SVD route.
  const Eigen::Index vertices = 300, samples = 40;
  std::mt19937 random (7);
  std::normal_distribution<double> normal;
  const auto gaussian = [&] (Eigen::Index rows, Eigen::Index cols) {
    return Eigen::MatrixXd (Eigen::MatrixXd::NullaryExpr (rows, cols, [&] () { return normal (random); }));
  };
  const Eigen::HouseholderQR<Eigen::MatrixXd> left (gaussian (3 * vertices, samples));
  const Eigen::HouseholderQR<Eigen::MatrixXd> right (gaussian (samples, samples));
  Eigen::VectorXd sigma (samples);
  for (Eigen::Index k = 0; k < samples; ++k)
    sigma[k] = std::pow (1e-5, static_cast<double> (k) / (samples - 1));
  Eigen::MatrixXd data = left.householderQ () * Eigen::MatrixXd::Identity (3 * vertices, samples) *
                         sigma.asDiagonal () * Eigen::MatrixXd (right.householderQ ()).transpose ();
  data.colwise () -= data.rowwise ().mean ().eval ();
  std::vector<std::vector<int>> sets (4);
  for (int v = 0; v < vertices; ++v) {
    if (v < 180)
      sets[0].push_back (v);
    if (v >= 150)
      sets[1].push_back (v);
    if (v % 7 == 3)
      sets[2].push_back (v); // 43 vertices: 129 rows < 4 x 40, thin SVD
    sets[3].push_back (v);
  }
  std::shuffle (sets[1].begin (), sets[1].end (), random);
  const std::vector<morphreg::PcaBasis> together = morphreg::computeVertexSetPcas (data, sets);
  ASSERT_EQ (together.size (), sets.size ());
  for (size_t s = 0; s < sets.size (); ++s) {
    Eigen::MatrixXd rows (3 * static_cast<Eigen::Index> (sets[s].size ()), samples);
    for (size_t k = 0; k < sets[s].size (); ++k)
      rows.middleRows<3> (3 * static_cast<Eigen::Index> (k)) = data.middleRows<3> (3 * sets[s][k]);
    const morphreg::PcaBasis alone = morphreg::computePca (rows);
    const std::string what = "vertex set " + std::to_string (s);
    expectOrthonormalSorted (together[s].basis, together[s].variances, what);
    ASSERT_EQ (together[s].variances.size (), alone.variances.size ()) << what;
    EXPECT_LT ((together[s].variances - alone.variances).cwiseAbs ().maxCoeff (), 1e-9 * alone.variances[0]) << what;
    // Same subspace, rows in the set's order: the set's data is reproduced from the basis.
    const Eigen::MatrixXd& u = together[s].basis;
    EXPECT_LT ((rows - u * (u.transpose () * rows)).cwiseAbs ().maxCoeff (), 1e-9) << what;
  }
}

TEST (ModelBuilderTest, VertexSetPcasRejectBadSets)
{
  const Eigen::MatrixXd data = Eigen::MatrixXd::Random (30, 5);
  EXPECT_THROW (morphreg::computeVertexSetPcas (data, {{0, 1}, {}}), morphreg::InvalidInputError) << "empty set";
  EXPECT_THROW (morphreg::computeVertexSetPcas (data, {{0, 10}}), morphreg::InvalidInputError) << "vertex 10 of 10";
  EXPECT_THROW (morphreg::computeVertexSetPcas (data, {{-1, 2}}), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::computeVertexSetPcas (data, {{2, 3, 2}}), morphreg::InvalidInputError) << "listed twice";
  EXPECT_THROW (morphreg::computeVertexSetPcas (Eigen::MatrixXd::Random (31, 5), {{0}}), morphreg::InvalidInputError);
  EXPECT_THROW (morphreg::computeVertexSetPcas (Eigen::MatrixXd::Random (30, 1), {{0}}), morphreg::InvalidInputError);
}

TEST (ModelBuilderTest, ProcrustesOnDataMatrixColumnsMatchesShapeList)
{
  std::vector<Eigen::Matrix3Xd> shapes;
  Eigen::MatrixXd columns (3 * meshes ()[0].numVertices (), 5);
  for (Eigen::Index s = 0; s < columns.cols (); ++s) {
    const Eigen::AngleAxisd rotation (0.1 * static_cast<double> (s), Eigen::Vector3d (0, 1, 1).normalized ());
    shapes.push_back ((rotation.toRotationMatrix () * meshes ()[s].vertices).colwise () + Eigen::Vector3d (s, 0, 1));
    columns.col (s) = Eigen::Map<const Eigen::VectorXd> (shapes.back ().data (), columns.rows ());
  }
  morphreg::alignGeneralisedProcrustes (shapes);
  morphreg::alignGeneralisedProcrustes (columns);
  for (Eigen::Index s = 0; s < columns.cols (); ++s)
    EXPECT_LT ((Eigen::Map<const Eigen::VectorXd> (shapes[s].data (), columns.rows ()) - columns.col (s))
                   .cwiseAbs ()
                   .maxCoeff (),
               1e-12);
  Eigen::MatrixXd bad (31, 3);
  EXPECT_THROW (morphreg::alignGeneralisedProcrustes (bad), morphreg::InvalidInputError);
  Eigen::MatrixXd single (30, 1);
  EXPECT_THROW (morphreg::alignGeneralisedProcrustes (single), morphreg::InvalidInputError);
}

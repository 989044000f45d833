// SPDX-License-Identifier: BSD-3-Clause
#include "population.h"

#include <morphreg/common/error.h>
#include <morphreg/model/model_builder.h>

#include <gtest/gtest.h>

using morphreg::ComponentSelection;
using morphreg::ModelBuilder;
using morphreg::ModelRegion;
using morphreg::MorphableModel;
using morphreg::ShapePrior;

namespace
{
const MorphableModel&
regionModel ()
{
  static const MorphableModel::ConstPtr model =
      ModelBuilder ().build (morphreg::test::trainingMeshes (25), morphreg::test::headRegions ());
  return *model;
}

/** The global basis of \a model cut into the regions of \a regions_of: same mean, same weights. */
MorphableModel
globalBasisCutIntoRegions (const MorphableModel& regions_of)
{
  const Eigen::MatrixXd& global = regions_of.globalBasis ();
  std::vector<ModelRegion> regions = regions_of.regions ();
  for (ModelRegion& region : regions) {
    region.basis.resize (3 * static_cast<Eigen::Index> (region.vertices.size ()), global.cols ());
    for (size_t r = 0; r < region.vertices.size (); ++r)
      region.basis.middleRows<3> (3 * r) = global.middleRows<3> (3 * static_cast<Eigen::Index> (region.vertices[r]));
    region.variances = regions_of.globalVariances ();
  }
  return MorphableModel (regions_of.triangles (), regions_of.mean (), regions);
}
} // namespace

TEST (MorphableModelTest, GammaResidualIsZeroForOneGlobalBasisCutIntoRegions)
{
  const MorphableModel cut = globalBasisCutIntoRegions (regionModel ());
  ASSERT_FALSE (cut.gammaPairs ().empty ());
  const Eigen::VectorXd g = Eigen::VectorXd::LinSpaced (regionModel ().globalVariances ().size (), 3.0, -1.0);
  const ComponentSelection all = cut.allComponents ();
  Eigen::VectorXd stacked (all.total ());
  for (int j = 0; j < cut.numRegions (); ++j)
    stacked.segment (all.offset (j), all.count (j)) = g;
  EXPECT_LT (cut.gammaResiduals (stacked, all).cwiseAbs ().maxCoeff (), 1e-12);
  EXPECT_LT ((cut.gammaMatrix (all) * stacked).cwiseAbs ().maxCoeff (), 1e-12);
  // Blending weights sum to one, so the cut model is the global model.
  const Eigen::VectorXd expected = cut.mean () + regionModel ().globalBasis () * g;
  const Eigen::Matrix3Xd generated = cut.generate (stacked, all);
  EXPECT_LT (
      (Eigen::Map<const Eigen::VectorXd> (generated.data (), generated.size ()) - expected).cwiseAbs ().maxCoeff (),
      1e-9);
  // Different coefficients per region disagree on shared vertices.
  stacked.head (all.count (0)) *= 2.0;
  EXPECT_GT (cut.gammaResiduals (stacked, all).cwiseAbs ().maxCoeff (), 1e-6);
}

TEST (MorphableModelTest, ShapeRowsMatchGenerate)
{
  const MorphableModel& model = regionModel ();
  const ComponentSelection sel = model.firstComponents (5);
  std::mt19937_64 rng (3);
  const Eigen::VectorXd m = model.sampleCoefficients (rng, sel);
  const Eigen::Matrix3Xd generated = model.generate (m, sel);
  const MorphableModel::RowMatrix h = model.shapeMatrix (sel);
  ASSERT_EQ (h.rows (), 3 * model.numVertices ());
  ASSERT_EQ (h.cols (), sel.total ());
  const Eigen::VectorXd flat = h * m + model.mean ();
  EXPECT_LT ((Eigen::Map<const Eigen::VectorXd> (generated.data (), generated.size ()) - flat).cwiseAbs ().maxCoeff (),
             1e-9);
  for (int i = 0; i < model.numVertices (); i += 97) {
    EXPECT_LT ((model.shapeRows (i, sel) - h.middleRows (3 * i, 3)).cwiseAbs ().maxCoeff (), 1e-15);
    EXPECT_LT ((model.vertex (i, m, sel) - generated.col (i)).norm (), 1e-9);
    Eigen::Vector3d sparse = model.meanVertex (i);
    for (const auto& e : model.vertexEntries (i))
      sparse += e.weight * model.regionRows (e.region, e.row, sel.count (e.region)) *
                m.segment (sel.offset (e.region), sel.count (e.region));
    EXPECT_LT ((sparse - generated.col (i)).norm (), 1e-9);
  }
  const auto cloud = model.generateCloud<pcl::PointNormal> (m, sel);
  ASSERT_EQ (static_cast<Eigen::Index> (cloud->size ()), model.numVertices ());
  EXPECT_LT (((*cloud)[10].getVector3fMap ().cast<double> () - generated.col (10)).norm (), 1e-3);
  EXPECT_NEAR ((*cloud)[10].getNormalVector3fMap ().norm (), 1.0, 1e-5);
  const auto xyz = model.generateCloud<pcl::PointXYZ> (m, sel);
  EXPECT_EQ (xyz->size (), cloud->size ());
  const pcl::PolygonMesh mesh = model.generatePolygonMesh (m, sel);
  EXPECT_EQ (static_cast<Eigen::Index> (mesh.polygons.size ()), model.triangles ().cols ());
  EXPECT_THROW (model.generate (Eigen::VectorXd::Zero (sel.total () + 1), sel), morphreg::InvalidInputError);
}

TEST (MorphableModelTest, FirstComponentsPerRegion)
{
  const MorphableModel& model = regionModel ();
  const ComponentSelection sel = model.firstComponents (3);
  ASSERT_EQ (sel.numRegions (), model.numRegions ());
  for (int j = 0; j < model.numRegions (); ++j) {
    EXPECT_EQ (sel.count (j), 3);
    EXPECT_EQ (sel.offset (j), 3 * j);
  }
  EXPECT_EQ (model.firstComponents (10000).total (), model.allComponents ().total ());
  EXPECT_THROW (model.firstComponents (std::vector<int>{1, 2}), morphreg::InvalidInputError);
  EXPECT_THROW (model.shapeMatrix (ComponentSelection ({1, 1})), morphreg::InvalidInputError);
}

TEST (MorphableModelTest, LambdaIsIdentityOrInverseStandardDeviation)
{
  const MorphableModel& model = regionModel ();
  const ComponentSelection sel = model.firstComponents (4);
  const Eigen::VectorXd var = model.variances (sel);
  EXPECT_EQ (model.lambdaDiagonal (sel, ShapePrior::identity), Eigen::VectorXd::Ones (sel.total ()));
  const Eigen::VectorXd lambda = model.lambdaDiagonal (sel, ShapePrior::inverse_std_dev);
  for (Eigen::Index k = 0; k < var.size (); ++k)
    EXPECT_NEAR (lambda[k] * std::sqrt (var[k]), 1.0, 1e-12);
}

TEST (MorphableModelTest, ProjectRecoversCoefficientsAndRegularisationShrinks)
{
  const MorphableModel& model = regionModel ();
  const ComponentSelection sel = model.firstComponents (6);
  std::mt19937_64 rng (11);
  const Eigen::VectorXd m = model.sampleCoefficients (rng, sel);
  const Eigen::Matrix3Xd shape = model.generate (m, sel);
  const auto exact = model.project (shape, sel);
  EXPECT_LT ((exact.coefficients - m).norm (), 1e-6 * m.norm ());
  EXPECT_LT (exact.rms_error, 1e-8);
  const auto shrunk = model.project (shape, sel, 10.0);
  EXPECT_LT ((model.lambdaDiagonal (sel, ShapePrior::inverse_std_dev).asDiagonal () * shrunk.coefficients).norm (),
             (model.lambdaDiagonal (sel, ShapePrior::inverse_std_dev).asDiagonal () * m).norm ());
  EXPECT_GT (shrunk.rms_error, exact.rms_error);
  EXPECT_THROW (model.project (Eigen::Matrix3Xd (shape.leftCols (10)), sel), morphreg::InvalidInputError);
  Eigen::Matrix3Xd bad = shape;
  bad (1, 1) = std::nan ("");
  EXPECT_THROW (model.project (bad, sel), morphreg::InvalidInputError);
  EXPECT_THROW (model.project (shape, sel, -1.0), morphreg::InvalidInputError);
}

TEST (MorphableModelTest, SamplesFollowTheVariances)
{
  const MorphableModel& model = regionModel ();
  const ComponentSelection sel = model.firstComponents (2);
  const Eigen::VectorXd var = model.variances (sel);
  std::mt19937_64 rng (5);
  Eigen::VectorXd sum_sq = Eigen::VectorXd::Zero (sel.total ());
  const int draws = 4000;
  for (int d = 0; d < draws; ++d)
    sum_sq += model.sampleCoefficients (rng, sel).cwiseAbs2 ();
  // A sampling tolerance, not an accuracy bound: 0.1 is about four and a half standard errors (sqrt (2 / 4000)).
  for (Eigen::Index k = 0; k < var.size (); ++k)
    EXPECT_NEAR (sum_sq[k] / draws / var[k], 1.0, 0.1);
}

TEST (MorphableModelTest, ConstructorRejectsInvalidRegions)
{
  const MorphableModel& model = regionModel ();
  std::vector<ModelRegion> regions = model.regions ();
  regions[0].weights[0] = 0.5;
  EXPECT_THROW (MorphableModel (model.triangles (), model.mean (), regions), morphreg::InvalidInputError);
  regions = model.regions ();
  regions[1].vertices.back () = static_cast<int> (model.numVertices ());
  EXPECT_THROW (MorphableModel (model.triangles (), model.mean (), regions), morphreg::InvalidInputError);
  regions = model.regions ();
  regions[2].basis (0, 0) = std::nan ("");
  EXPECT_THROW (MorphableModel (model.triangles (), model.mean (), regions), morphreg::InvalidInputError);
  regions = model.regions ();
  regions[3].variances.conservativeResize (regions[3].variances.size () - 1);
  EXPECT_THROW (MorphableModel (model.triangles (), model.mean (), regions), morphreg::InvalidInputError);
  morphreg::TriangleMesh::Triangles triangles = model.triangles ();
  triangles (0, 0) = -1;
  EXPECT_THROW (MorphableModel (triangles, model.mean (), model.regions ()), morphreg::InvalidInputError);
  EXPECT_THROW (MorphableModel (model.triangles (), model.mean (), {}), morphreg::InvalidInputError);
  MorphableModel copy = model;
  EXPECT_THROW (copy.setLandmarks ({{"nose_tip", -1}}), morphreg::InvalidInputError);
  EXPECT_THROW (copy.landmarkVertex ("nose_tip"), morphreg::InvalidInputError);
  EXPECT_THROW (copy.setProfileLine ({static_cast<int> (model.numVertices ())}), morphreg::InvalidInputError);
}

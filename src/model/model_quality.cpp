// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/model/model_quality.h>
#include <morphreg/model/pca.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace morphreg
{
namespace
{
/** The model's mean as 3 x N. */
Eigen::Matrix3Xd
meanShape (const MorphableModel& model)
{
  return Eigen::Map<const Eigen::Matrix3Xd> (model.mean ().data (), 3, model.numVertices ());
}

void
requireComponents (const MorphableModel& model, int components, const char* measure)
{
  const Eigen::Index available = model.globalBasis ().cols ();
  if (components < 0 || components > available)
    throw InvalidInputError (std::string (measure) + ": " + std::to_string (components) +
                             " components asked for; the model's global PCA has " + std::to_string (available));
}

/** The meshes' vertices moved rigidly onto \a mean (least squares); InvalidInputError if a topology differs. */
std::vector<Eigen::Matrix3Xd>
alignedShapes (const std::vector<TriangleMesh>& meshes, const Eigen::Matrix3Xd& mean, const char* measure)
{
  if (meshes.empty ())
    throw InvalidInputError (std::string (measure) + ": no meshes");
  std::vector<Eigen::Matrix3Xd> shapes;
  for (std::size_t m = 0; m < meshes.size (); ++m) {
    const TriangleMesh::Vertices& vertices = meshes[m].vertices;
    if (vertices.cols () != mean.cols () || !vertices.allFinite ())
      throw InvalidInputError (std::string (measure) + ": mesh " + std::to_string (m) + " has " +
                               std::to_string (vertices.cols ()) +
                               " vertices (finite: " + (vertices.allFinite () ? "yes" : "no") + "); the model has " +
                               std::to_string (mean.cols ()));
    const Eigen::Matrix4d transform = Eigen::umeyama (vertices, mean, false);
    shapes.emplace_back ((transform.topLeftCorner<3, 3> () * vertices).colwise () + transform.topRightCorner<3, 1> ());
  }
  return shapes;
}

QualityMeasure
summarise (const std::vector<double>& distances)
{
  QualityMeasure measure;
  for (double d : distances)
    measure.mean += d;
  measure.mean /= static_cast<double> (distances.size ());
  for (double d : distances)
    measure.std_dev += (d - measure.mean) * (d - measure.mean);
  measure.std_dev = std::sqrt (measure.std_dev / static_cast<double> (distances.size ()));
  return measure;
}
} // namespace

Eigen::VectorXd
compactness (const MorphableModel& model)
{
  const Eigen::VectorXd& variances = model.globalVariances ();
  const double total = variances.sum ();
  if (variances.size () == 0 || !(total > 0.0))
    throw InvalidInputError ("compactness: the model's global PCA has no variance");
  return explainedVariance (variances);
}

double
meanVertexDistance (const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b)
{
  return (a - b).colwise ().norm ().mean ();
}

QualityMeasure
generalisation (const MorphableModel& model, const std::vector<TriangleMesh>& held_out, int components)
{
  requireComponents (model, components, "generalisation");
  const Eigen::Matrix3Xd mean = meanShape (model);
  const Eigen::MatrixXd basis = model.globalBasis ().leftCols (components);
  std::vector<double> errors;
  for (const Eigen::Matrix3Xd& shape : alignedShapes (held_out, mean, "generalisation")) {
    const Eigen::Map<const Eigen::VectorXd> x (shape.data (), shape.size ());
    const Eigen::VectorXd reconstruction = model.mean () + basis * (basis.transpose () * (x - model.mean ()));
    errors.push_back (
        meanVertexDistance (shape, Eigen::Map<const Eigen::Matrix3Xd> (reconstruction.data (), 3, shape.cols ())));
  }
  return summarise (errors);
}

QualityMeasure
specificity (const MorphableModel& model, const std::vector<TriangleMesh>& training, int components, int samples,
             std::uint64_t seed)
{
  requireComponents (model, components, "specificity");
  if (samples < 1)
    throw InvalidInputError ("specificity: " + std::to_string (samples) + " samples asked for; at least one");
  const Eigen::Matrix3Xd mean = meanShape (model);
  const std::vector<Eigen::Matrix3Xd> shapes = alignedShapes (training, mean, "specificity");
  const Eigen::MatrixXd basis = model.globalBasis ().leftCols (components);
  const Eigen::VectorXd std_devs = model.globalVariances ().head (components).cwiseMax (0.0).cwiseSqrt ();
  std::mt19937_64 rng (seed);
  std::normal_distribution<double> normal;
  std::vector<double> distances;
  for (int s = 0; s < samples; ++s) {
    Eigen::VectorXd coefficients (components);
    for (int k = 0; k < components; ++k)
      coefficients[k] = normal (rng) * std_devs[k];
    const Eigen::VectorXd sample = model.mean () + basis * coefficients;
    const Eigen::Matrix3Xd sample_shape = Eigen::Map<const Eigen::Matrix3Xd> (sample.data (), 3, mean.cols ());
    double closest = std::numeric_limits<double>::infinity ();
    for (const Eigen::Matrix3Xd& shape : shapes)
      closest = std::min (closest, meanVertexDistance (sample_shape, shape));
    distances.push_back (closest);
  }
  return summarise (distances);
}

} // namespace morphreg

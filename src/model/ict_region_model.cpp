// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/memory_budget.h>
#include <morphreg/common/error.h>
#include <morphreg/model/ict_region_model.h>

namespace morphreg
{
namespace
{
std::vector<int>
ibugVertices (const MorphableModel& ict, int first, int last)
{
  std::vector<int> vertices;
  for (int k = first; k <= last; ++k)
    vertices.push_back (ict.landmarkVertex (ibug68LandmarkId (k)));
  return vertices;
}

/** The mean vertex nearest to the centroid of the iBUG points \a points. */
int
nearestToCentroid (const MorphableModel& ict, const std::vector<int>& points)
{
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero ();
  for (const int k : points)
    centroid += ict.meanVertex (ibugVertices (ict, k, k)[0]);
  centroid /= static_cast<double> (points.size ());
  const Eigen::Map<const Eigen::Matrix3Xd> mean (ict.mean ().data (), 3, ict.numVertices ());
  Eigen::Index nearest = 0;
  (mean.colwise () - centroid).colwise ().squaredNorm ().minCoeff (&nearest);
  return static_cast<int> (nearest);
}
} // namespace

std::vector<LandmarkGroup>
ictRegionGroups (const MorphableModel& ict)
{
  return {{"eyes", ibugVertices (ict, 36, 47), 18.0},
          {"nose", ibugVertices (ict, 27, 35), 15.0},
          {"mouth", ibugVertices (ict, 48, 67), 12.0},
          {"ears", {ict.landmarkVertex ("left_tragus"), ict.landmarkVertex ("right_tragus")}, 35.0},
          {"chin", ibugVertices (ict, 6, 10), 25.0},
          {"cheeks", {nearestToCentroid (ict, {36, 48, 2}), nearestToCentroid (ict, {45, 54, 14})}, 30.0}};
}

MorphableModel::Ptr
buildIctRegionModel (const MorphableModel& ict, int samples, std::uint64_t seed, const ModelBuilderSettings& settings)
{
  if (samples < 2)
    throw InvalidInputError ("buildIctRegionModel: at least two samples are needed, got " + std::to_string (samples));
  requireMemory (ModelBuilder::memoryEstimate (static_cast<std::size_t> (samples), ict.numVertices ()),
                 "a model of " + std::to_string (samples) + " samples of the " + std::to_string (ict.numVertices ()) +
                     "-vertex model");
  const TriangleMesh mean = ict.meanMesh ();
  const RegionLabels regions = segmentByLandmarkGroups (mean, ictRegionGroups (ict));
  std::mt19937_64 rng (seed);
  const ComponentSelection all = ict.allComponents ();
  std::vector<TriangleMesh> heads;
  for (int s = 0; s < samples; ++s)
    heads.push_back (ict.generateMesh (ict.sampleCoefficients (rng, all), all));
  MorphableModel::Ptr model = ModelBuilder (settings).build (heads, regions);
  model->setLandmarks (ict.landmarks ());
  model->setProfileLine (ict.profileLine ());
  model->setUnits (ict.units ());
  auto metadata = model->metadata ();
  metadata["source"] = "buildIctRegionModel: " + std::to_string (samples) + " samples of " +
                       (ict.metadata ().count ("source") ? ict.metadata ().at ("source") : std::string ("a model"));
  model->setMetadata (metadata);
  return model;
}

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/io/model_description.h>
#include <morphreg/io/model_io.h>

#include <vector>

namespace morphreg
{
namespace
{
std::vector<double>
toStdVector (const Eigen::VectorXd& values)
{
  return std::vector<double> (values.data (), values.data () + values.size ());
}
} // namespace

nlohmann::json
describeModel (const MorphableModel& model, const std::string& file)
{
  nlohmann::json regions = nlohmann::json::array ();
  for (const ModelRegion& region : model.regions ())
    regions.push_back ({{"name", region.name},
                        {"vertices", region.vertices.size ()},
                        {"components", region.variances.size ()},
                        {"variances_mm2", toStdVector (region.variances)}});
  const auto file_units = model.metadata ().find (kFileUnitsKey);
  return {
      {"file", file},
      {"units", model.units ()},
      {"file_units", file_units == model.metadata ().end () ? std::string ("mm") : file_units->second},
      {"vertices", model.numVertices ()},
      {"triangles", model.triangles ().cols ()},
      {"regions", regions},
      {"global_pca",
       {{"components", model.globalVariances ().size ()}, {"variances_mm2", toStdVector (model.globalVariances ())}}},
      {"noise_variance_mm2", model.noiseVariance ()},
      {"profile_line_vertices", model.profileLine ().size ()},
      {"landmarks", model.landmarks ()},
      {"metadata", model.metadata ()}};
}
} // namespace morphreg

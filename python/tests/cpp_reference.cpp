// SPDX-License-Identifier: BSD-3-Clause
// The C++ API's answers to the Python tests' requests, for their equality checks: reads a request (JSON) and writes
// the results (JSON doubles keep every digit). Usage: morphreg_python_reference request.json result.json
// Each key of the request present is answered under the same key:
//   "tps":       {"source", "target", "points": [[x, y, z], ...], "regularization"}  -> the warped points
//   "mls":       {"source", "target", "points", "falloff"}                          -> the warped points
//   "model":     {"path", "coefficients", "components", "seed"}                     -> "instance", "sample"
//   "head":      {"resolution", "seed"}                                            -> "vertices"
//   "scan":      {"resolution", "head_seed", "seed", "angular_samples", "row_spacing"} -> "points", "normals"
//   "segmented": {"vertices", "faces", "labels", "num_segments", "source", "target", "overlap", "blend_width"}
//                                                                                  -> the warped vertices
#include <morphreg/common/cloud_matrix.h>
#include <morphreg/io/json_file.h>
#include <morphreg/io/model_io.h>
#include <morphreg/synthetic/head_generator.h>
#include <morphreg/synthetic/scan_simulator.h>
#include <morphreg/warp/moving_least_squares_warp.h>
#include <morphreg/warp/segmented_warp.h>
#include <morphreg/warp/thin_plate_spline.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <iostream>
#include <random>

namespace
{
using nlohmann::json;

Eigen::Matrix3Xd
points (const json& rows)
{
  Eigen::Matrix3Xd matrix (3, rows.size ());
  for (std::size_t i = 0; i < rows.size (); ++i)
    for (int k = 0; k < 3; ++k)
      matrix (k, i) = rows[i][k].get<double> ();
  return matrix;
}

json
rows (const Eigen::Matrix3Xd& matrix)
{
  json list = json::array ();
  for (Eigen::Index i = 0; i < matrix.cols (); ++i)
    list.push_back ({matrix (0, i), matrix (1, i), matrix (2, i)});
  return list;
}

json
thinPlateSpline (const json& request)
{
  morphreg::ThinPlateSpline<double, 3> spline;
  spline.setRegularization (request["regularization"].get<double> ());
  spline.fit (points (request["source"]), points (request["target"]));
  return rows (spline.evaluate (points (request["points"])));
}

json
movingLeastSquares (const json& request)
{
  morphreg::MovingLeastSquaresWarp warp;
  warp.setFalloff (request["falloff"].get<double> ());
  warp.setLandmarks (points (request["source"]), points (request["target"]));
  return rows (warp.transformPoints (points (request["points"])));
}

json
model (const json& request)
{
  const auto loaded = morphreg::loadModel (request["path"].get<std::string> ());
  const auto selection = loaded->firstComponents (request["components"].get<int> ());
  const auto coefficients = request["coefficients"].get<std::vector<double>> ();
  std::mt19937_64 rng (request["seed"].get<std::uint64_t> ());
  return {{"instance", rows (loaded->generate (
                           Eigen::Map<const Eigen::VectorXd> (coefficients.data (), coefficients.size ()), selection))},
          {"sample", rows (loaded->generate (loaded->sampleCoefficients (rng, selection), selection))}};
}

json
scan (const json& request)
{
  const morphreg::synthetic::HeadGenerator generator (request["resolution"].get<int> ());
  morphreg::synthetic::ScanSimulator::Parameters parameters;
  parameters.angular_samples = request["angular_samples"].get<int> ();
  parameters.row_spacing = request["row_spacing"].get<double> ();
  const auto head = generator.sample (request["head_seed"].get<std::uint64_t> ());
  const auto simulated =
      morphreg::synthetic::ScanSimulator (parameters).scan (head.mesh, request["seed"].get<std::uint64_t> ());
  return {{"points", rows (morphreg::pointsOf (*simulated.cloud))},
          {"normals", rows (morphreg::normalsOf (*simulated.cloud))}};
}

json
segmented (const json& request)
{
  morphreg::TriangleMesh mesh;
  mesh.vertices = points (request["vertices"]);
  const auto faces = request["faces"];
  mesh.triangles.resize (3, faces.size ());
  for (std::size_t i = 0; i < faces.size (); ++i)
    for (int k = 0; k < 3; ++k)
      mesh.triangles (k, i) = faces[i][k].get<int> ();
  morphreg::SegmentedWarp warp (request["labels"].get<std::vector<int>> (), request["num_segments"].get<int> ());
  warp.setBlendWidth (request["blend_width"].get<double> ());
  warp.setLandmarks (mesh, points (request["source"]), points (request["target"]),
                     request["overlap"].get<std::vector<double>> ());
  return rows (warp.warp (mesh).vertices);
}
} // namespace

int
main (int argc, char** argv)
{
  if (argc != 3) {
    std::cerr << "usage: morphreg_python_reference request.json result.json\n";
    return 2;
  }
  const json request = json::parse (std::ifstream (argv[1]));
  json result = json::object ();
  if (request.contains ("tps"))
    result["tps"] = thinPlateSpline (request["tps"]);
  if (request.contains ("mls"))
    result["mls"] = movingLeastSquares (request["mls"]);
  if (request.contains ("model"))
    result["model"] = model (request["model"]);
  if (request.contains ("head"))
    result["head"] = rows (morphreg::synthetic::HeadGenerator (request["head"]["resolution"].get<int> ())
                               .sample (request["head"]["seed"].get<std::uint64_t> ())
                               .mesh.vertices);
  if (request.contains ("scan"))
    result["scan"] = scan (request["scan"]);
  if (request.contains ("segmented"))
    result["segmented"] = segmented (request["segmented"]);
  morphreg::writeJsonFile (argv[2], result);
  return 0;
}

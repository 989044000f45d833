// SPDX-License-Identifier: BSD-3-Clause
// check_unit_estimate ORIGINAL_FIT.ply ESTIMATED_FIT.ply TRUE_SCALE BOUND: passes (exit 0) when register estimated the
// unit of a scan in an arbitrary unit from its head as its fit of the original (mm) says the head is: both reports
// (next to the meshes, .json) ok, the second's unit "estimated" with scale_to_mm F; F / TRUE_SCALE (mm per unit of the
// file as read) times the original fit's similarity scale within 2 % of 1 (the head is taken at the model's size,
// which the original's fit measures; F itself is off by the head's size against the model, within 15 %); and the
// estimated fit, brought into the original's frame (times TRUE_SCALE / F), a face median (ICT's first 9409 vertices)
// of at most BOUND mm from the original fit.
#include <morphreg/io/mesh_io.h>

#include <nlohmann/json.hpp>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
nlohmann::json
reportOf (const std::string& mesh)
{
  std::ifstream in (std::filesystem::path (mesh).replace_extension (".json"));
  return nlohmann::json::parse (in);
}

/** The median distance between the first 9409 vertices (ICT's face) of \a a and \a b. */
double
faceMedian (const Eigen::Matrix3Xd& a, const Eigen::Matrix3Xd& b)
{
  const Eigen::Index count = std::min<Eigen::Index> (9409, a.cols ());
  const Eigen::VectorXd distances = (a.leftCols (count) - b.leftCols (count)).colwise ().norm ().transpose ();
  std::vector<double> sorted (distances.data (), distances.data () + distances.size ());
  std::nth_element (sorted.begin (), sorted.begin () + sorted.size () / 2, sorted.end ());
  return sorted[sorted.size () / 2];
}

int
check (const std::string& original_fit, const std::string& estimated_fit, double true_scale, double bound)
{
  const nlohmann::json original = reportOf (original_fit), estimated = reportOf (estimated_fit);
  if (original.at ("status") != "ok" || estimated.at ("status") != "ok" ||
      estimated.at ("scan").at ("units") != "estimated") {
    std::cerr << "expected two fits with status ok, the second's unit estimated; got " << original.at ("status") << ", "
              << estimated.at ("status") << " " << estimated.at ("scan").at ("units") << "\n";
    return 1;
  }
  const double factor = estimated.at ("scan").at ("scale_to_mm").get<double> () / true_scale;
  const double head_scale = original.at ("similarity").at ("scale").get<double> ();
  const morphreg::TriangleMesh a = morphreg::loadTriangleMesh (original_fit);
  const morphreg::TriangleMesh b = morphreg::loadTriangleMesh (estimated_fit);
  const double median = a.vertices.cols () == b.vertices.cols () ? faceMedian (a.vertices, b.vertices / factor) : -1.0;
  std::cout << "estimated scale over the true " << factor << ", times the original fit's scale " << head_scale << ": "
            << factor * head_scale << "; face median from the original fit " << median << " mm (bound " << bound
            << ")\n";
  const bool ok = std::abs (factor * head_scale - 1.0) <= 0.02 && std::abs (factor - 1.0) <= 0.15 && median >= 0.0 &&
                  median <= bound;
  if (!ok)
    std::cerr << "check_unit_estimate: " << estimated_fit << " is not the original's fit at an estimated scale\n";
  return ok ? 0 : 1;
}
} // namespace

int
main (int argc, char** argv)
{
  if (argc != 5) {
    std::cerr << "usage: check_unit_estimate ORIGINAL_FIT.ply ESTIMATED_FIT.ply TRUE_SCALE BOUND\n";
    return 2;
  }
  try {
    return check (argv[1], argv[2], std::stod (argv[3]), std::stod (argv[4]));
  }
  catch (const std::exception& e) {
    std::cerr << "check_unit_estimate: " << e.what () << "\n";
    return 1;
  }
}

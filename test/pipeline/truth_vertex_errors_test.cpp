// SPDX-License-Identifier: BSD-3-Clause
// A fit's vertex errors against the true mesh (truthVertexErrors), over every vertex and over those the scan covers.
#include <morphreg/common/error.h>
#include <morphreg/io/mesh_io.h>
#include <morphreg/pipeline/scan_file_registration.h>

#include "support/expect_error.h"
#include "support/synthetic_heads.h"
#include "support/temp_directory.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
TEST (TruthVertexErrorsTest, EveryVertexAndTheCoveredOnesAgainstTheTrueMesh)
{
  const morphreg::test::TempDirectory dir;
  const morphreg::TriangleMesh truth = morphreg::test::headGenerator (20).sample (2).mesh;
  morphreg::saveTriangleMesh (dir.file ("truth.ply"), truth);
  morphreg::TriangleMesh fitted = truth;
  Eigen::VectorXd residuals = Eigen::VectorXd::Zero (truth.numVertices ());
  const Eigen::Index half = truth.numVertices () / 2;
  fitted.vertices.leftCols (half).row (0).array () += 2.0; // the uncovered half 2 mm off
  residuals.head (half).setConstant (NAN);
  const nlohmann::json errors = morphreg::truthVertexErrors (fitted, residuals, dir.file ("truth.ply"));
  EXPECT_NEAR (errors["max"].get<double> (), 2.0, 1e-5);
  EXPECT_NEAR (errors["rms"].get<double> (), std::sqrt (4.0 * half / truth.numVertices ()), 1e-5);
  EXPECT_EQ (errors["covered_by_scan"]["count"], truth.numVertices () - half);
  EXPECT_NEAR (errors["covered_by_scan"]["max"].get<double> (), 0.0, 1e-5);
  EXPECT_EQ (errors["file"], dir.file ("truth.ply"));

  morphreg::saveTriangleMesh (dir.file ("other.ply"), morphreg::test::headGenerator (24).sample (2).mesh);
  morphreg::test::expectErrorContaining<morphreg::InvalidInputError> (
      [&] { morphreg::truthVertexErrors (fitted, residuals, dir.file ("other.ply")); }, dir.file ("other.ply"));
}
} // namespace

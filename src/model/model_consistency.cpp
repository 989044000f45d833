// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/model/model_consistency.h>

#include <cmath>
#include <sstream>

namespace morphreg
{
namespace
{
/** FormatError unless the columns of \a basis are orthonormal to 10^-3; \a part names it. */
void
requireOrthonormal (const Eigen::MatrixXd& basis, const std::string& source, const std::string& part)
{
  if (basis.cols () == 0)
    return;
  const Eigen::MatrixXd gram = basis.transpose () * basis;
  Eigen::Index row = 0, col = 0;
  const double error =
      (gram - Eigen::MatrixXd::Identity (gram.rows (), gram.cols ())).cwiseAbs ().maxCoeff (&row, &col);
  if (!(error <= 1e-3)) {
    std::ostringstream text;
    text << source << ": " << part << " is not orthonormal: ";
    if (row == col)
      text << "column " << row << " has length " << std::sqrt (gram (row, row)) << ", not 1";
    else
      text << "columns " << row << " and " << col << " have the dot product " << gram (row, col) << ", not 0";
    throw FormatError (text.str () + " (a corrupt or rescaled model file)");
  }
}

void
requireSaneTopology (const MorphableModel& model, const std::string& source)
{
  const TriangleMesh::Triangles& triangles = model.triangles ();
  for (Eigen::Index t = 0; t < triangles.cols (); ++t) {
    const Eigen::Vector3i corners = triangles.col (t);
    if (corners[0] == corners[1] || corners[1] == corners[2] || corners[0] == corners[2])
      throw FormatError (source + ": triangle " + std::to_string (t) + " (" + std::to_string (corners[0]) + ", " +
                         std::to_string (corners[1]) + ", " + std::to_string (corners[2]) +
                         ") repeats a vertex (a corrupt topology)");
  }
}
} // namespace

void
requireConsistentModel (const MorphableModel& model, const std::string& source)
{
  Eigen::Index at = 0;
  const double largest = model.mean ().size () ? model.mean ().cwiseAbs ().maxCoeff (&at) : 0.0;
  if (largest > kMaxModelCoordinate) {
    std::ostringstream text;
    text << source << ": the mean's vertex " << at / 3 << " has the coordinate " << model.mean ()[at]
         << ", beyond +-1e6 in any unit (a corrupt model file)";
    throw FormatError (text.str ());
  }
  requireSaneTopology (model, source);
  for (int j = 0; j < model.numRegions (); ++j)
    requireOrthonormal (model.region (j).basis, source, "the basis of region '" + model.region (j).name + "'");
  requireOrthonormal (model.globalBasis (), source, "the global basis");
}

void
requireSameMean (const Eigen::VectorXd& mean, const Eigen::VectorXd& copy, const std::string& source,
                 const std::string& names)
{
  if (copy.size () != mean.size ())
    throw FormatError (source + ": " + names + " hold different numbers of coordinates");
  const Eigen::ArrayXd allowed = (1e-6 * mean.array ().abs ()).max (1e-5);
  Eigen::Index at = 0;
  const double worst = ((mean - copy).array ().abs () / allowed).maxCoeff (&at);
  if (worst > 1.0) {
    std::ostringstream text;
    text << source << ": " << names << " disagree at vertex " << at / 3 << " (" << mean[at] << " and " << copy[at]
         << "): the file is corrupt (a flipped bit?)";
    throw FormatError (text.str ());
  }
}

} // namespace morphreg

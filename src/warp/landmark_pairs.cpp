// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/warp/impl/landmark_pairs.h>

#include <Eigen/SVD>

#include <algorithm>
#include <numeric>
#include <sstream>
#include <vector>

namespace morphreg
{
namespace detail
{
double
boundingBoxDiagonal (const Eigen::MatrixXd& points)
{
  return (points.rowwise ().maxCoeff () - points.rowwise ().minCoeff ()).norm ();
}

namespace
{
/** Landmarks closer than this fraction of their extent are one landmark (equal up to round-off). */
constexpr double kCoincidenceTolerance = 1e-12;
/** Source landmarks whose thinnest spread is below this fraction of the widest are flat (coplanar/collinear). */
constexpr double kFlatnessTolerance = 1e-9;

void
requireLandmarkPairs (const Eigen::MatrixXd& source, const Eigen::MatrixXd& target, const std::string& caller,
                      const std::string& method)
{
  std::ostringstream msg;
  msg << caller << ": ";
  if (source.rows () != target.rows ())
    msg << "source landmarks are " << source.rows () << "-dimensional but targets are " << target.rows ()
        << "-dimensional";
  else if (source.cols () != target.cols ())
    msg << "mismatched landmark counts: " << source.cols () << " source landmarks but " << target.cols () << " targets";
  else if (source.rows () != 2 && source.rows () != 3)
    msg << source.rows () << "-dimensional landmarks; a " << method << " here is 2D or 3D";
  else if (source.cols () == 0)
    msg << "no landmarks given";
  else {
    for (Eigen::Index i = 0; i < source.cols (); ++i)
      if (!source.col (i).allFinite () || !target.col (i).allFinite ()) {
        msg << (source.col (i).allFinite () ? "target" : "source") << " landmark " << i
            << " is not finite (NaN or Inf)";
        throw InvalidInputError (msg.str ());
      }
    return;
  }
  throw InvalidInputError (msg.str ());
}

/** Indices of the landmark pairs to keep: coincident sources with coincident targets are merged (the first
 *  kept); coincident sources with different targets are an InvalidInputError.
 */
std::vector<Eigen::Index>
distinctLandmarks (const Eigen::MatrixXd& source, const Eigen::MatrixXd& target, const std::string& caller,
                   const std::string& method)
{
  const Eigen::Index n = source.cols ();
  const double source_tolerance = kCoincidenceTolerance * boundingBoxDiagonal (source);
  const double target_tolerance =
      kCoincidenceTolerance * std::max (boundingBoxDiagonal (target), boundingBoxDiagonal (source));
  std::vector<Eigen::Index> order (n);
  std::iota (order.begin (), order.end (), Eigen::Index (0));
  std::sort (order.begin (), order.end (),
             [&] (Eigen::Index a, Eigen::Index b) { return source (0, a) < source (0, b); });
  std::vector<bool> dropped (n, false);
  for (Eigen::Index a = 0; a < n; ++a)
    for (Eigen::Index b = a + 1; b < n && source (0, order[b]) - source (0, order[a]) <= source_tolerance; ++b) {
      const Eigen::Index i = std::min (order[a], order[b]), j = std::max (order[a], order[b]);
      if ((source.col (i) - source.col (j)).norm () > source_tolerance)
        continue;
      if ((target.col (i) - target.col (j)).norm () > target_tolerance) {
        std::ostringstream msg;
        msg << caller << ": source landmarks " << i << " and " << j << " coincide but their targets differ by "
            << (target.col (i) - target.col (j)).norm () << "; a " << method << " cannot map one point to two";
        throw InvalidInputError (msg.str ());
      }
      dropped[j] = true;
    }
  std::vector<Eigen::Index> kept;
  for (Eigen::Index i = 0; i < n; ++i)
    if (!dropped[i])
      kept.push_back (i);
  return kept;
}

/** Throws unless the (merged) source landmarks are enough and span the whole space (not coplanar/collinear);
 *  returns the widest / thinnest spread, the conditioning of the affine part.
 */
double
requireAffineSpan (const Eigen::MatrixXd& landmarks, Eigen::Index merged, const std::string& caller,
                   const std::string& method)
{
  const Eigen::Index n = landmarks.rows (), d = landmarks.cols ();
  std::ostringstream msg;
  msg << caller << ": ";
  if (n < d + 1) {
    msg << "only " << n << " distinct landmark(s)";
    if (merged > 0)
      msg << " (after merging " << merged << " duplicate(s))";
    msg << "; a " << d << "D " << method << " needs at least " << d + 1 << " not all "
        << (d == 3 ? "coplanar" : "collinear");
    throw InvalidInputError (msg.str ());
  }
  const Eigen::MatrixXd centred = landmarks.rowwise () - landmarks.colwise ().mean ();
  const Eigen::VectorXd spread = Eigen::JacobiSVD<Eigen::MatrixXd> (centred).singularValues ();
  const Eigen::Index rank = (spread.array () > kFlatnessTolerance * spread[0]).count ();
  if (rank == d)
    return spread[0] / spread[d - 1];
  msg << "all " << n << " source landmarks are " << (rank == d - 1 && d == 3 ? "coplanar" : "collinear")
      << " (thinnest/widest spread " << spread[d - 1] / spread[0] << "); a " << d << "D " << method
      << " needs landmarks that span " << d << "D";
  throw InvalidInputError (msg.str ());
}

} // namespace

LandmarkPairs
distinctLandmarkPairs (const Eigen::MatrixXd& source, const Eigen::MatrixXd& target, const std::string& caller,
                       const std::string& method)
{
  requireLandmarkPairs (source, target, caller, method);
  const std::vector<Eigen::Index> kept = distinctLandmarks (source, target, caller, method);
  LandmarkPairs pairs;
  pairs.source.resize (static_cast<Eigen::Index> (kept.size ()), source.rows ());
  pairs.target.resize (pairs.source.rows (), source.rows ());
  for (std::size_t i = 0; i < kept.size (); ++i) {
    pairs.source.row (static_cast<Eigen::Index> (i)) = source.col (kept[i]).transpose ();
    pairs.target.row (static_cast<Eigen::Index> (i)) = target.col (kept[i]).transpose ();
  }
  pairs.merged = source.cols () - pairs.source.rows ();
  pairs.affine_condition = requireAffineSpan (pairs.source, pairs.merged, caller, method);
  return pairs;
}

} // namespace detail
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
// Approach 2, TPS-ICP (docs/method.md, "TPS-ICP"): after the profile fit, rounds of a thin plate spline warp of the
// posed model onto the photos' targets and a 3D-3D fit of the model to the warped mesh.
#include <morphreg/common/error.h>
#include <morphreg/photo/photo_fit_method.h>
#include <morphreg/warp/thin_plate_spline.h>

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace morphreg
{
namespace
{
/** At most this many rounds of TPS warp and 3D-3D fit. */
constexpr int kTpsIcpRounds = 10;

/** How far (model mm) from its nearest anchor a warped vertex is trusted: the weight of its row falls off as a
 *  Gaussian of that distance with this sigma, about the spacing of the frontal landmarks. */
constexpr double kWarpTrustSigma = 15.0;

/** Per model vertex with image rows: the weighted least-squares point of their targets (the marks and outline
 *  points at the vertex's current depth), and the largest isotropic weight of its landmark rows. */
struct Anchors
{
  std::map<int, Eigen::Vector3d> points;
  std::map<int, double> landmark_weights;
};

Anchors
anchors (const std::vector<PoseShapeRow>& rows, const std::vector<PhotoRowKind>& kinds, const Eigen::Matrix3Xd& posed)
{
  std::map<int, std::pair<Eigen::Matrix3d, Eigen::Vector3d>> sums; // sum W, sum W T
  Anchors result;
  for (size_t r = 0; r < rows.size (); ++r) {
    if (kinds[r] == PhotoRowKind::depth)
      continue; // the sagittal plane is no image target: the warp keeps the vertex's depth
    auto& sum =
        sums.emplace (rows[r].slot, std::pair (Eigen::Matrix3d::Zero (), Eigen::Vector3d::Zero ())).first->second;
    sum.first += rows[r].metric;
    sum.second += rows[r].metric * rows[r].target;
    if (kinds[r] == PhotoRowKind::landmark)
      result.landmark_weights[rows[r].slot] =
          std::max (result.landmark_weights[rows[r].slot], 0.5 * rows[r].metric.trace ());
  }
  for (const auto& [vertex, sum] : sums) {
    // The current position with a vanishing weight fixes the directions no row constrains (the depth).
    const double epsilon = 1e-9 * std::max (sum.first.trace (), 1e-300);
    result.points[vertex] =
        (sum.first + epsilon * Eigen::Matrix3d::Identity ()).lu ().solve (sum.second + epsilon * posed.col (vertex));
  }
  return result;
}

/** The weight of each of \a vertices' warped positions: a Gaussian (kWarpTrustSigma) of its distance from the nearest
 *  of \a anchors (both in model mm). The spline interpolates between its anchors and only extrapolates away from
 *  them: far from every anchor (the back of the head, the sides behind a frontal photo's landmarks, the skull under
 *  hair) the model's prior decides. On rendered photos of the real head scan this took TPS-ICP from 0.77x, 0.83x
 *  (hair in the outline) and 0.74x (traced from the hairline) of the mean head's face median to 0.62x, 0.64x, 0.57x,
 *  and the synthetic unseen heads' vertex RMS from 1.33 to 1.26 mm. */
Eigen::VectorXd
warpTrust (const Eigen::Matrix3Xd& vertices, const Eigen::Matrix3Xd& anchors)
{
  Eigen::VectorXd trust (vertices.cols ());
  for (Eigen::Index i = 0; i < vertices.cols (); ++i) {
    const double nearest = (anchors.colwise () - vertices.col (i)).colwise ().squaredNorm ().minCoeff ();
    trust[i] = std::exp (-0.5 * nearest / (kWarpTrustSigma * kWarpTrustSigma));
  }
  return trust;
}

/** The rows of one round, for every model vertex: the posed model warped (in model mm) by a 3D thin plate spline
 *  that moves each anchored vertex to its anchor. The warped vertices guide the parts the photos do not show, each
 *  as far as the warp is trusted there (warpTrust), and share the image rows' total weight; each landmark's anchor
 *  is a point row at its landmark weight, and the outline rows stay, so the fit keeps to the outlines where the
 *  warp's smooth interpolation cannot follow them. */
std::vector<PoseShapeRow>
tpsRows (const std::vector<PoseShapeRow>& image, const std::vector<PhotoRowKind>& kinds, const PoseShapeState& state)
{
  const double s = state.scale ();
  const Eigen::Matrix3Xd posed = state.posed ();
  const Anchors anchored = anchors (image, kinds, posed);
  Eigen::Matrix3Xd source (3, anchored.points.size ()), target (3, anchored.points.size ());
  Eigen::Index column = 0;
  for (const auto& [vertex, point] : anchored.points) {
    source.col (column) = posed.col (vertex) / s;
    target.col (column++) = point / s;
  }
  ThinPlateSpline<double, 3> tps;
  tps.fit (source, target);
  Eigen::Matrix3Xd warped = posed / s;
  const Eigen::VectorXd trust = warpTrust (warped, source);
  tps.transformPositions (warped);
  warped *= s;
  // At weight 1 each the mesh would outweigh the image rows a hundredfold and the fit would follow the warp's
  // extrapolation; sharing their weight keeps the priors weighing as in the joint fit.
  const auto image_rows =
      std::count_if (kinds.begin (), kinds.end (), [] (PhotoRowKind k) { return k != PhotoRowKind::depth; });
  const double share = static_cast<double> (image_rows) / static_cast<double> (warped.cols ()) / (s * s);
  std::vector<PoseShapeRow> rows;
  for (Eigen::Index i = 0; i < warped.cols (); ++i)
    rows.push_back ({static_cast<int> (i), warped.col (i), share * trust[i] * Eigen::Matrix3d::Identity ()});
  for (const auto& [vertex, weight] : anchored.landmark_weights)
    rows.push_back ({vertex, anchored.points.at (vertex), weight * Eigen::Matrix3d::Identity ()});
  for (size_t r = 0; r < image.size (); ++r)
    if (kinds[r] != PhotoRowKind::landmark)
      rows.push_back (image[r]);
  return rows;
}

class TpsIcpFitMethod : public PhotoFitMethod
{
public:
  std::string
  name () const override
  {
    return "tps";
  }

  PhotoRows
  rows () const override
  {
    return PhotoRows::all;
  }

  PhotoFit
  fit (MultiViewProblem& problem, const PoseShapeState& start) const override
  {
    problem.requireLandmarks ();
    // Approach 2 starts from the profile fit; photos without an outline start from the joint fit.
    PhotoFit result = problem.hasOutline () ? photoFitMethod ("profile")->fit (problem, start)
                                            : problem.stagedFit (start, PhotoRows::all, "joint");
    const PoseShapeState best = rounds (problem, fittedState (problem, result), result);
    PhotoFit fit = problem.result (best, PhotoRows::all);
    fit.history = std::move (result.history);
    fit.tps_rounds = result.tps_rounds;
    fit.final_residuals.stage = PhotoFitStage::tps_icp;
    fit.returned = fit.tps_rounds > 0 ? "tps_icp" : result.returned;
    return fit;
  }

private:
  /** The rounds from \a state while the image error falls and the head stays plausible; the best state. */
  static PoseShapeState
  rounds (const MultiViewProblem& problem, PoseShapeState state, PhotoFit& result)
  {
    const PoseShapeLeastSquares& solver = problem.solver (true);
    PoseShapeState best = state;
    double best_error = std::numeric_limits<double>::infinity ();
    for (int round = 0;; ++round) {
      PhotoFitIteration iteration;
      iteration.stage = PhotoFitStage::tps_icp;
      std::vector<PhotoRowKind> kinds;
      const std::vector<PoseShapeRow> image = problem.rows (state, PhotoRows::all, {}, iteration, &kinds);
      const double error = problem.imageError (iteration);
      if (!(error < best_error) || !isPlausibleShape (state.coefficients.cwiseQuotient (solver.sigma ())))
        break; // no better in the photos, or a head the model's population does not hold
      best = state;
      best_error = error;
      result.tps_rounds = round;
      result.history.push_back (iteration);
      if (round == kTpsIcpRounds)
        break;
      const std::vector<PoseShapeRow> rows = tpsRows (image, kinds, state);
      for (int it = 0; it < problem.settings ().shape_iterations; ++it) {
        const Eigen::Matrix3Xd before = state.posed ();
        if (!solver.step (state, rows))
          throw NumericalError ("PhotoFitting: the TPS-ICP normal equations could not be solved");
        if (MultiViewProblem::converged (before, state))
          break;
      }
    }
    return best;
  }
};
} // namespace

PhotoFitMethod::ConstPtr
makeTpsIcpFitMethod ()
{
  return std::make_shared<TpsIcpFitMethod> ();
}
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/common/error.h>
#include <morphreg/fitting/pose_shape_least_squares.h>

#include <Eigen/Cholesky>
#include <Eigen/Geometry>

#include <array>
#include <cmath>

namespace morphreg
{
namespace
{
/** Rows below which summing the normal equations is not worth an OpenMP fork-join. */
constexpr size_t kParallelRows = 1024;

Eigen::Matrix3d
skew (const Eigen::Vector3d& v)
{
  Eigen::Matrix3d s;
  s << 0, -v.z (), v.y (), v.z (), 0, -v.x (), -v.y (), v.x (), 0;
  return s;
}

/** 3 x 7 Jacobian of s R x + t at \a rotated = s R x with respect to (log s, a rotation increment theta applied as
 *  exp([theta]_x) R, t). */
Eigen::Matrix<double, 3, 7>
similarityJacobian (const Eigen::Vector3d& rotated)
{
  Eigen::Matrix<double, 3, 7> jacobian;
  jacobian.col (0) = rotated;
  jacobian.middleCols<3> (1) = -skew (rotated);
  jacobian.rightCols<3> ().setIdentity ();
  return jacobian;
}

/** Applies the update \a d of similarityJacobian's parameters; the rotation is re-orthonormalised. */
void
updateSimilarity (const Eigen::Matrix<double, 7, 1>& d, PoseShapeState& state)
{
  state.log_scale += d[0];
  const Eigen::Vector3d theta = d.segment<3> (1);
  const double angle = theta.norm ();
  if (angle > 0.0)
    state.rotation = Eigen::AngleAxisd (angle, theta / angle).toRotationMatrix () * state.rotation;
  state.rotation = Eigen::Quaterniond (state.rotation).normalized ().toRotationMatrix ();
  state.translation += d.tail<3> ();
}
} // namespace

void
PoseShapeSettings::validate (const std::string& who) const
{
  requirePriorWeight (smoothness_weight, who + ": lambda_1");
  requirePriorWeight (prior_weight, who + ": lambda_2");
  if (!(max_step_sigma > 0.0) || !(coefficient_limit > 0.0))
    throw InvalidInputError (who + ": the trust region and the coefficient limit must be > 0 standard deviations");
}

double
requirePriorWeight (double weight, const std::string& what)
{
  if (!(weight >= 0.0) || !std::isfinite (weight))
    throw InvalidInputError (what + " must be finite and >= 0, got " + std::to_string (weight));
  return weight;
}

void
requireEnoughRows (size_t rows, size_t needed, const std::string& who, const std::string& counts,
                   const std::string& hint)
{
  if (rows < needed)
    throw TooFewCorrespondencesError (who + ": only " + std::to_string (rows) + " rows (" + counts + "), at least " +
                                      std::to_string (needed) + " are needed; check " + hint);
}

double
PoseShapeState::scale () const
{
  return std::exp (log_scale);
}

Eigen::Matrix3Xd
PoseShapeState::posed () const
{
  return (scale () * rotation * vertices).colwise () + translation;
}

Eigen::Matrix4d
PoseShapeState::similarity () const
{
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity ();
  m.topLeftCorner<3, 3> () = scale () * rotation;
  m.topRightCorner<3, 1> () = translation;
  return m;
}

PoseShapeLeastSquares::PoseShapeLeastSquares (bool estimate_scale)
{
  settings_.estimate_scale = estimate_scale;
}

PoseShapeLeastSquares::PoseShapeLeastSquares (const MorphableModel& model, std::vector<int> slots,
                                              const PoseShapeSettings& settings)
  : model_ (&model), slots_ (std::move (slots)), settings_ (settings)
{
  settings_.validate ("PoseShapeLeastSquares");
  if (settings_.components.numRegions () == 0)
    settings_.components = model.firstComponents (0);
  model.requireCompatible (settings_.components, nullptr, "PoseShapeLeastSquares");
  all_vertices_ = slots_.empty ();
  if (all_vertices_) {
    slots_.resize (static_cast<size_t> (model.numVertices ()));
    for (size_t i = 0; i < slots_.size (); ++i)
      slots_[i] = static_cast<int> (i);
  }
  const ComponentSelection& selection = settings_.components;
  sigma_ = model.variances (selection).cwiseSqrt ();
  const MorphableModel::RowMatrix gamma = model.gammaMatrix (selection);
  const double lambda1 = settings_.smoothness_weight, lambda2 = settings_.prior_weight;
  prior_ = lambda1 * lambda1 * (gamma.transpose () * gamma);
  prior_.diagonal () += lambda2 * lambda2 * model.lambdaDiagonal (selection, settings_.prior).cwiseAbs2 ();
  for (int r = 0; r < selection.numRegions (); ++r)
    max_columns_ += selection.count (r);
}

Eigen::Matrix3Xd
PoseShapeLeastSquares::vertices (const Eigen::VectorXd& coefficients) const
{
  const ComponentSelection& selection = settings_.components;
  if (all_vertices_)
    return model_->generate (coefficients, selection);
  Eigen::Matrix3Xd positions (3, static_cast<Eigen::Index> (slots_.size ()));
  for (size_t k = 0; k < slots_.size (); ++k) {
    Eigen::Vector3d p = model_->meanVertex (slots_[k]);
    for (const RegionEntry& e : model_->vertexEntries (slots_[k])) {
      const int count = selection.count (e.region);
      if (count > 0)
        p += e.weight *
             (model_->regionRows (e.region, e.row, count) * coefficients.segment (selection.offset (e.region), count));
    }
    positions.col (static_cast<Eigen::Index> (k)) = p;
  }
  return positions;
}

PoseShapeState
PoseShapeLeastSquares::state (const Eigen::Matrix4d& similarity, const Eigen::VectorXd& coefficients) const
{
  const Eigen::Matrix3d linear = similarity.topLeftCorner<3, 3> ();
  const double scale = std::cbrt (linear.determinant ());
  PoseShapeState state;
  state.log_scale = std::log (scale);
  state.rotation = Eigen::Quaterniond (Eigen::Matrix3d (linear / scale)).normalized ().toRotationMatrix ();
  state.translation = similarity.topRightCorner<3, 1> ();
  state.selection = settings_.components;
  state.coefficients = coefficients;
  if (model_)
    state.vertices = vertices (coefficients);
  return state;
}

double
PoseShapeLeastSquares::cost (const PoseShapeState& state, const std::vector<PoseShapeRow>& rows,
                             double inverse_scale2) const
{
  const Eigen::Matrix3d sr = state.scale () * state.rotation;
  double sum = 0.0;
  // Serial: a few microseconds per thousand rows, less than an OpenMP fork-join costs on a busy machine.
  for (const PoseShapeRow& row : rows) {
    const Eigen::Vector3d r = row.target - sr * state.vertices.col (row.slot) - state.translation;
    sum += r.dot (row.metric * r);
  }
  if (settings_.model_units)
    sum *= inverse_scale2 > 0.0 ? inverse_scale2 : 1.0 / (state.scale () * state.scale ());
  if (hasShape ())
    sum += state.coefficients.dot (prior_ * state.coefficients);
  return sum;
}

void
PoseShapeLeastSquares::normalEquations (const PoseShapeState& state, const std::vector<PoseShapeRow>& rows,
                                        double inverse_scale2, Eigen::MatrixXd& hessian,
                                        Eigen::VectorXd& gradient) const
{
  const ComponentSelection& selection = settings_.components;
  const bool shape = hasShape ();
  const Eigen::Index dim = hessian.rows ();
  const Eigen::Matrix3d sr = state.scale () * state.rotation;
  const double row_scale = settings_.model_units ? inverse_scale2 : 1.0;
  const auto count_rows = static_cast<long> (rows.size ());
#pragma omp parallel if (shape && rows.size() >= kParallelRows)
  {
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero (dim, dim);
    Eigen::VectorXd g = Eigen::VectorXd::Zero (dim);
    Eigen::Matrix<double, 3, Eigen::Dynamic> jacobian (3, max_columns_), weighted (3, max_columns_);
    Eigen::MatrixXd block (max_columns_, max_columns_);
    Eigen::VectorXd rhs (max_columns_);
    // Column ranges of one row's Jacobian: {first local column, first unknown, count}; the similarity first.
    std::vector<std::array<int, 3>> ranges;
#pragma omp for schedule(static) nowait
    for (long c = 0; c < count_rows; ++c) {
      const PoseShapeRow& row = rows[static_cast<size_t> (c)];
      const Eigen::Vector3d rotated = sr * state.vertices.col (row.slot);
      const Eigen::Vector3d residual = row.target - rotated - state.translation;
      jacobian.leftCols<7> () = similarityJacobian (rotated);
      ranges.assign (1, {0, 0, 7});
      int k = 7;
      if (shape)
        for (const RegionEntry& e : model_->vertexEntries (slots_[static_cast<size_t> (row.slot)])) {
          const int count = selection.count (e.region);
          if (count == 0)
            continue;
          jacobian.middleCols (k, count).noalias () = (e.weight * sr) * model_->regionRows (e.region, e.row, count);
          ranges.push_back ({k, 7 + selection.offset (e.region), count});
          k += count;
        }
      // J^T W J and J^T W r, coefficient-wise (no GEMM dispatch for these small sizes), added block by block.
      weighted.leftCols (k).noalias () = (row_scale * row.metric) * jacobian.leftCols (k);
      block.topLeftCorner (k, k).noalias () = weighted.leftCols (k).transpose ().lazyProduct (jacobian.leftCols (k));
      rhs.head (k).noalias () = weighted.leftCols (k).transpose () * residual;
      for (const auto& a : ranges) {
        g.segment (a[1], a[2]) += rhs.segment (a[0], a[2]);
        for (const auto& b : ranges)
          h.block (a[1], b[1], a[2], b[2]) += block.block (a[0], b[0], a[2], b[2]);
      }
    }
#pragma omp critical
    {
      hessian += h;
      gradient += g;
    }
  }
}

bool
PoseShapeLeastSquares::solve (const PoseShapeState& state, Eigen::MatrixXd& hessian, Eigen::VectorXd& gradient,
                              Eigen::VectorXd& delta) const
{
  const Eigen::Index p = sigma_.size ();
  if (hasShape ()) {
    hessian.bottomRightCorner (p, p) += prior_;
    gradient.tail (p) -= prior_ * state.coefficients;
  }
  const auto hold = [&hessian, &gradient] (Eigen::Index k) {
    const double diagonal = hessian (k, k);
    hessian.row (k).setZero ();
    hessian.col (k).setZero ();
    hessian (k, k) = diagonal > 0.0 ? diagonal : 1.0;
    gradient[k] = 0.0;
  };
  if (!settings_.estimate_scale)
    hold (0);
  // Active set: a coefficient at the limit that the descent pushes further out keeps its value, so the projection
  // onto the limit cannot undo the rest of the step.
  if (std::isfinite (settings_.coefficient_limit))
    for (Eigen::Index i = 0; i < p; ++i)
      if (std::abs (state.coefficients[i]) >= (1.0 - 1e-9) * settings_.coefficient_limit * sigma_[i] &&
          gradient[7 + i] * state.coefficients[i] > 0.0)
        hold (7 + i);
  hessian.diagonal ().array () += 1e-12 * std::max (1.0, hessian.diagonal ().maxCoeff ());
  const Eigen::LDLT<Eigen::MatrixXd> solver (hessian);
  delta = solver.solve (gradient);
  return solver.info () == Eigen::Success && delta.allFinite ();
}

Eigen::VectorXd
PoseShapeLeastSquares::limitStep (const PoseShapeState& state, Eigen::VectorXd& delta) const
{
  const Eigen::Index p = sigma_.size ();
  if (p == 0)
    return Eigen::VectorXd ();
  const double largest = delta.tail (p).cwiseQuotient (sigma_).cwiseAbs ().maxCoeff ();
  if (largest > settings_.max_step_sigma)
    delta *= settings_.max_step_sigma / largest;
  Eigen::VectorXd change = delta.tail (p).cwiseQuotient (sigma_);
  if (settings_.damp_reversals && state.last_step.size () == p && change.dot (state.last_step) < 0.0) {
    change *= 0.5;
    delta.tail (p) *= 0.5;
  }
  return change;
}

PoseShapeState
PoseShapeLeastSquares::moved (const PoseShapeState& state, const Eigen::VectorXd& delta) const
{
  PoseShapeState candidate = state;
  updateSimilarity (delta.head<7> (), candidate);
  if (hasShape ()) {
    candidate.coefficients += delta.tail (sigma_.size ());
    if (std::isfinite (settings_.coefficient_limit)) {
      const Eigen::VectorXd bound = settings_.coefficient_limit * sigma_;
      candidate.coefficients = candidate.coefficients.cwiseMin (bound).cwiseMax (-bound);
    }
    candidate.vertices = vertices (candidate.coefficients);
  }
  return candidate;
}

bool
PoseShapeLeastSquares::step (PoseShapeState& state, const std::vector<PoseShapeRow>& rows) const
{
  const Eigen::Index dim = 7 + sigma_.size ();
  const double inverse_scale2 = 1.0 / (state.scale () * state.scale ());
  Eigen::MatrixXd hessian = Eigen::MatrixXd::Zero (dim, dim);
  Eigen::VectorXd gradient = Eigen::VectorXd::Zero (dim);
  normalEquations (state, rows, inverse_scale2, hessian, gradient);
  Eigen::VectorXd delta;
  if (!solve (state, hessian, gradient, delta))
    return false;
  const Eigen::VectorXd change = limitStep (state, delta);
  // Backtracking on the cost with these rows: halve the (damped) step until it does not rise.
  const double current = cost (state, rows, inverse_scale2);
  for (double alpha = 1.0; alpha > 1e-2; alpha *= 0.5) {
    PoseShapeState candidate = moved (state, alpha * delta);
    if (cost (candidate, rows, inverse_scale2) <= current) {
      candidate.last_step = alpha * change;
      state = std::move (candidate);
      return true;
    }
  }
  state.last_step = Eigen::VectorXd::Zero (change.size ());
  return true;
}
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#include <morphreg/registration/morphable_convergence.h>

#include <cmath>

namespace morphreg
{
MorphableConvergence::MorphableConvergence (int max_iterations, double motion_epsilon, double fitness_epsilon,
                                            double max_sigma, int rising_iterations)
  : max_iterations_ (max_iterations), motion_epsilon_ (motion_epsilon), fitness_epsilon_ (fitness_epsilon),
    max_sigma_ (max_sigma), rising_iterations_ (rising_iterations)
{}

void
MorphableConvergence::startPhase (int budget, bool check_rising, Eigen::VectorXd sigma)
{
  budget_ = budget;
  phase_iterations_ = 0;
  check_rising_ = check_rising;
  sigma_ = std::move (sigma);
  rising_ = 0;
  stalled_ = 0;
  best_cost_ = std::numeric_limits<double>::infinity ();
  previous_cost_ = std::numeric_limits<double>::infinity ();
  termination_ = IcpTermination::max_iterations;
}

bool
MorphableConvergence::checkCost (double cost, double best_cost)
{
  constexpr double kRise = 1.05;     // a cost this many times the best counts as rising
  constexpr double kProgress = 1e-3; // a relative improvement below this one is no progress
  cost_ = cost;
  const bool same_rows = !std::isnan (best_cost);
  if (same_rows)
    best_cost_ = best_cost;
  improved_ = same_rows ? cost <= best_cost_ : cost < best_cost_;
  const bool progress = cost < (1.0 - kProgress) * best_cost_;
  stalled_ = progress || !same_rows ? 0 : stalled_ + 1;
  if (improved_) {
    best_cost_ = cost;
    rising_ = 0;
  }
  else if (check_rising_ && cost > kRise * best_cost_ && ++rising_ >= rising_iterations_)
    diverge (IcpDivergence::cost_rose, "the cost rose " + std::to_string (rising_) + " times in a row above the best");
  if (check_rising_ && stalled_ >= rising_iterations_ && !hasDiverged ())
    termination_ = IcpTermination::fitness_converged;
  return !hasDiverged ();
}

void
MorphableConvergence::update (bool solved, double motion, const Eigen::VectorXd& coefficients)
{
  if (!solved) {
    diverge (IcpDivergence::unsolvable, "the normal equations could not be solved");
    return;
  }
  ++iterations_;
  ++phase_iterations_;
  if (max_sigma_ > 0.0 && sigma_.size () > 0 &&
      (coefficients.cwiseAbs ().array () > max_sigma_ * sigma_.array () + 1e-9).any ())
    diverge (IcpDivergence::prior_exceeded,
             "a shape coefficient left the prior (more than " + std::to_string (max_sigma_) + " standard deviations)");
  else if (motion < motion_epsilon_)
    termination_ = IcpTermination::transformation_converged;
  else if (fitness_epsilon_ > 0.0 && std::abs (previous_cost_ - cost_) < fitness_epsilon_)
    termination_ = IcpTermination::fitness_converged;
  previous_cost_ = cost_;
}

bool
MorphableConvergence::hasConverged () const
{
  return hasDiverged () || termination_ != IcpTermination::max_iterations || phase_iterations_ >= budget_;
}

void
MorphableConvergence::diverge (IcpDivergence why, std::string message)
{
  divergence_ = why;
  message_ = std::move (message);
}
} // namespace morphreg

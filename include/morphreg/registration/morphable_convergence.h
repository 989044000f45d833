// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file morphable_convergence.h
 *  \brief When MorphableICP's phases stop, in the spirit of pcl::registration::DefaultConvergenceCriteria.
 */
#include <morphreg/registration/registration_report.h>

#include <Eigen/Core>

#include <limits>
#include <string>

namespace morphreg
{
/** \brief The stopping rules of MorphableICP: an iteration budget over all phases and one per phase; per phase, the
 *  mean squared vertex motion of an update below the motion epsilon or the change of the cost per row below the
 *  fitness epsilon (converged); and the divergence rules: the normal equations could not be solved, a coefficient
 *  left the prior (more than max_sigma standard deviations) or, where the phase checks it, the cost per row stayed
 *  above 1.05 times the phase's best for rising_iterations iterations in a row. Where the best is scored on the
 *  current rows (checkCost's second argument), a phase whose cost has not improved on its best by 0.1 % for
 *  rising_iterations iterations in a row has settled: fitness_converged.
 *
 *  Per iteration: checkCost with the cost at the current state and at the phase's best on the same rows (improved()
 *  then says whether the current state is the better one), the step, update; hasConverged() ends the phase.
 */
class MorphableConvergence
{
public:
  /** \param[in] max_iterations the budget over all phases
   *  \param[in] motion_epsilon the mean squared vertex motion (mm^2) of a converged update
   *  \param[in] fitness_epsilon the change of the cost per row (mm^2) of a converged iteration (<= 0: not checked)
   *  \param[in] max_sigma the coefficients' limit in prior standard deviations (<= 0: none)
   *  \param[in] rising_iterations iterations above the best that count as divergence
   */
  MorphableConvergence (int max_iterations, double motion_epsilon, double fitness_epsilon, double max_sigma,
                        int rising_iterations);

  /** \brief The iterations left over all phases.
   *  \return the budget over all phases minus the iterations run, the most the next phase may take
   */
  int
  remaining () const
  {
    return max_iterations_ - iterations_;
  }

  /** \brief Starts a phase of \a budget iterations.
   *  \param[in] budget the phase's iterations (at most remaining())
   *  \param[in] check_rising whether a rising cost counts as divergence (the shape phases)
   *  \param[in] sigma the prior standard deviations of the phase's coefficients (empty: not checked)
   */
  void
  startPhase (int budget, bool check_rising, Eigen::VectorXd sigma);

  /** \brief Records the cost per row at the state about to be updated.
   *  \param[in] cost the cost per row (mm^2) at the current state
   *  \param[in] best_cost the phase's best state scored on the same rows (NaN: the best cost recorded so far). The
   *  rows change with every correspondence search, and rejectors admit more of them as a fit improves, so only a
   *  comparison on the same rows says whether the state got worse.
   *  \return false if it diverged (the cost rose too often)
   */
  bool
  checkCost (double cost, double best_cost = std::numeric_limits<double>::quiet_NaN ());

  /** \brief Whether the last checkCost was the phase's best.
   *  \return true if the state just checked is the best of the phase, the one to keep
   */
  bool
  improved () const
  {
    return improved_;
  }

  /** \brief The lowest cost per row of the phase so far.
   *  \return the best cost per row (mm^2); infinity before the first checkCost
   */
  double
  bestCost () const
  {
    return best_cost_;
  }

  /** \brief Records an update: \a solved false marks divergence; else one iteration, its \a motion (mm^2) and the
   *  \a coefficients reached.
   *  \param[in] solved whether the normal equations were solved
   *  \param[in] motion the mean squared vertex motion of the update (mm^2)
   *  \param[in] coefficients the shape coefficients after the update, checked against the prior
   */
  void
  update (bool solved, double motion, const Eigen::VectorXd& coefficients);

  /** \brief Whether the phase ends: converged, diverged or out of budget.
   *  \return true if the phase should stop iterating
   */
  bool
  hasConverged () const;

  /** \brief Whether a divergence rule fired.
   *  \return true if the run diverged (see divergence())
   */
  bool
  hasDiverged () const
  {
    return divergence_ != IcpDivergence::none;
  }

  /** \brief The iterations run over all phases.
   *  \return the number of recorded updates
   */
  int
  iterations () const
  {
    return iterations_;
  }

  /** \brief Why the last phase stopped, for the report.
   *  \return IcpTermination::diverged after a divergence, else the phase's convergence or budget reason
   */
  IcpTermination
  termination () const
  {
    return hasDiverged () ? IcpTermination::diverged : termination_;
  }

  /** \brief Which divergence rule fired.
   *  \return the rule, or IcpDivergence::none
   */
  IcpDivergence
  divergence () const
  {
    return divergence_;
  }

  /** \brief What diverged, in words, for the report.
   *  \return the divergence's sentence, empty if none
   */
  const std::string&
  message () const
  {
    return message_;
  }

private:
  void
  diverge (IcpDivergence why, std::string message);

  int max_iterations_;
  double motion_epsilon_;
  double fitness_epsilon_;
  double max_sigma_;
  int rising_iterations_;

  int iterations_ = 0;
  int budget_ = 0;
  int phase_iterations_ = 0;
  bool check_rising_ = false;
  Eigen::VectorXd sigma_;
  int rising_ = 0;
  int stalled_ = 0; ///< iterations in a row without progress on the best, compared on the same rows
  bool improved_ = false;
  double best_cost_ = std::numeric_limits<double>::infinity ();
  double previous_cost_ = std::numeric_limits<double>::infinity ();
  double cost_ = 0.0;
  IcpTermination termination_ = IcpTermination::not_run;
  IcpDivergence divergence_ = IcpDivergence::none;
  std::string message_;
};
} // namespace morphreg

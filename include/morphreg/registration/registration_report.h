// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file registration_report.h
 *  \brief What a MorphableICP run did: why it stopped, every iteration, and the fit quality it reached.
 */
#include <Eigen/Core>

#include <cmath>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief The two stages of the 3D-3D fit (thesis: similarity to convergence first, then with shape). */
enum class IcpStage
{
  similarity, ///< scale, rotation and translation; the shape is held fixed
  shape       ///< similarity and the selected shape coefficients together
};

/** \brief Why a MorphableICP run stopped. */
enum class IcpTermination
{
  not_run,                  ///< align() has not run yet
  transformation_converged, ///< the mean squared vertex motion of an update fell below the transformation epsilon
  fitness_converged,        ///< the change of the cost per row fell below the Euclidean fitness epsilon
  max_iterations,           ///< the iteration budget ran out (the best state is returned)
  diverged ///< cost rising, coefficients far outside the prior or an unsolvable system: best state returned
};

/** \brief Why a run stopped as diverged (IcpTermination::diverged); the best state is returned in every case. */
enum class IcpDivergence
{
  none,           ///< it did not diverge
  cost_rose,      ///< the shape stage's cost stayed above its best (the usual end of a fit that has settled)
  prior_exceeded, ///< a shape coefficient left the prior (setDivergenceGuard's limit)
  unsolvable      ///< the normal equations could not be solved
};

/** \brief Lower-case name of \a termination (e.g. "transformation_converged"), for reports and logs.
 *  \param[in] termination the reason a run stopped
 *  \return the enumerator's name
 */
std::string
toString (IcpTermination termination);

/** \brief Lower-case name of \a stage ("similarity" or "shape"), for reports and logs.
 *  \param[in] stage the fit stage
 *  \return the enumerator's name
 */
std::string
toString (IcpStage stage);

/** \brief One Gauss-Newton iteration. */
struct IcpIteration
{
  IcpStage stage;      ///< the stage the iteration belongs to
  double error;        ///< mean squared distance (mm^2) over the accepted correspondences, before the update
  int correspondences; ///< correspondences found (before rejection)
  int kept;            ///< correspondences left after every rejector (landmarks not counted)
  double seconds;      ///< wall time of the iteration
};

/** \brief The report of the last MorphableICP::align(). */
struct IcpReport
{
  IcpTermination termination = IcpTermination::not_run; ///< why the run stopped
  std::string message;                                  ///< human-readable detail (e.g. what diverged)
  IcpDivergence divergence = IcpDivergence::none;       ///< what diverged, with IcpTermination::diverged
  std::vector<IcpIteration> history;                    ///< every iteration, in order
  int similarity_iterations = 0;                        ///< iterations of the similarity stage
  int shape_iterations = 0;                             ///< iterations of the shape stage
  /** \brief The similarity the iterations started from (the guess, the landmark, the coarse or the global start). */
  Eigen::Matrix4d initial_transformation = Eigen::Matrix4d::Identity ();
  std::string initialisation;             ///< how it was found: "guess", "landmarks", "coarse" or "global"
  std::string initialisation_detail;      ///< for the global start: how it chose (GlobalAlignment::method)
  double initialisation_confidence = 1.0; ///< the global start's confidence in [0, 1]; 1 for the others
  int head_points = -1;                   ///< target points the global start found on the head (-1: not searched)
  bool target_smoothing = false;          ///< whether the target points were projected onto their local planes
  double target_noise_ratio = NAN;        ///< the target's measured noise ratio (TargetSurface; NaN: not measured)
  /** \brief Accepted correspondences at the returned state, over which the fitness figures below are taken: the
   *  distance from each of their model vertices to its nearest target point (mm). fitness_rms^2 is the fitness score,
   *  PCL's mean squared distance, which pcl::Registration::getFitnessScore() returns after the fit. */
  int correspondences = 0;
  double fitness_mean = 0.0;   ///< mean scan-to-model distance (mm) at the returned state
  double fitness_median = 0.0; ///< median scan-to-model distance (mm) at the returned state
  double fitness_rms = 0.0;    ///< RMS scan-to-model distance (mm): the square root of getFitnessScore()
};

} // namespace morphreg

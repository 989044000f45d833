#pragma once
/** \file registration_report.h
 *  \brief What a MorphableICP run did: why it stopped, every iteration, and the fit quality it reached.
 */
#include <Eigen/Core>

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
  diverged                  ///< cost rising, coefficients far outside the prior or an unsolvable system: best state returned
};

/** \brief Lower-case name of \a termination (e.g. "transformation_converged"). */
std::string
toString (IcpTermination termination);

/** \brief Lower-case name of \a stage ("similarity" or "shape"). */
std::string
toString (IcpStage stage);

/** \brief One Gauss-Newton iteration. */
struct IcpIteration
{
  IcpStage stage;
  double error;        ///< mean squared distance (mm^2) over the accepted correspondences, before the update
  int correspondences; ///< correspondences found (before rejection)
  int kept;            ///< correspondences left after every rejector (landmarks not counted)
  double seconds;      ///< wall time of the iteration
};

/** \brief The report of the last MorphableICP::align(). */
struct IcpReport
{
  IcpTermination termination = IcpTermination::not_run;
  std::string message;              ///< human-readable detail (e.g. what diverged)
  std::vector<IcpIteration> history;
  int similarity_iterations = 0;
  int shape_iterations = 0;
  /** The similarity the iterations started from (the guess, the landmark or the coarse initialisation). */
  Eigen::Matrix4d initial_transformation = Eigen::Matrix4d::Identity ();
  /** Fit quality at the returned state: scan-to-model distances (mm) over the accepted correspondences. */
  int correspondences = 0;
  double fitness_mean = 0.0;
  double fitness_median = 0.0;
  double fitness_rms = 0.0;
};

} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file initial_alignment_strategy.h
 *  \brief Where a MorphableICP fit starts, as objects: each start maps the model's mean head into the target's frame
 *  with a similarity. The starts are in starts/, one file each, and are made by name in one place
 *  (makeInitialAlignment, src/registration/initial_alignment_strategy.cpp), where a new start is registered.
 */
#include <morphreg/common/landmarks.h>
#include <morphreg/mesh/triangle_mesh.h>
#include <morphreg/registration/initial_alignment.h>

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief What a start may look at: the model's mean head, the target, its landmarks and the caller's guess. */
struct StartInputs
{
  TriangleMesh model_mean;                  ///< the model's mean head, mm
  Eigen::Matrix3Xd model_landmarks;         ///< the mean head's landmarks (3 x L), in the order of target_landmarks
  Eigen::Matrix3Xd target_landmarks;        ///< the target's landmarks (3 x L), mm
  Eigen::Matrix3Xd target;                  ///< the target's points (3 x N), mm
  Eigen::Matrix3Xd target_normals;          ///< their normals (3 x N), or 3 x 0 when the target has none
  std::optional<Eigen::Vector3d> viewpoint; ///< the sensor's position for a target seen from one view
  TargetNeighbourSearch target_neighbours;  ///< k nearest target points, from the registration's k-d tree
  Eigen::Matrix4d guess = Eigen::Matrix4d::Identity (); ///< the similarity the caller passed to align()
};

/** \brief A start found: the similarity and how it was found, for the registration's report. */
struct StartEstimate
{
  Eigen::Matrix4d similarity = Eigen::Matrix4d::Identity (); ///< model frame to target frame
  std::string method;      ///< the start that found it (the automatic start names the one it chose)
  std::string detail;      ///< how it chose, where the start says (the global start's method)
  double confidence = 1.0; ///< in [0, 1]; 1 for starts that do not search
  int head_points = -1;    ///< target points found on the head (-1: not searched)
};

/** \brief A way of starting the fit. */
class InitialAlignmentStrategy
{
public:
  using ConstPtr = std::shared_ptr<const InitialAlignmentStrategy>; ///< shared pointer to const

  virtual ~InitialAlignmentStrategy () = default;

  /** \brief The start's name as settings and reports give it.
   *  \return e.g. "landmarks" */
  virtual std::string
  name () const = 0;

  /** \brief The start for \a inputs. Throws InvalidInputError naming what is missing (landmarks, points).
   *  \param[in] inputs the model's mean head, the target and its landmarks, the guess
   *  \return the similarity and how it was found */
  virtual StartEstimate
  estimate (const StartInputs& inputs) const = 0;
};

/** \brief The names of the registered starts, in the order settings list them ("auto" first).
 *  \return the names */
const std::vector<std::string>&
initialAlignmentNames ();

/** \brief The start called \a name; InvalidInputError listing the names for an unknown one.
 *  \param[in] name the start's name
 *  \return the start */
InitialAlignmentStrategy::ConstPtr
makeInitialAlignment (const std::string& name);
} // namespace morphreg

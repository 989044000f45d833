// SPDX-License-Identifier: BSD-3-Clause
#pragma once
/** \file photo_fit_method.h
 *  \brief A way of fitting the model to photos (docs/method.md, "Fitting to photographs"): a strategy over the one
 *  MultiViewProblem. The methods are registered in one place (src/photo/photo_fit_methods.cpp); a new one is a class
 *  in its own file and one line there.
 */
#include <morphreg/photo/multi_view_problem.h>
#include <morphreg/photo/photo_fit.h>

#include <memory>
#include <string>
#include <vector>

namespace morphreg
{
/** \brief A photo fitting method: what it fits (rows()) and how (fit()). */
class PhotoFitMethod
{
public:
  using ConstPtr = std::shared_ptr<const PhotoFitMethod>; ///< shared pointer to const

  virtual ~PhotoFitMethod () = default;

  /** \brief The method's name, as `fit-photos --approach` takes it.
   *  \return e.g. "joint"
   */
  virtual std::string
  name () const = 0;

  /** \brief What the method fits: the traced outlines alone, or every row (the shape prior is chosen on the same
   *  rows, ShapePriorSelection).
   *  \return the rows
   */
  virtual PhotoRows
  rows () const = 0;

  /** \brief Fits \a problem from \a start (the pose and shape to begin with). Throws InvalidInputError naming what
   *  is missing when the photos lack what the method needs (an outline, landmarks).
   *  \param[in] problem the photos, cameras and model (its outline labels change as it fits)
   *  \param[in] start the state to begin with
   *  \return the fit, with its history; PhotoFitting adds the method's name, the prior and the camera rounds
   */
  virtual PhotoFit
  fit (MultiViewProblem& problem, const PoseShapeState& start) const = 0;
};

/** \brief The registered method called \a name. Throws InvalidInputError listing the names for an unknown one.
 *  \param[in] name the method's name
 *  \return the method
 */
PhotoFitMethod::ConstPtr
photoFitMethod (const std::string& name);

/** \brief The names of the registered methods, in the order they are listed.
 *  \return the names
 */
std::vector<std::string>
photoFitMethodNames ();

/** \brief The state a fit ended in, from its result: to go on from it (a camera round, TPS-ICP after a profile fit).
 *  \param[in] problem the problem it was fitted over
 *  \param[in] fit the fit
 *  \return the state
 */
PoseShapeState
fittedState (const MultiViewProblem& problem, const PhotoFit& fit);
} // namespace morphreg

// SPDX-License-Identifier: BSD-3-Clause
// The registry of photo fitting methods: the one place that lists them. A new method is a PhotoFitMethod in its own
// file with a factory declared and listed here.
#include <morphreg/common/error.h>
#include <morphreg/photo/photo_fit_method.h>

#include <functional>

namespace morphreg
{
PhotoFitMethod::ConstPtr
makeProfileFitMethod ();
PhotoFitMethod::ConstPtr
makeJointFitMethod ();
PhotoFitMethod::ConstPtr
makeTpsIcpFitMethod ();

namespace
{
/** Every method, in the order help texts and errors list them. */
const std::vector<std::function<PhotoFitMethod::ConstPtr ()>>&
factories ()
{
  static const std::vector<std::function<PhotoFitMethod::ConstPtr ()>> all = {
      makeProfileFitMethod,
      makeJointFitMethod,
      makeTpsIcpFitMethod,
  };
  return all;
}
} // namespace

std::vector<std::string>
photoFitMethodNames ()
{
  std::vector<std::string> names;
  for (const auto& make : factories ())
    names.push_back (make ()->name ());
  return names;
}

PhotoFitMethod::ConstPtr
photoFitMethod (const std::string& name)
{
  std::string known;
  for (const auto& make : factories ()) {
    PhotoFitMethod::ConstPtr method = make ();
    if (method->name () == name)
      return method;
    known += (known.empty () ? "" : ", ") + method->name ();
  }
  throw InvalidInputError ("photo fitting approach \"" + name + "\" is none of " + known);
}

PoseShapeState
fittedState (const MultiViewProblem& problem, const PhotoFit& fit)
{
  return problem.solver (true).state (fit.similarity (), fit.coefficients_mm);
}
} // namespace morphreg
